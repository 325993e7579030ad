// The rasterizer's state (GL 2.1 sections 3.4 to 3.5 and 4.1.5): shading, facing and culling,
// depth function, line width and point size; and raster::State, all of it as the rasterizer
// reads it for a draw (fog and polygon offset add theirs in fog.cpp).
#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

// Each setter here flushes stored vertices only when it changes its value (Context::assign), as
// Mesa's light.c, polygon.c, depth.c, lines.c and points.c do; an invalid value flushes nothing.
void Context::ShadeModel(GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (mode != GL_FLAT && mode != GL_SMOOTH) return error(GL_INVALID_ENUM);
  assign(shade_model_, mode);
}

void Context::FrontFace(GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (mode != GL_CW && mode != GL_CCW) return error(GL_INVALID_ENUM);
  assign(front_face_, mode);
}

void Context::CullFace(GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (!valid_face(mode)) return error(GL_INVALID_ENUM);
  assign(cull_mode_, mode);
}

void Context::DepthFunc(GLenum func) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (func < GL_NEVER || func > GL_ALWAYS) return error(GL_INVALID_ENUM);
  assign(depth_func_, func);
}
void Context::LineWidth(float w) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (w <= 0) return error(GL_INVALID_VALUE);  // Mesa's test: a NaN passes
  assign(line_width_, w);
}

void Context::PointSize(float size) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (size <= 0) return error(GL_INVALID_VALUE);  // as Mesa's points.c: a NaN passes
  assign(point_size_, size);
}

raster::State Context::raster_state() const {
  raster::State rs;
  rs.viewport = viewport_;
  rs.depth_range = depth_range_;
  rs.flat = shade_model_ == GL_FLAT;
  rs.depth_test = depth_test_;
  rs.depth_func = depth_func_;
  rs.cull = cull_face_;
  rs.cull_mode = cull_mode_;
  rs.front_face = front_face_;
  rs.two_side = lighting_ && model_.two_side;
  rs.add_secondary = lighting_ && model_.separate_specular;
  rs.float_window = precision_ == Precision::Float;
  rs.fb_height = fb_.height;
  rs.line_width = line_width_;
  rs.point_size = point_size_;
  fog_raster_state(rs);
  fragment_raster_state(rs);
  rs.counters = &counters_;
  return rs;
}

}  // namespace ffc::state
