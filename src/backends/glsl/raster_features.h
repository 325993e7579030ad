// The rasterization state the core profile keeps as the fixed-function one does, handed over as
// it is: polygon offset (GL 2.1 section 3.5.5). The same llvmpipe scales the units by its depth
// buffer's resolution on either profile, so the values go through unchanged.
#pragma once
#include "backends/glsl/gl_core.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

void apply_raster_features(const CoreGl& gl, const state::SinkState& s);

}  // namespace ffc::glsl
