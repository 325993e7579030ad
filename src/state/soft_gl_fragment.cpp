// The gl* entry points of the per-fragment operations, glBitmap and the attribute stacks: each
// forwards to the current Context, as soft_gl.cpp's do.
#include "state/soft_gl_fragment.h"

#include <cstring>

#include "state/context.h"

namespace ffc::state {

namespace {
Context* C() { return Context::current(); }
}  // namespace

#define FWD(call) \
  if (Context* ctx_ = C()) ctx_->call

void APIENTRY AlphaFunc(GLenum func, GLclampf ref) { FWD(AlphaFunc(func, ref)); }
void APIENTRY BlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { FWD(BlendColor(r, g, b, a)); }
void APIENTRY BlendEquation(GLenum mode) { FWD(BlendEquationSeparate(mode, mode)); }
void APIENTRY BlendEquationSeparate(GLenum rgb, GLenum alpha) { FWD(BlendEquationSeparate(rgb, alpha)); }
void APIENTRY BlendFunc(GLenum src, GLenum dst) { FWD(BlendFuncSeparate(src, dst, src, dst)); }
void APIENTRY BlendFuncSeparate(GLenum sr, GLenum dr, GLenum sa, GLenum da) { FWD(BlendFuncSeparate(sr, dr, sa, da)); }
void APIENTRY ColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) { FWD(ColorMask(r, g, b, a)); }
void APIENTRY DepthMask(GLboolean on) { FWD(DepthMask(on)); }
void APIENTRY Scissor(GLint x, GLint y, GLsizei w, GLsizei h) { FWD(Scissor(x, y, w, h)); }
void APIENTRY LineStipple(GLint factor, GLushort pattern) { FWD(LineStipple(factor, pattern)); }
void APIENTRY Bitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym, const GLubyte* b) {
  FWD(Bitmap(w, h, xo, yo, xm, ym, b));
}
void APIENTRY PushAttrib(GLbitfield mask) { FWD(PushAttrib(mask)); }
void APIENTRY PopAttrib() { FWD(PopAttrib()); }
void APIENTRY PushClientAttrib(GLbitfield mask) { FWD(PushClientAttrib(mask)); }
void APIENTRY PopClientAttrib() { FWD(PopClientAttrib()); }
#undef FWD

void* fragment_proc_address(const char* name) {
  struct Entry {
    const char* name;
    void* fn;
  };
  static const Entry kEntries[] = {
      {"glAlphaFunc", reinterpret_cast<void*>(&AlphaFunc)},
      {"glBlendColor", reinterpret_cast<void*>(&BlendColor)},
      {"glBlendEquation", reinterpret_cast<void*>(&BlendEquation)},
      {"glBlendEquationSeparate", reinterpret_cast<void*>(&BlendEquationSeparate)},
      {"glBlendFunc", reinterpret_cast<void*>(&BlendFunc)},
      {"glBlendFuncSeparate", reinterpret_cast<void*>(&BlendFuncSeparate)},
      {"glColorMask", reinterpret_cast<void*>(&ColorMask)},
      {"glDepthMask", reinterpret_cast<void*>(&DepthMask)},
      {"glScissor", reinterpret_cast<void*>(&Scissor)},
      {"glLineStipple", reinterpret_cast<void*>(&LineStipple)},
      {"glBitmap", reinterpret_cast<void*>(&Bitmap)},
      {"glPushAttrib", reinterpret_cast<void*>(&PushAttrib)},
      {"glPopAttrib", reinterpret_cast<void*>(&PopAttrib)},
      {"glPushClientAttrib", reinterpret_cast<void*>(&PushClientAttrib)},
      {"glPopClientAttrib", reinterpret_cast<void*>(&PopClientAttrib)},
  };
  for (const Entry& e : kEntries)
    if (std::strcmp(name, e.name) == 0) return e.fn;
  return nullptr;
}

}  // namespace ffc::state
