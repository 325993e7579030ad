// Feedback (GL 2.1 section 5.3; Mesa's feedback.c and its draw module's feedback stage):
// glFeedbackBuffer, glRenderMode, and the values a primitive reports.
#include <cmath>
#include <initializer_list>

#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

// A fed-back triangle's depths as the offset stage of Mesa's draw module leaves them
// (draw_pipe_offset.c): z + units + max(|dz/dx|, |dz/dy|) * factor in float, both terms 0 unless
// GL_POLYGON_OFFSET_FILL is on (polygons are filled), then clamped to [0, 1] by a clamp that takes
// NaN to 0. The slopes divide by the triangle's doubled area, so a triangle of zero area gets
// 0/0 or x/0 there, and 0 times that a NaN: its depths all become 0.
void Context::feedback_offset(const raster::WindowVertex* const* v, const raster::State& rs, float* z) const {
  float p[3][3];
  for (int k = 0; k < 3; ++k) p[k][0] = float(v[k]->pos.x), p[k][1] = float(v[k]->pos.y), p[k][2] = float(v[k]->pos.z);
  const float ex = p[0][0] - p[2][0], ey = p[0][1] - p[2][1], ez = p[0][2] - p[2][2];
  const float fx = p[1][0] - p[2][0], fy = p[1][1] - p[2][1], fz = p[1][2] - p[2][2];
  const float det = ex * fy - ey * fx, inv_det = 1.0f / det;
  const float dzdx = std::fabs((ey * fz - ez * fy) * inv_det), dzdy = std::fabs((ez * fx - ex * fz) * inv_det);
  const float scale = offset_fill_ ? offset_factor_ : 0.0f, units = offset_fill_ ? rs.offset_units : 0.0f;
  const float offset = units + (dzdx > dzdy ? dzdx : dzdy) * scale;
  for (int k = 0; k < 3; ++k) {
    const float d = p[k][2] + offset;
    z[k] = d > 0 ? (d > 1 ? 1.0f : d) : 0.0f;
  }
}

// A primitive as feedback reports it (kind: GL_POINT_TOKEN, GL_LINE_TOKEN or GL_POLYGON_TOKEN). A
// clipped triangle goes back as Mesa's clipper emits it (emit_poly in draw_pipe_clip.c): a fan of
// triangles (v[i], v[i+1], v[0]), the first vertex last, also when the clipped polygon is a
// triangle. With the offset stage in the pipeline, a triangle's depths are offset (feedback_offset).
void Context::feedback_primitive(GLenum kind, const raster::WindowVertex* w, size_t count, bool clipped,
                                 const raster::State& rs, bool offset_stage) {
  auto one = [&](std::initializer_list<const raster::WindowVertex*> vs) {
    // Mesa's cull stage runs after its clipper, on each triangle it passes on, by the float window
    // determinant (window_culled: one of zero area is a back face there).
    if (kind == GL_POLYGON_TOKEN && window_culled(window_det(vs.begin()), rs)) return;
    float z[3] = {};
    if (kind == GL_POLYGON_TOKEN && offset_stage) feedback_offset(vs.begin(), rs, z);
    // A hit: its window depths, as feedback would report them; nothing goes to the feedback buffer.
    if (render_mode_ == GL_SELECT) {
      int k = 0;
      for (const raster::WindowVertex* v : vs) select_hit(kind == GL_POLYGON_TOKEN && offset_stage ? z[k++] : v->pos.z);
      return;
    }
    feedback_put(kind);
    if (kind == GL_POLYGON_TOKEN) feedback_put(double(vs.size()));
    int n = 0;
    for (const raster::WindowVertex* v : vs) {
      feedback_put(v->pos.x), feedback_put(v->pos.y);
      if (feedback_type_ != GL_2D) feedback_put(kind == GL_POLYGON_TOKEN && offset_stage ? double(z[n]) : v->pos.z);
      ++n;
      if (feedback_type_ == GL_4D_COLOR_TEXTURE) feedback_put(1 / v->inv_w);
      if (feedback_type_ == GL_3D_COLOR || feedback_type_ == GL_3D_COLOR_TEXTURE || feedback_type_ == GL_4D_COLOR_TEXTURE)
        for (int k = 0; k < 4; ++k)  // -0: a NaN clamped (vertex_stage.cpp, clamp_unlit), fed back as 1
          feedback_put(v->color[k] == 0 && std::signbit(v->color[k]) ? 1.0 : double(v->color[k]));
      if (feedback_type_ == GL_3D_COLOR_TEXTURE || feedback_type_ == GL_4D_COLOR_TEXTURE)
        for (int k = 0; k < 4; ++k) feedback_put(texcoord_[k]);
    }
  };
  if (kind == GL_POINT_TOKEN) return one({&w[0]});
  if (kind != GL_POLYGON_TOKEN) return one({&w[0], &w[1]});
  if (!clipped) return one({&w[0], &w[1], &w[2]});
  for (size_t i = 1; i + 1 < count; ++i) one({&w[i], &w[i + 1], &w[0]});
}

// Fed-back texture coordinates are the current ones as set (Mesa reports them untransformed by the
// texture matrix): texture generation is not modelled, nor coordinates that vary between the
// vertices of one draw (soft's vertices carry none).
void Context::note_texgen_in_feedback() {
  if (render_mode_ != GL_FEEDBACK || (feedback_type_ != GL_3D_COLOR_TEXTURE && feedback_type_ != GL_4D_COLOR_TEXTURE))
    return;
  if (texcoord_varies_) deviations_.insert(kTexCoordVarying);
  for (GLenum gen : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
    if (enabled_state(gen) == 1) deviations_.insert(kTexGen);
}

void Context::feedback_put(double x) {
  if (feedback_count_ < feedback_size_) feedback_[feedback_count_] = GLfloat(x);
  else feedback_overflow_ = true;
  ++feedback_count_;
}

void Context::FeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  // Mesa's order (feedback.c): feedback mode, the size, a null buffer, then the type.
  if (!outside_begin_end_or_compiling()) return;
  if (render_mode_ == GL_FEEDBACK) return error(GL_INVALID_OPERATION);
  if (size < 0) return error(GL_INVALID_VALUE);
  if (!buffer && size > 0) return error(GL_INVALID_VALUE);
  if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
      type != GL_4D_COLOR_TEXTURE)
    return error(GL_INVALID_ENUM);
  feedback_ = buffer, feedback_size_ = size, feedback_type_ = type;
}

GLint Context::RenderMode(GLenum mode) {
  if (!outside_exec_primitive()) return 0;
  if (mode != GL_RENDER && mode != GL_FEEDBACK && mode != GL_SELECT) return error(GL_INVALID_ENUM), 0;
  // Feedback needs a buffer of non-zero size; selection a glSelectBuffer of non-zero size. Mesa
  // records GL_INVALID_OPERATION and then switches the mode all the same; ours stays in its mode,
  // as GL 2.1 section 2.5 says.
  if (mode == GL_FEEDBACK && feedback_size_ == 0) return error(GL_INVALID_OPERATION), 0;
  if (mode == GL_SELECT && select_.size == 0) return error(GL_INVALID_OPERATION), 0;
  GLint result = 0;
  if (render_mode_ == GL_FEEDBACK) result = feedback_overflow_ ? -1 : feedback_count_;
  if (render_mode_ == GL_SELECT) result = leave_select();
  render_mode_ = mode;
  feedback_count_ = 0;
  feedback_overflow_ = false;
  return result;
}
// glPassThrough: a marker in the feedback buffer (GL_PASS_THROUGH_TOKEN, then the value); nothing
// in the other modes.
// Mesa's glPassThrough flushes (FLUSH_VERTICES) only in feedback mode; elsewhere it checks for
// glBegin/glEnd and does nothing (measured, seed 244949 stream 3617352611758767512, repro
// pass_through_flushes_in_feedback_only.txt: a GL_COMPILE_AND_EXECUTE list's draw, glPassThrough in
// GL_RENDER, then a wrapped glBegin: the colour read inside it is from before the draw).
void Context::PassThrough(GLfloat token) {
  if (render_mode_ != GL_FEEDBACK) {
    if (in_begin_) error(GL_INVALID_OPERATION);
    return;
  }
  if (!outside_begin_end()) return;
  feedback_put(GL_PASS_THROUGH_TOKEN);
  feedback_put(token);
}
}  // namespace ffc::state
