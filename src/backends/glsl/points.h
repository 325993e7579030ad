// GL_POINTS on a core profile as llvmpipe's legacy fixed function draws them (GL 2.1 section
// 3.3.1, as raster::draw_point reproduces it): a square of whole pixels, an odd size around the
// pixel holding the centre, an even one around the nearest pixel corner. The core rasterizer
// would draw a quad of the point's size with polygon tie rules, one pixel away wherever an edge
// of the quad falls on a pixel centre. Instead a geometry shader takes each point, finds its
// window position from gl_Position and the viewport (u_point_viewport), chooses the pixel square
// by llvmpipe's rule in 1/256 pixel, and emits a strip whose corners lie on pixel boundaries (no
// pixel centre on an edge), mapped back to clip space with w = 1, the point's depth and colours.
// Programs that capture transform feedback keep no such shader: they record the vertex stage.
#pragma once
#include <string>
#include <vector>

#include "backends/glsl/shader_gen.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

// The point's width in whole pixels as llvmpipe rounds it (half down, at least 1, at most 255).
int point_width(float point_size);

// The uniforms of k.points programs: the viewport and the width.
void point_uniforms(const ProgramKey& k, const state::SinkState* s, std::vector<Uniform>& out);

// The vertex shader's outputs renamed for the geometry shader, and the geometry shader; both
// empty unless k.points.
std::string point_vertex_renames(const ProgramKey& k, const std::vector<std::string>& colours);
std::string point_geometry(const ProgramKey& k, const std::vector<std::string>& colours);

}  // namespace ffc::glsl
