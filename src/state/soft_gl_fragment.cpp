// The gl* entry points of the per-fragment operations, glBitmap and the attribute stacks: each
// forwards to the current Context, as soft_gl.cpp's do, and compiles into display lists (LISTABLE,
// display_list.h) but for the client's attribute stack, which GL 2.1 section 5.4 executes at once.
#include "state/soft_gl_entries.h"

namespace ffc::state::entry {

#define FWD(call) \
  if (Context* ctx_ = C()) ctx_->call

void APIENTRY AlphaFunc(GLenum func, GLclampf ref) { LISTABLE(AlphaFunc, func, ref); FWD(AlphaFunc(func, ref)); }
void APIENTRY BlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { LISTABLE(BlendColor, r, g, b, a); FWD(BlendColor(r, g, b, a)); }
void APIENTRY BlendEquation(GLenum mode) { LISTABLE(BlendEquation, mode); FWD(BlendEquationSeparate(mode, mode)); }
void APIENTRY BlendEquationSeparate(GLenum rgb, GLenum alpha) {
  LISTABLE(BlendEquationSeparate, rgb, alpha);
  FWD(BlendEquationSeparate(rgb, alpha));
}
void APIENTRY BlendFunc(GLenum src, GLenum dst) { LISTABLE(BlendFunc, src, dst); FWD(BlendFuncSeparate(src, dst, src, dst)); }
void APIENTRY BlendFuncSeparate(GLenum sr, GLenum dr, GLenum sa, GLenum da) {
  LISTABLE(BlendFuncSeparate, sr, dr, sa, da);
  FWD(BlendFuncSeparate(sr, dr, sa, da));
}
void APIENTRY ColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) { LISTABLE(ColorMask, r, g, b, a); FWD(ColorMask(r, g, b, a)); }
void APIENTRY DepthMask(GLboolean on) { LISTABLE(DepthMask, on); FWD(DepthMask(on)); }
void APIENTRY Scissor(GLint x, GLint y, GLsizei w, GLsizei h) { LISTABLE(Scissor, x, y, w, h); FWD(Scissor(x, y, w, h)); }
void APIENTRY LineStipple(GLint factor, GLushort pattern) { LISTABLE(LineStipple, factor, pattern); FWD(LineStipple(factor, pattern)); }

// A bitmap in a list: its bits unpacked when the list is compiled (GL 2.1 section 5.4), by the
// GL_UNPACK_* state of that moment, into rows of whole bytes kept by the list; replayed whatever
// the unpack state is then.
void APIENTRY PackedBitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym, PackedBits bits) {
  FWD(Bitmap(w, h, xo, yo, xm, ym, bits.data, true));
}
void APIENTRY Bitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym, const GLubyte* b) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* l = c->list_recording()) {
    const PackedBits bits = l->keep(c->pack_bitmap(w, h, b));
    if (compiled_only<ListKind::State, PackedBitmap>(w, h, xo, yo, xm, ym, bits)) return;
    return c->Bitmap(w, h, xo, yo, xm, ym, bits.data, true);
  }
  c->Bitmap(w, h, xo, yo, xm, ym, b, false);
}
void APIENTRY PushAttrib(GLbitfield mask) { LISTABLE(PushAttrib, mask); FWD(PushAttrib(mask)); }
void APIENTRY PopAttrib() { LISTABLE(PopAttrib); FWD(PopAttrib()); }
void APIENTRY PushClientAttrib(GLbitfield mask) { FWD(PushClientAttrib(mask)); }
void APIENTRY PopClientAttrib() { FWD(PopClientAttrib()); }
#undef FWD

}  // namespace ffc::state::entry
