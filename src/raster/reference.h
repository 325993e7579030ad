// The reference rasterizer: the rules by which a set-up triangle (raster::setup) becomes pixels,
// written out pixel by pixel with no shortcut, to be read as the rule book. Every fast path (the
// row loop, the box and span kernels, the triangle lists, any thread count) must write the same
// bits into the colour and depth buffers; tests/raster/reference_test.cpp holds them to it.
#pragma once
#include "raster/raster.h"

namespace ffc::raster {

// Draws t (set up; its box may reach past the framebuffer) into fb, all rows, on this thread.
// Fog and polygon offset are not among its rules (State::fragment_ops: the scalar loop's).
void draw_reference(Framebuffer& fb, const Triangle& t, const State& s);

// While on, draw_triangles draws every triangle with draw_reference (for tests and for reading
// a picture's origin; process-wide, off by default).
void set_reference_rasterizer(bool on);
bool reference_rasterizer();

}  // namespace ffc::raster
