#include "backends/glsl/gl_core.h"

#include <stdexcept>

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

GLuint compile_shader(const CoreGl& gl, GLenum type, const std::string& src, const char* what) {
  const GLuint s = gl.CreateShader(type);
  const char* text = src.c_str();
  gl.ShaderSource(s, 1, &text, nullptr);
  gl.CompileShader(s);
  GLint ok = 0;
  gl.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    gl.GetShaderInfoLog(s, sizeof log, nullptr, log);
    gl.DeleteShader(s);
    throw std::runtime_error(std::string("glsl: ") + what + " does not compile: " + log + "\n" + src);
  }
  return s;
}

void link_program(const CoreGl& gl, GLuint program, const char* what) {
  gl.LinkProgram(program);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {};
    gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("glsl: ") + what + " does not link: " + log);
  }
}

}  // namespace ffc::glsl
