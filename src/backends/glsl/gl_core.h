// The core-profile GL functions the GLSL backend calls, in a table of its own loaded from the EGL
// context: the ffc_gl* dispatch points at our state tracker, so these never go through it.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

namespace ffc::glsl {

#define FFC_GLSL_CORE_FUNCTIONS(X)                                                                       \
  X(decltype(&::glClear), Clear) X(decltype(&::glClearColor), ClearColor)                                 \
  X(decltype(&::glClearDepth), ClearDepth) X(decltype(&::glEnable), Enable) X(decltype(&::glDisable), Disable) \
  X(decltype(&::glViewport), Viewport) X(decltype(&::glDepthRange), DepthRange)                           \
  X(decltype(&::glDepthFunc), DepthFunc) X(decltype(&::glDepthMask), DepthMask)                           \
  X(decltype(&::glColorMask), ColorMask) X(decltype(&::glCullFace), CullFace)                             \
  X(decltype(&::glFrontFace), FrontFace) X(decltype(&::glScissor), Scissor)                               \
  X(decltype(&::glPointSize), PointSize) X(decltype(&::glLineWidth), LineWidth)                           \
  X(decltype(&::glReadPixels), ReadPixels) X(decltype(&::glPixelStorei), PixelStorei)                     \
  X(decltype(&::glFinish), Finish) X(decltype(&::glGetError), GetError)                                   \
  X(decltype(&::glDrawElements), DrawElements) X(decltype(&::glDrawArrays), DrawArrays)                   \
  X(decltype(&::glGetIntegerv), GetIntegerv) X(PFNGLDRAWRANGEELEMENTSPROC, DrawRangeElements)           \
  X(decltype(&::glPolygonOffset), PolygonOffset)                                                          \
  X(decltype(&::glGenTextures), GenTextures) X(decltype(&::glBindTexture), BindTexture)                   \
  X(decltype(&::glDeleteTextures), DeleteTextures) X(PFNGLTEXBUFFERPROC, TexBuffer)                        \
  X(decltype(&::glTexImage2D), TexImage2D) X(decltype(&::glTexParameteri), TexParameteri)                 \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture) X(PFNGLUNIFORM1IPROC, Uniform1i)                               \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate) X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate) \
  X(PFNGLBLENDCOLORPROC, BlendColor)                                                                      \
  X(PFNGLCREATESHADERPROC, CreateShader) X(PFNGLSHADERSOURCEPROC, ShaderSource)                           \
  X(PFNGLCOMPILESHADERPROC, CompileShader) X(PFNGLGETSHADERIVPROC, GetShaderiv)                           \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog) X(PFNGLDELETESHADERPROC, DeleteShader)                   \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram) X(PFNGLATTACHSHADERPROC, AttachShader)                         \
  X(PFNGLLINKPROGRAMPROC, LinkProgram) X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                             \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) X(PFNGLDELETEPROGRAMPROC, DeleteProgram)               \
  X(PFNGLUSEPROGRAMPROC, UseProgram) X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                   \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv) X(PFNGLUNIFORM3FVPROC, Uniform3fv) X(PFNGLUNIFORM4FVPROC, Uniform4fv) \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv) X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)           \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays) X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)               \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) X(PFNGLGENBUFFERSPROC, GenBuffers)                   \
  X(PFNGLBINDBUFFERPROC, BindBuffer) X(PFNGLBUFFERDATAPROC, BufferData)                                   \
  X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange) X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                         \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                 \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                                    \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                            \
  X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray) X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation) \
  X(PFNGLTRANSFORMFEEDBACKVARYINGSPROC, TransformFeedbackVaryings)                                        \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase) X(PFNGLBEGINTRANSFORMFEEDBACKPROC, BeginTransformFeedback)   \
  X(PFNGLENDTRANSFORMFEEDBACKPROC, EndTransformFeedback)

struct CoreGl {
#define FFC_GLSL_MEMBER(type, name) type name = nullptr;
  FFC_GLSL_CORE_FUNCTIONS(FFC_GLSL_MEMBER)
#undef FFC_GLSL_MEMBER
  // Loads every entry; returns the names not found (empty on success).
  std::vector<std::string> load(void* (*loader)(const char* name));
};

// One shader stage compiled; a failure throws std::runtime_error naming `what` with the driver's
// log and the source. Every program of the backend (generated, stipple, pixel copy) is built with
// these two.
GLuint compile_shader(const CoreGl& gl, GLenum type, const std::string& src, const char* what);
// `program` (its stages attached, transform feedback varyings named) linked; a failure throws,
// naming `what`, with the driver's log.
void link_program(const CoreGl& gl, GLuint program, const char* what);

}  // namespace ffc::glsl
