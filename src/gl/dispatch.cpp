#include "gl/dispatch.h"

#define FFC_GL_FUNCTION(ret, name, params) ret(APIENTRY* ffc_gl##name) params = nullptr;
#include "gl_functions.inc"
#undef FFC_GL_FUNCTION

namespace ffc::gl {

std::vector<std::string> load(Loader loader) {
  std::vector<std::string> missing;
#define FFC_GL_FUNCTION(ret, name, params)                                        \
  ffc_gl##name = reinterpret_cast<decltype(ffc_gl##name)>(loader("gl" #name)); \
  if (!ffc_gl##name) missing.push_back("gl" #name);
#include "gl_functions.inc"
#undef FFC_GL_FUNCTION
  return missing;
}

}  // namespace ffc::gl
