// The GLSL backend's vertex-level check: what its generated vertex shaders compute (window
// positions and lit colours, recorded with transform feedback) against Mesa's fixed-function
// feedback (GL_3D_COLOR), primitive by primitive. Feedback reports primitives after clipping and
// culling; transform feedback records them before: each of Mesa's primitives is paired with the
// one of ours at the same window positions (culled ones of ours are never asked for), and a
// primitive with a vertex the clipper made (at a position none of ours has) is counted, not compared.
#pragma once
#include <functional>
#include <set>
#include <string>

#include "check/feedback.h"

namespace ffc::glsl {

struct VertexComparison {
  size_t mesa_primitives = 0;
  size_t compared = 0;     // paired with one of ours and compared vertex by vertex
  size_t clipped = 0;      // with a clip-made vertex: not compared
  size_t unpaired = 0;     // every vertex at one of our positions, yet no primitive of ours there: a failure
  size_t vertices = 0;     // compared
  double max_abs = 0, rms = 0;  // colour, every channel
  double max_position = 0;      // window x, y, pixels
  size_t worst_primitive = 0, worst_vertex = 0;
  check::FeedbackVertex worst_mesa{}, worst_ours{};
  std::set<std::string> known_mesa_deviations;  // as soft names them for the same calls
  uint64_t compiles = 0, cache_hits = 0;        // the GLSL backend's program cache over the draw
};

// Draws with `draw` on Mesa (feedback) and on the GLSL backend (transform feedback) and compares.
VertexComparison compare_with_mesa(int width, int height, const std::function<void()>& draw);

}  // namespace ffc::glsl
