// Points the core context's rasterizer places one pixel from Mesa's fixed function: llvmpipe draws
// a legacy GL point as a square of whole pixels (an odd size around the pixel holding the centre,
// an even one around the nearest pixel corner, ties rounded up), the core profile as a quad of
// the point's size rasterized as polygons are; the two agree except where one of the quad's edges
// falls exactly on a pixel centre (an odd size centred on a pixel edge, an even one on a pixel
// centre), where the polygon's tie rule takes the other pixel. Such draws are reported.
#pragma once
#include <cstddef>
#include <cstdint>

#include "state/draw_sink.h"

namespace ffc::glsl {

// Whether a point of the draw (elements[k] names vertex k when not null) has such a centre.
bool point_on_tie(const state::SinkState& s, const state::SinkVertex* v, size_t count, const uint32_t* elements, size_t n,
                  int fb_height);

}  // namespace ffc::glsl
