// The per-fragment operations after coverage and colour (State::Ops), shared by the fragment-ops
// row loop of triangles (fragment_ops.cpp) and the loops of lines and points (raster.cpp). Not an
// interface.
#pragma once
#include <cstdint>

#include "raster/pixel_rules.h"
#include "raster/raster.h"

namespace ffc::raster::detail {

inline bool scissor_pass(const State::Ops& o, int x, int y) {
  return !o.scissor || (x >= o.scissor_x0 && x < o.scissor_x1 && y >= o.scissor_y0 && y < o.scissor_y1);
}

// The alpha test as llvmpipe runs it on an 8-bit colour buffer (lp_bld_alpha.c): the fragment's
// alpha converted to unorm8 as it would be stored, compared with the reference converted the same
// way (measured: with GL_GREATER and reference 0.5, alpha 0.503 fails and 0.504 passes).
inline bool alpha_pass(const State::Ops& o, double alpha) {
  return !o.alpha_test || depth_pass(o.alpha_func, to_unorm8(alpha), o.alpha_ref);  // the same eight comparisons
}

// The fragment's colour into the buffer at `dst`: blended when on, then written through the
// colour mask.
void write_color(const State::Ops& o, uint8_t* dst, const glm::dvec4& color);

}  // namespace ffc::raster::detail
