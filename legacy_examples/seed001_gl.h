// The few core-profile OpenGL 3.3 functions seed 001's programs call, as a table of pointers
// loaded from a context's proc-address function (EglContext::proc_address headless,
// glfwGetProcAddress in a window). The types are Khronos's <GL/glcorearb.h>: no loader library,
// and nothing of the fixed-function dispatch (gl/dispatch.h) is visible here, so the two GLs
// cannot be mixed up in one file.
#pragma once
#include <GL/glcorearb.h>

#include <string>
#include <vector>

namespace seed001 {

// X(type, name): every entry point the programs use, with its <GL/glcorearb.h> pointer type.
#define SEED001_GL_FUNCTIONS(X)                               \
  X(PFNGLGETSTRINGPROC, GetString)                            \
  X(PFNGLGETERRORPROC, GetError)                              \
  X(PFNGLVIEWPORTPROC, Viewport)                              \
  X(PFNGLCLEARCOLORPROC, ClearColor)                          \
  X(PFNGLCLEARPROC, Clear)                                    \
  X(PFNGLENABLEPROC, Enable)                                  \
  X(PFNGLFINISHPROC, Finish)                                  \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                        \
  X(PFNGLREADPIXELSPROC, ReadPixels)                          \
  X(PFNGLCREATESHADERPROC, CreateShader)                      \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                      \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                    \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                        \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)              \
  X(PFNGLDELETESHADERPROC, DeleteShader)                      \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                    \
  X(PFNGLATTACHSHADERPROC, AttachShader)                      \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                        \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                      \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)            \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                    \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                          \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)          \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)              \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                          \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)          \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                          \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                          \
  X(PFNGLBUFFERDATAPROC, BufferData)                          \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                    \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)        \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                          \
  X(PFNGLDRAWELEMENTSPROC, DrawElements)

struct Gl33 {
#define SEED001_GL_MEMBER(type, name) type name = nullptr;
  SEED001_GL_FUNCTIONS(SEED001_GL_MEMBER)
#undef SEED001_GL_MEMBER

  using Loader = void* (*)(const char* name);
  // Fills every entry from `loader` ("gl" + the member's name); returns the names it could not
  // find (empty: all loaded).
  std::vector<std::string> load(Loader loader);
};

}  // namespace seed001
