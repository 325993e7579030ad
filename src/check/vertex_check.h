// The vertex-level regression: our lit colours against Mesa's, vertex by vertex.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "check/feedback.h"

namespace ffc::check {

struct ChannelStats {
  double max_abs = 0, rms = 0;
};

struct VertexReport {
  size_t vertices = 0;
  double max_abs = 0, rms = 0;  // our float path against Mesa, every channel of every vertex
  double max_abs_double = 0, rms_double = 0;  // our double reference against Mesa
  double max_abs_float_vs_double = 0;         // how far our float path is from the reference
  ChannelStats channel[4];                    // float path, per channel (r, g, b, a)
  double max_position = 0;                    // window-position disagreement, pixels
  // Where the float path is furthest from Mesa: primitive, vertex, and both colours.
  size_t worst_primitive = 0, worst_vertex = 0;
  FeedbackVertex worst_mesa{}, worst_ours{};
  std::vector<std::string> known_mesa_deviations;
};

// Draws with `draw` on Mesa, our float and our double backends in feedback mode and compares.
// Throws std::runtime_error when the primitives do not line up (different count, token or
// vertex count): that is a structural failure, not a colour difference.
VertexReport compare_vertices(int width, int height, const std::function<void()>& draw);

}  // namespace ffc::check
