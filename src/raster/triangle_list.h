// Triangles that share their vertices, as glDrawArrays, glDrawElements and immediate mode give
// them. Each vertex is mapped to the window once; each triangle is binned once, as a 4-byte
// number, to the threads whose bands of rows it meets (a vector of triangles at a time on a Highway
// vector target), and set up where it is drawn: a group at a time (eight on AVX2 and AVX-512) for
// the box kernel (raster/wide/) when the state
// is smooth colour without secondary colour, culling or two-sided lighting, one by one otherwise.
#pragma once
#include <algorithm>
#include <climits>
#include <cstdint>
#include <vector>

#include "raster/raster.h"
#include "pool/workers.h"

namespace ffc::raster {

// A vertex after the vertex stage, as setup reads it: 32 bytes, two to a cache line. Float path
// only: the window position is map_to_window's with State::float_window, bit for bit.
struct alignas(32) ShadedVertex {
  float x, y, z;    // window position, y counted down from the top as llvmpipe has it (GL's y is
                    // fb_height - y in float, as map_float computes it)
  float w;          // clip w (1/w is taken in double, as map_to_window does)
  glm::vec4 color;  // primary colour for the front (flat: its own; the provoking one is chosen later)
};

// Its position snapped to 1/256 pixel (pixel centres at +128), kept apart: the triangle walk reads
// only these, 8 bytes a vertex, and most triangles at high subdivision need nothing more.
struct Snapped {
  int32_t x, y;
};
constexpr int32_t kNotMapped = INT32_MIN;  // x of a vertex that needs clipping

// The vertices of a draw, as arrays. back, front_sec and back_sec are filled only when the state
// reads them (two-sided lighting, separate specular).
struct ListVertices {
  std::vector<ShadedVertex> hot;
  std::vector<Snapped> snapped;
  std::vector<glm::vec4> clip;  // for clipping and facing
  std::vector<glm::vec4> back, front_sec, back_sec;
  void resize(size_t n, bool two_side, bool secondary) {
    hot.resize(n), snapped.resize(n), clip.resize(n);
    back.resize(two_side ? n : 0), front_sec.resize(secondary ? n : 0), back_sec.resize(two_side && secondary ? n : 0);
  }
  // Whether records [0, n) exist, with the colours the state reads.
  bool holds(size_t n, bool two_side, bool secondary) const {
    const size_t have = hot.size();
    return have >= n && back.size() == (two_side ? have : 0) && front_sec.size() == (secondary ? have : 0) &&
           back_sec.size() == (two_side && secondary ? have : 0);
  }
  // At least n records (growing to `room`, n at least, where it must grow), without touching those
  // there are: growing value-initialises the new records.
  void grow(size_t n, size_t room, bool two_side, bool secondary) {
    if (!holds(n, two_side, secondary)) resize(std::max(n, room), two_side, secondary);
  }
};

// Vertices [first, first + count): window and snapped positions from their clip coordinates
// (vs.clip). `front`: columns of their front colours (r, g, b, a; vertex first + j at [j]),
// written into the records with the positions; null: the colours are the caller's.
void map_list_vertices(ListVertices& vs, size_t first, size_t count, const State& s, const float* const* front = nullptr);

// The binned triangles of a draw, kept between draws so that steady state allocates nothing.
struct TriangleBins {
  std::vector<std::vector<uint32_t>> lists;
  // Room for a draw of up to `triangles` on `threads` threads, so that it allocates nothing: a
  // draw whose size varies from frame to frame (immediate mode's last part after early draws)
  // would otherwise grow the lists whenever it outgrows every earlier one.
  void reserve(size_t triangles, int threads);
};

// Draws triangle t from vertices (idx[3t], idx[3t+1], idx[3t+2]), or (3t, 3t+1, 3t+2) when idx is
// null; the third is the provoking vertex. In two passes over the threads: binning (each thread
// takes a contiguous share of the triangles, drops those that enclose no pixel centre and keeps
// the others for the threads whose bands they meet), then drawing (each thread sets up and draws
// what was kept for it, in primitive order). Triangles that need clipping take clip_and_map. Not
// for feedback, and s.float_window must be set. `clear`, when pending, is done first: each
// thread clears the bands it draws, just before it draws them.
void draw_triangle_list(Framebuffer& fb, const State& s, const ListVertices& vs, const uint32_t* idx,
                        size_t triangles, pool::Workers& workers, TriangleBins& bins, const ClearRequest& clear = {});

}  // namespace ffc::raster
