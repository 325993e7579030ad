// The GLSL backend's draw sink: what our state tracker assembles, drawn through a core-profile
// context with the program generated for the state's key (cached by key), the uniforms uploaded
// when their values change (uniform_cache.h), the vertices the program reads streamed into one buffer
// (vertex_stream.h), GL's lists drawn from the caller's indices (draw_list.h). Nothing is allocated per draw
// once a scene's programs and states were seen. It can also record what the vertex shader computes
// (transform feedback), for `ffcompat check`.
#pragma once
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "backends/glsl/draw_list.h"
#include "backends/glsl/gl_core.h"
#include "backends/glsl/material_stream.h"
#include "backends/glsl/pixel_write.h"
#include "backends/glsl/shader_gen.h"
#include "backends/glsl/stipple.h"
#include "backends/glsl/unfilled.h"
#include "backends/glsl/uniform_cache.h"
#include "backends/glsl/vertex_stream.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

struct CapturedVertex {
  glm::vec4 clip;
  glm::vec4 front, back;  // back = front without two-sided lighting
};

// One draw as transform feedback recorded it: points, lines or triangles (provoking vertex last).
struct CapturedDraw {
  GLenum mode = GL_TRIANGLES;
  bool flat = false, cull = false;
  GLenum cull_mode = GL_BACK, front_face = GL_CCW;
  glm::ivec4 viewport{0};
  glm::dvec2 depth_range{0, 1};
  std::vector<CapturedVertex> vertices;
};

struct Stats {
  uint64_t draws = 0, compiles = 0, cache_hits = 0, uniform_uploads = 0;
};

// A program as the cache holds it: the key, the sources and the uniforms' last values.
struct ProgramInfo {
  ProgramKey key;
  Sources sources;
  std::vector<Uniform> uniforms;
  uint64_t draws = 0;
};

class Renderer final : public state::DrawSink {
 public:
  explicit Renderer(const CoreGl& gl);  // the context current, the functions loaded
  ~Renderer() override;
  void draw(const state::SinkState& s, GLenum mode, const state::SinkVertex* vertices, size_t count,
            const uint32_t* indices, size_t index_count) override;
  void clear(const state::SinkState& s, GLbitfield mask) override;
  void read_back(uint8_t* rgba, int width, int height) override;
  void read_depth(uint32_t* depth, int width, int height) override { glsl::read_depth(gl_, depth, width, height); }
  void write_back(const uint8_t* rgba, const uint32_t* depth, int width, int height) override {
    pixels_.write(gl_, rgba, depth, width, height);
  }

  void set_capture(bool on) { capture_ = on; }
  void set_phong(bool on) { phong_ = on; }  // lit smooth draws lit per fragment
  const std::vector<CapturedDraw>& captured() const { return captured_; }
  const Stats& stats() const { return stats_; }
  std::vector<const ProgramInfo*> programs() const;  // in the order they were made
  const std::set<std::string>& unsupported() const { return unsupported_; }

 private:
  struct Program {
    explicit Program(const ProgramKey& k) : cache(k) {}
    GLuint id = 0;
    UniformCache cache;
    VertexFormat format;  // the attributes it reads
    std::vector<GLint> locations;  // per uniform of info.uniforms
    std::vector<bool> uploaded;
    ProgramInfo info;
    size_t order = 0;
  };
  Program& program_for(const ProgramKey& k);
  void upload(Program& p, const state::SinkState& s);
  void apply(const state::SinkState& s);
  void apply_fragment(const state::SinkState& s);
  void submit(const DrawList& list);
  void capture_draw(const state::SinkState& s, const DrawList& list, const Program& p);
  CapturedDraw record(const state::SinkState& s, const DrawList& list, const Program& p);
  bool stippled(const state::SinkState& s, GLenum mode, const DrawList& list, const Program& p);  // stipple.h
  void report(const std::string& what);  // a feature drawn without: one line on stderr, once

  const CoreGl& gl_;
  GLuint vao_ = 0, tfb_ = 0;
  VertexStream vertices_;
  StreamBuffer elements_;  // the draw's list
  std::map<uint64_t, Program> programs_;
  std::vector<uint32_t> list_;    // decompose()'s lists, kept for the next draw
  std::vector<uint8_t> read_rows_;  // read_back's rows as GL reads them
  GLenum read_format_ = GL_RGBA;  // the colour buffer's own order, read without conversion
  bool capture_ = false, phong_ = false;
  std::vector<CapturedDraw> captured_;
  Stats stats_;
  std::set<std::string> unsupported_;
  MaterialStream materials_;  // glMaterial inside glBegin/glEnd (material_stream.h)
  EdgeStream edges_;          // glPolygonMode's boundary flags (unfilled.h)
  PixelWriter pixels_;        // glDrawPixels and glBitmap (pixel_write.h)
  StippleLines stipple_;      // line stipple (stipple.h)
  std::vector<StippleVertex> pieces_;
  int fb_height_ = 0;         // the surface's rows (its first viewport), for the stipple's window y
};

}  // namespace ffc::glsl
