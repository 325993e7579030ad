// The current values beyond the normal and colour (GL 2.1 section 2.7: texture coordinates, the
// edge flag), glRect (section 2.10), glHint (section 5.6), the texture coordinate array and
// glInterleavedArrays (section 2.8, table 2.5).
#include "state/client_arrays.h"
#include "state/context.h"

namespace ffc::state {

// Texture coordinates and the edge flag may be set anywhere, glBegin/glEnd included.
void Context::TexCoord(float s, float t, float r, float q) {
  const glm::vec4 tc{s, t, r, q};
  if (in_begin_ && tc != texcoord_ && (!verts_.empty() || !list_pos_.empty())) texcoord_varies_ = true;
  texcoord_ = tc;
}
void Context::EdgeFlag(GLboolean flag) { edge_flag_ = flag != GL_FALSE; }

void Context::Rect(float x1, float y1, float x2, float y2) {
  if (!outside_begin_end()) return;
  Begin(GL_QUADS);
  Vertex(x1, y1, 0, 1), Vertex(x2, y1, 0, 1), Vertex(x2, y2, 0, 1), Vertex(x1, y2, 0, 1);
  End();
}

namespace {
bool hint_target(GLenum t) {
  switch (t) {
    case GL_PERSPECTIVE_CORRECTION_HINT: case GL_POINT_SMOOTH_HINT: case GL_LINE_SMOOTH_HINT:
    case GL_POLYGON_SMOOTH_HINT: case GL_FOG_HINT: case GL_GENERATE_MIPMAP_HINT: case GL_TEXTURE_COMPRESSION_HINT:
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT:
      return true;
  }
  return false;
}
}  // namespace

// Stored and reported, never acted on (GL lets an implementation ignore hints). Mesa checks the
// mode before the target.
void Context::Hint(GLenum target, GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) return error(GL_INVALID_ENUM);
  if (!hint_target(target)) return error(GL_INVALID_ENUM);
  const auto it = hints_.find(target);  // Mesa's hint.c flushes only on a change
  if (changes((it == hints_.end() ? GLenum(GL_DONT_CARE) : it->second) != mode)) hints_[target] = mode;
}

void Context::TexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) return error(GL_INVALID_ENUM);
  if (size < 1 || size > 4) return error(GL_INVALID_VALUE);
  texcoord_array_ = {texcoord_array_.enabled, size, type, stride, p};
}

namespace {
// GL 2.1 table 2.5: which arrays a format holds, their sizes and offsets in floats (the colour of
// the C4UB formats takes one float's room), and the whole element's size.
struct Interleaved {
  GLenum format;
  int tex, color, normal, vertex;  // sizes, 0 when absent
  bool ubyte_color;
  int color_at, normal_at, vertex_at, size;  // in floats
};
constexpr Interleaved kInterleaved[] = {
    {GL_V2F, 0, 0, 0, 2, false, 0, 0, 0, 2},
    {GL_V3F, 0, 0, 0, 3, false, 0, 0, 0, 3},
    {GL_C4UB_V2F, 0, 4, 0, 2, true, 0, 0, 1, 3},
    {GL_C4UB_V3F, 0, 4, 0, 3, true, 0, 0, 1, 4},
    {GL_C3F_V3F, 0, 3, 0, 3, false, 0, 0, 3, 6},
    {GL_N3F_V3F, 0, 0, 3, 3, false, 0, 0, 3, 6},
    {GL_C4F_N3F_V3F, 0, 4, 3, 3, false, 0, 4, 7, 10},
    {GL_T2F_V3F, 2, 0, 0, 3, false, 0, 0, 2, 5},
    {GL_T4F_V4F, 4, 0, 0, 4, false, 0, 0, 4, 8},
    {GL_T2F_C4UB_V3F, 2, 4, 0, 3, true, 2, 0, 3, 6},
    {GL_T2F_C3F_V3F, 2, 3, 0, 3, false, 2, 0, 5, 8},
    {GL_T2F_N3F_V3F, 2, 0, 3, 3, false, 0, 2, 5, 8},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, 3, false, 2, 6, 9, 12},
    {GL_T4F_C4F_N3F_V4F, 4, 4, 3, 4, false, 4, 8, 11, 15},
};
}  // namespace

// As Mesa's varray.c: the edge flag and index arrays off, then each array of the format on and
// pointed into the element, or off.
void Context::InterleavedArrays(GLenum format, GLsizei stride, const void* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  const Interleaved* f = nullptr;
  for (const Interleaved& i : kInterleaved)
    if (i.format == format) f = &i;
  if (!f) return error(GL_INVALID_ENUM);
  const GLsizei s = stride ? stride : GLsizei(f->size * sizeof(GLfloat));
  const auto* base = static_cast<const GLubyte*>(p);
  auto at = [&](int floats) { return base + floats * sizeof(GLfloat); };
  other_enables_[GL_EDGE_FLAG_ARRAY] = false;
  other_enables_[GL_INDEX_ARRAY] = false;
  texcoord_array_ = {f->tex != 0, f->tex ? f->tex : texcoord_array_.size, f->tex ? GLenum(GL_FLOAT) : texcoord_array_.type,
                     f->tex ? s : texcoord_array_.stride, f->tex ? base : texcoord_array_.pointer};
  other_enables_[GL_TEXTURE_COORD_ARRAY] = f->tex != 0;
  if (f->color)
    color_array_ = {true, f->color, GLenum(f->ubyte_color ? GL_UNSIGNED_BYTE : GL_FLOAT), s, at(f->color_at)};
  else
    color_array_.enabled = false;
  if (f->normal)
    normal_array_ = {true, 3, GL_FLOAT, s, at(f->normal_at)};
  else
    normal_array_.enabled = false;
  vertex_array_ = {true, f->vertex, GL_FLOAT, s, at(f->vertex_at)};
}

// The texture coordinates of array element i, when that array is on.
void Context::fetch_texcoord(GLint i) {
  if (!texcoord_array_.enabled) return;
  texcoord_varies_ = true;
  const glm::dvec4 t = attribute(texcoord_array_, i, texcoord_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1));
  texcoord_ = glm::vec4(t);
}

int Context::attribute_values(GLenum pname, GLdouble* out) {
  switch (pname) {
    case GL_CURRENT_TEXTURE_COORDS:
      for (int k = 0; k < 4; ++k) out[k] = texcoord_[k];
      return 4;
    case GL_EDGE_FLAG: out[0] = edge_flag_; return 1;
    case GL_TEXTURE_COORD_ARRAY_SIZE: out[0] = texcoord_array_.size; return 1;
    case GL_TEXTURE_COORD_ARRAY_TYPE: out[0] = texcoord_array_.type; return 1;
    case GL_TEXTURE_COORD_ARRAY_STRIDE: out[0] = texcoord_array_.stride; return 1;
  }
  if (hint_target(pname)) {
    const auto it = hints_.find(pname);
    out[0] = it == hints_.end() ? GL_DONT_CARE : it->second;
    return 1;
  }
  return 0;
}

}  // namespace ffc::state
