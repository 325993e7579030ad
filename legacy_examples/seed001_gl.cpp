#include "seed001_gl.h"

namespace seed001 {

std::vector<std::string> Gl33::load(Loader loader) {
  std::vector<std::string> missing;
#define SEED001_GL_LOAD(type, name)                                  \
  name = reinterpret_cast<type>(loader("gl" #name));                 \
  if (!name) missing.push_back("gl" #name);
  SEED001_GL_FUNCTIONS(SEED001_GL_LOAD)
#undef SEED001_GL_LOAD
  return missing;
}

}  // namespace seed001
