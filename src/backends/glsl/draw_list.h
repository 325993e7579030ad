// What one draw hands the core profile: GL_POINTS, GL_LINES and GL_TRIANGLES go as they came (the
// caller's indices, or glDrawArrays when there are none: the same primitives, the same provoking
// vertex, nothing copied); every other mode is rewritten by decompose() into `scratch`. A feature
// that must rewrite those three modes too (drawn differently from GL's lists) turns the pass-through
// off in listed().
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "backends/glsl/primitives.h"

namespace ffc::glsl {

struct DrawList {
  GLenum mode = GL_TRIANGLES;          // GL_POINTS, GL_LINES or GL_TRIANGLES
  const uint32_t* indices = nullptr;   // null: vertices 0 .. count - 1 (glDrawArrays)
  size_t count = 0;                    // whole primitives only
  size_t vertices = 0;                 // every index below it (glDrawRangeElements: no index scan)
};

// The list for `n` vertices of `mode` (elements[k] names vertex k when elements is not null) out of
// `vertices` (every element below it). With `edges` (an unfilled glPolygonMode pass, unfilled.h)
// every mode is decomposed, so that each triangle gets its boundary flags.
DrawList listed(GLenum mode, const uint32_t* elements, size_t n, size_t vertices, const SplitRule& rule,
                std::vector<uint32_t>& scratch, std::vector<uint8_t>* edges = nullptr);

}  // namespace ffc::glsl
