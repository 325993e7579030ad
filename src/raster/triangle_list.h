// Triangles that share their vertices, as glDrawArrays and glDrawElements give them. Each vertex
// is mapped to the window once; then every thread walks the whole list and sets up and draws only
// what falls in its own bands of rows, so no triangle is stored between setup and drawing and the
// planes of a triangle that covers no pixel centre are never computed.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/raster.h"
#include "raster/workers.h"

namespace ffc::raster {

// A vertex after the vertex stage, as the triangle stage reads it (48 bytes). Float path only:
// the window fields are map_to_window's with State::float_window, bit for bit.
struct ShadedVertex {
  glm::vec4 clip;
  double inv_w;      // 1 / clip.w
  float x, y, z;     // window position
  int32_t sx, sy;    // snapped to 1/256 pixel, pixel centres at +128
  uint32_t outside;  // outside_planes(clip), or kUnsnappable; 0: the window fields are set
};
constexpr uint32_t kUnsnappable = 1u << 8;  // inside, but too far out for 32-bit snapped coordinates

constexpr uint16_t kNoBand = 0xFFFF;

// Fills v.inv_w, the window fields and v.outside from v.clip. Returns the band of the row the
// vertex lies in (clamped to the framebuffer), kNoBand when it is not mapped: a triangle whose
// three vertices share a band draws only in that band.
uint16_t map_shaded(ShadedVertex& v, const State& s);

// Lit colours per vertex; only those the state reads are filled (back: two-sided lighting,
// secondary: separate specular).
struct ShadedColors {
  std::vector<glm::vec4> front, back, front_sec, back_sec;
};

// Draws triangle t from vertices (idx[3t], idx[3t+1], idx[3t+2]), or (3t, 3t+1, 3t+2) when idx is
// null; the third is the provoking vertex. Triangles that need clipping take clip_and_map. Not
// for feedback, and s.float_window must be set.
// `bands` holds map_shaded's result per vertex.
void draw_triangle_list(Framebuffer& fb, const State& s, const ShadedVertex* v, const uint16_t* bands,
                        const ShadedColors& colors, const uint32_t* idx, size_t triangles, Workers& workers);

}  // namespace ffc::raster
