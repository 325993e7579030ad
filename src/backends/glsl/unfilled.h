// glPolygonMode (GL 2.1 section 3.5.4) on a core profile, whose glPolygonMode takes only
// GL_FRONT_AND_BACK and which has no edge flags: a draw of polygons is split into one pass per
// mode its visible faces use. The GL_FILL pass draws triangles, culling the faces of the other
// passes. A GL_LINE or GL_POINT pass draws through a geometry shader that takes each triangle,
// finds its facing from the window-space winding (as Mesa's draw module does, after the vertex
// stage), keeps it only when its face is this pass's, and emits its boundary edges (or their
// first vertices) as the decomposition marked them (primitives.h), every vertex with the colour
// of the face shown and, under GL_FLAT, the provoking vertex's. The boundary flags reach the
// shader through a buffer texture indexed by gl_PrimitiveIDIn.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "backends/glsl/gl_core.h"
#include "backends/glsl/shader_gen.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

// Whether a draw of `mode` is split into passes: polygons under an unfilled glPolygonMode, not
// already a pass. Asked before polygon_passes so that a filled draw builds no std::function.
inline bool needs_polygon_passes(const state::SinkState& s, GLenum mode) {
  return mode >= GL_TRIANGLES && !s.pass_mode && (s.polygon_mode[0] != GL_FILL || s.polygon_mode[1] != GL_FILL);
}

// For a draw of `mode` under an unfilled glPolygonMode: `draw` called once per pass with the
// pass's state (pass_mode and pass_faces set, culling adjusted); true. Otherwise false.
bool polygon_passes(const state::SinkState& s, GLenum mode, const std::function<void(const state::SinkState&)>& draw);

// Whether `s` is a GL_LINE or GL_POINT pass (its triangles need their boundary flags).
inline bool unfilled_pass(const state::SinkState& s) { return s.pass_mode == GL_LINE || s.pass_mode == GL_POINT; }

void unfilled_key(ProgramKey& k, const state::SinkState& s);

// The vertex shader's colour outputs (and v_fog) renamed for the geometry shader to read, and
// the geometry shader; both empty unless k.unfilled.
std::string unfilled_vertex_renames(const ProgramKey& k, const std::vector<std::string>& colours);
std::string unfilled_geometry(const ProgramKey& k, const std::vector<std::string>& colours);

// The boundary flags of a pass's triangles in a buffer texture on unit 0.
class EdgeStream {
 public:
  std::vector<uint8_t>* flags(const state::SinkState& s) { return unfilled_pass(s) ? &flags_ : nullptr; }
  void stream(const CoreGl& gl, const state::SinkState& s);
  void destroy(const CoreGl& gl);

 private:
  std::vector<uint8_t> flags_;
  GLuint buffer_ = 0, texture_ = 0;
};

}  // namespace ffc::glsl
