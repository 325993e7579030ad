// Line stipple on the GLSL backend, as Mesa's draw module applies it ahead of llvmpipe's line
// rasterizer (and as soft's raster::draw_line reproduces it): the draw's lines, as transform
// feedback recorded them, are cut on the CPU into one sub-line per run of set pattern bits, and
// those sub-lines are drawn by a pass-through program, so that the core context rasterizes each
// of them with the draw's fragment state (depth test, blending, masks, scissor).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "backends/glsl/gl_core.h"

namespace ffc::glsl {

struct CapturedVertex;

// A sub-line's end as the core context takes it: the clip position and the colour.
struct StippleVertex {
  glm::vec4 clip;
  glm::vec4 color;
};

struct StippleRule {
  int factor = 1;             // glLineStipple's factor, 1 .. 256
  uint16_t pattern = 0xFFFF;  // and its pattern, bit 0 first
  bool restart_each = false;  // GL_LINES: each line starts the pattern again; strips and loops run on
  bool flat = false;          // GL_FLAT: every piece takes its line's provoking (second) vertex's colour
  glm::ivec4 viewport{0};
  glm::dvec2 depth_range{0, 1};
  int fb_height = 0;          // the framebuffer's rows: llvmpipe measures y downwards from its top
};

// `lines` holds pairs (the list order, the provoking vertex second), clipped here as Mesa clips
// them before its stipple stage (the pattern starts where the clipped line does). `out` gets pairs again: the pieces, each end's clip position chosen so that the core context's
// viewport transform puts it on the window position the cut lerped.
void cut_stippled(const std::vector<CapturedVertex>& lines, const StippleRule& rule, std::vector<StippleVertex>& out);

// The pass-through programs (smooth, flat) and their vertex array.
class StippleLines {
 public:
  void draw(const CoreGl& gl, const std::vector<StippleVertex>& lines, bool flat);
  void destroy(const CoreGl& gl);

 private:
  GLuint programs_[2] = {0, 0}, vao_ = 0, buffer_ = 0;
};

}  // namespace ffc::glsl
