// A draw sink: something other than the vertex stage and the rasterizer that draws what our
// context assembles (the GLSL backend hands it to a core-profile GL through shaders). When a sink
// is set and the render mode is GL_RENDER, glDrawArrays, glDrawElements, glEnd and glClear give it
// the primitive mode, the object-space attributes of each vertex as GL fetched them (arrays or
// current values) and the indices; feedback and selection still take soft's path. The sink reads
// the rest of the state (matrices, lights, materials, the lighting key, culling, depth) from
// SinkState, a snapshot taken at the draw.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "lighting/lighting.h"
#include "state/fragment.h"

namespace ffc::state {

// One vertex as the sink's buffers hold it (the layout the GLSL backend streams: 11 floats).
struct SinkVertex {
  // Made unset: a draw's vertices are written whole before they are read, and a vector resized for
  // a large draw then zeroes nothing.
  SinkVertex() {}
  SinkVertex(const glm::vec4& p, const glm::vec3& n, const glm::vec4& c) : position(p), normal(n), color(c) {}
  glm::vec4 position;
  glm::vec3 normal;
  glm::vec4 color;
};

// The material of both faces at one vertex, for a glBegin/glEnd whose glMaterial calls change it
// between vertices: per face ambient (its alpha holding the shininess), diffuse, specular and
// emission, as the GLSL backend streams them (32 floats).
struct SinkMaterial {
  glm::vec4 face[2][4];
};

// Every value of the snapshot but the list of names: trivially copyable, so that the GLSL
// backend can compare two draws' states byte by byte (its uniform cache, uniform_cache.h) and
// reuse the uniforms it made for equal bytes. A value that feeds a uniform belongs here (or behind
// one of the pointers the cache compares: lights, materials, fragment).
struct SinkValues {
  bool lighting = false;
  lighting::Key key;  // Key{} when lighting is off
  const lighting::LightParams* lights = nullptr;        // [8], positions and directions in eye space
  const lighting::MaterialParams* materials = nullptr;  // [2], front and back, colour material tracked
  lighting::ModelParams model;  // color_material: the colour comes per vertex (the key's bit)
  glm::mat4 modelview{1}, mvp{1};  // in float, as Mesa computes them
  glm::dmat3 normal_inverse{1};    // M^-1 of the modelview's upper 3x3: eye normal = n * M^-1
  double rescale = 0;              // GL_RESCALE_NORMAL's divisor; 0: none
  bool flat = false;
  bool cull = false;
  GLenum cull_mode = GL_BACK, front_face = GL_CCW;
  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  glm::ivec4 viewport{0};
  glm::dvec2 depth_range{0, 1};
  float point_size = 1, line_width = 1;
  const FragmentState* fragment = nullptr;  // scissor, blending, masks, alpha test, stipple
  glm::vec4 clear_color{0};
  double clear_depth = 1;
  // Fog (state/fog.cpp): the mode, the coordinate's source, Mesa's optimized parameters
  // (raster::State::fog_params: linear's scale and offset, exp's and exp2's density over ln 2 and
  // sqrt(ln 2)) and the colour.
  bool fog = false;
  GLenum fog_mode = GL_EXP, fog_coord_src = GL_FRAGMENT_DEPTH;
  glm::vec4 fog_params{0};
  glm::vec3 fog_color{0};
  // Polygon offset (glPolygonOffset's values as given; the sink's GL scales the units itself).
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0, offset_units = 0;
  // glPolygonMode per face (front, back). A sink drawing the faces of one mode at a time sets
  // pass_mode to it and pass_faces to the faces it covers (bit 0 front, bit 1 back); 0: not split.
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL};
  GLenum pass_mode = 0;
  unsigned pass_faces = 3;
  // One material per vertex when glMaterial changed it inside this glBegin/glEnd; null otherwise
  // (`materials` then holds for every vertex).
  const std::vector<SinkMaterial>* vertex_materials = nullptr;
};

struct SinkState : SinkValues {
  // Enabled state that changes pictures and that the sink is not given (fog, polygon offset and
  // modes, ...): one line each, for the sink to report.
  std::vector<std::string> unsupported;
};

static_assert(std::is_trivially_copyable_v<SinkValues>, "compared byte by byte: no owning members");

class DrawSink {
 public:
  virtual ~DrawSink() = default;
  // mode: a GL primitive (GL_POINTS .. GL_POLYGON); indices into `vertices` (null: 0 .. count - 1).
  virtual void draw(const SinkState& s, GLenum mode, const SinkVertex* vertices, size_t count,
                    const uint32_t* indices, size_t index_count) = 0;
  // glClear's mask (colour and depth; the others have no buffer here).
  virtual void clear(const SinkState& s, GLbitfield mask) = 0;
  // glReadPixels reads soft's framebuffer: the sink copies its colour buffer there first (RGBA8,
  // top row first, as raster::Framebuffer keeps it).
  virtual void read_back(uint8_t* rgba, int width, int height) = 0;
  // glDrawPixels and glBitmap are soft's: the sink's colour and depth copied into soft's
  // framebuffer, soft draws there, and the result goes back to the sink: these two take GL's rows
  // (the bottom one first, as raster::Framebuffer keeps them), depth as 24-bit values.
  virtual void read_depth(uint32_t* depth, int width, int height) = 0;
  virtual void write_back(const uint8_t* rgba, const uint32_t* depth, int width, int height) = 0;
};

}  // namespace ffc::state
