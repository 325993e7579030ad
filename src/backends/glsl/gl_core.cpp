#include "backends/glsl/gl_core.h"

namespace ffc::glsl {

std::vector<std::string> CoreGl::load(void* (*loader)(const char* name)) {
  std::vector<std::string> missing;
#define FFC_GLSL_LOAD(type, name)                                     \
  name = reinterpret_cast<type>(loader("gl" #name));                  \
  if (!name) missing.push_back("gl" #name);
  FFC_GLSL_CORE_FUNCTIONS(FFC_GLSL_LOAD)
#undef FFC_GLSL_LOAD
  return missing;
}

}  // namespace ffc::glsl
