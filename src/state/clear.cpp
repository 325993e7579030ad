// glClearColor, glClearDepth and glClear (GL 2.1 section 4.2.3): a clear is kept pending until
// something draws or reads, so that a triangle list can clear band by band on its threads.
#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

void Context::ClearColor(float r, float g, float b, float a) {
  if (!outside_begin_end_keeping_vertices()) return;
  clear_color_ = glm::vec4(clamp01(r), clamp01(g), clamp01(b), clamp01(a));
}

void Context::ClearDepth(double d) {
  if (!outside_begin_end_keeping_vertices()) return;
  clear_depth_ = clamp01(d);
}

void Context::Clear(GLbitfield mask) {
  if (!outside_begin_end()) return;
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT))
    return error(GL_INVALID_VALUE);
  if (render_mode_ != GL_RENDER) return;
  if (sink_) return sink_->clear(sink_state(), mask);  // draw_sink.h
  if (clear_with_fragment_ops(mask)) return;  // fragment.cpp
  raster::ClearRequest& c = pending_clear_;  // a later clear of the same buffer replaces an earlier one
  if (mask & GL_COLOR_BUFFER_BIT) c.color = true, c.clear_color = clear_color_;
  if (mask & GL_DEPTH_BUFFER_BIT) c.depth = true, c.clear_depth = clear_depth_;
}

void Context::flush_clear() {
  if (!pending_clear_.pending()) return;
  raster::clear(fb_, pending_clear_, workers());
  pending_clear_ = {};
}

// Nothing is left to do: every draw is finished when its call returns. Inside glBegin/glEnd both
}  // namespace ffc::state
