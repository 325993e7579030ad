// The gl* entry points of the per-fragment operations, glBitmap and the attribute stacks
// (soft_gl_fragment.cpp), declared where state::proc_address (soft_gl.cpp) finds them by the
// dispatch's names (gl/gl_functions.inc).
#pragma once
#include <GL/gl.h>

namespace ffc::state {

void APIENTRY AlphaFunc(GLenum func, GLclampf ref);
void APIENTRY BlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a);
void APIENTRY BlendEquation(GLenum mode);
void APIENTRY BlendEquationSeparate(GLenum rgb, GLenum alpha);
void APIENTRY BlendFunc(GLenum src, GLenum dst);
void APIENTRY BlendFuncSeparate(GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha);
void APIENTRY ColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a);
void APIENTRY DepthMask(GLboolean on);
void APIENTRY Scissor(GLint x, GLint y, GLsizei w, GLsizei h);
void APIENTRY LineStipple(GLint factor, GLushort pattern);
void APIENTRY Bitmap(GLsizei w, GLsizei h, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                     const GLubyte* bitmap);
void APIENTRY PushAttrib(GLbitfield mask);
void APIENTRY PopAttrib();
void APIENTRY PushClientAttrib(GLbitfield mask);
void APIENTRY PopClientAttrib();

// The entry point of that list named `name` ("glBlendFunc"), or null.
void* fragment_proc_address(const char* name);

}  // namespace ffc::state
