#include "backends/glsl/renderer.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "backends/glsl/raster_features.h"
#include "raster/raster.h"

namespace ffc::glsl {

namespace {

// Mesa's draw module looks for vertices outside the view volume among those the draw uses.
bool any_outside(const state::SinkState& s, const state::SinkVertex* v, size_t count, const uint32_t* idx, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    const size_t i = idx ? idx[k] : k;
    if (i < count && raster::outside_planes(glm::dvec4(s.mvp * v[i].position)) != 0) return true;
  }
  return false;
}

}  // namespace

Renderer::Renderer(const CoreGl& gl) : gl_(gl), vertices_(gl), elements_(gl, GL_ELEMENT_ARRAY_BUFFER) {
  gl_.GenVertexArrays(1, &vao_);
  gl_.BindVertexArray(vao_);  // the streams bind their buffers to it (the element buffer is its state)
  gl_.GenBuffers(1, &tfb_);
  // A new buffer's contents are undefined in GL; llvmpipe's start at 0, and soft's too: cleared
  // here so that a program drawing without glClear sees the same on every backend.
  gl_.ClearColor(0, 0, 0, 0);
  gl_.ClearDepth(0);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // llvmpipe's pbuffer is BGRA: read in RGBA, Mesa converts through a blit to a staging texture;
  // in its own order it copies, and read_back swaps red and blue as it flips the rows.
  GLint format = 0, type = 0;
  gl_.GetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
  gl_.GetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
  if (format == GL_BGRA && type == GL_UNSIGNED_BYTE) read_format_ = GL_BGRA;
  GLint vp[4] = {0, 0, 0, 0};  // a context's first viewport is its surface
  gl_.GetIntegerv(GL_VIEWPORT, vp);
  fb_height_ = vp[3];
}

Renderer::~Renderer() {
  for (auto& [k, p] : programs_) gl_.DeleteProgram(p.id);
  materials_.destroy(gl_), edges_.destroy(gl_), pixels_.destroy(gl_), stipple_.destroy(gl_);
  gl_.DeleteBuffers(1, &tfb_);
  gl_.DeleteVertexArrays(1, &vao_);
}

std::vector<const ProgramInfo*> Renderer::programs() const {
  std::vector<const Program*> ps;
  for (const auto& [k, p] : programs_) ps.push_back(&p);
  std::sort(ps.begin(), ps.end(), [](const Program* a, const Program* b) { return a->order < b->order; });
  std::vector<const ProgramInfo*> out;
  for (const Program* p : ps) out.push_back(&p->info);
  return out;
}

Renderer::Program& Renderer::program_for(const ProgramKey& k) {
  const uint64_t id = k.packed();
  if (auto it = programs_.find(id); it != programs_.end()) {
    ++stats_.cache_hits;
    return it->second;
  }
  ++stats_.compiles;
  Program p(k);
  p.order = programs_.size();
  p.info.key = k;
  p.info.sources = generate(k);
  p.info.uniforms = uniforms(k, nullptr);
  const GLuint vs = compile_shader(gl_, GL_VERTEX_SHADER, p.info.sources.vertex, "a generated shader");
  const GLuint fs = compile_shader(gl_, GL_FRAGMENT_SHADER, p.info.sources.fragment, "a generated shader");
  p.id = gl_.CreateProgram();
  gl_.AttachShader(p.id, vs);
  gl_.AttachShader(p.id, fs);
  if (!p.info.sources.geometry.empty()) {
    const GLuint gs = compile_shader(gl_, GL_GEOMETRY_SHADER, p.info.sources.geometry, "a generated shader");
    gl_.AttachShader(p.id, gs), gl_.DeleteShader(gs);
  }
  std::vector<const char*> names;
  for (const std::string& n : p.info.sources.feedback) names.push_back(n.c_str());
  gl_.TransformFeedbackVaryings(p.id, GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
  gl_.DeleteShader(vs);  // kept by the program until it is deleted
  gl_.DeleteShader(fs);
  link_program(gl_, p.id, "a generated program");
  p.format = format_of(gl_, p.id);
  for (const Uniform& u : p.info.uniforms) p.locations.push_back(gl_.GetUniformLocation(p.id, u.name.c_str()));
  p.uploaded.assign(p.info.uniforms.size(), false);
  return programs_.emplace(id, std::move(p)).first->second;
}

// Each uniform is sent when its value differs from the one the program holds.
void Renderer::upload(Program& p, const state::SinkState& s) {
  const std::vector<Uniform>& now = p.cache.values(s);
  for (size_t i = 0; i < now.size(); ++i) {
    Uniform& held = p.info.uniforms[i];
    if (p.uploaded[i] && std::memcmp(held.value.data(), now[i].value.data(), sizeof(float) * size_t(now[i].size)) == 0)
      continue;
    held.value = now[i].value;
    p.uploaded[i] = true;
    ++stats_.uniform_uploads;
    const GLint at = p.locations[i];
    const float* v = held.value.data();
    switch (held.size) {
      case 1: gl_.Uniform1fv(at, 1, v); break;
      case 3: gl_.Uniform3fv(at, 1, v); break;
      case 4: gl_.Uniform4fv(at, 1, v); break;
      case 9: gl_.UniformMatrix3fv(at, 1, GL_FALSE, v); break;
      default: gl_.UniformMatrix4fv(at, 1, GL_FALSE, v); break;
    }
  }
}

void Renderer::apply_fragment(const state::SinkState& s) {
  const state::FragmentState& f = *s.fragment;
  gl_.ColorMask(f.color_mask[0], f.color_mask[1], f.color_mask[2], f.color_mask[3]);
  gl_.DepthMask(f.depth_mask);
  if (f.scissor_test) {
    gl_.Enable(GL_SCISSOR_TEST);
    const glm::ivec4 b = f.scissor_box;
    if (b.z >= 0) gl_.Scissor(b.x, b.y, b.z, b.w);
    else gl_.Disable(GL_SCISSOR_TEST);  // never set: the whole window
  } else {
    gl_.Disable(GL_SCISSOR_TEST);
  }
}

void Renderer::report(const std::string& what) {
  if (unsupported_.insert(what).second)
    std::fprintf(stderr, "ffcompat: the GLSL backend does not draw %s; drawn without it\n", what.c_str());
}

void Renderer::apply(const state::SinkState& s) {
  for (const std::string& what : s.unsupported) report(what);
  gl_.Viewport(s.viewport.x, s.viewport.y, s.viewport.z, s.viewport.w);
  gl_.DepthRange(s.depth_range.x, s.depth_range.y);
  s.depth_test ? gl_.Enable(GL_DEPTH_TEST) : gl_.Disable(GL_DEPTH_TEST);
  gl_.DepthFunc(s.depth_func);
  s.cull ? gl_.Enable(GL_CULL_FACE) : gl_.Disable(GL_CULL_FACE);
  gl_.CullFace(s.cull_mode);
  gl_.FrontFace(s.front_face);
  gl_.PointSize(s.point_size);
  gl_.LineWidth(s.line_width);
  apply_fragment(s);
  apply_raster_features(gl_, s);
  const state::FragmentState& f = *s.fragment;
  if (f.blend) {
    gl_.Enable(GL_BLEND);
    gl_.BlendFuncSeparate(f.src_rgb, f.dst_rgb, f.src_alpha, f.dst_alpha);
    gl_.BlendEquationSeparate(f.eq_rgb, f.eq_alpha);
    gl_.BlendColor(f.blend_color.r, f.blend_color.g, f.blend_color.b, f.blend_color.a);
  } else {
    gl_.Disable(GL_BLEND);
  }
}

void Renderer::draw(const state::SinkState& s, GLenum mode, const state::SinkVertex* v, size_t count,
                    const uint32_t* indices, size_t index_count) {
  if (needs_polygon_passes(s, mode) && polygon_passes(s, mode, [&](const state::SinkState& pass) { draw(pass, mode, v, count, indices, index_count); }))
    return;
  const size_t n = indices ? index_count : count;
  SplitRule rule;
  rule.flat = s.flat, rule.from_elements = indices != nullptr, rule.pipeline = capture_ || s.pass_mode;
  if (mode == GL_QUADS || mode == GL_QUAD_STRIP) rule.any_outside = any_outside(s, v, count, indices, n);
  const DrawList list = listed(mode, indices, n, count, rule, list_, edges_.flags(s));
  if (list.count == 0) return;
  ++stats_.draws;
  ProgramKey key = ProgramKey::of(s, phong_);
  // Points as whole-pixel squares (points.h), except where transform feedback records the vertex stage.
  key.points = mode == GL_POINTS && !capture_ && !(key.phong && key.lit);
  Program& p = program_for(key);
  ++p.info.draws;
  gl_.UseProgram(p.id);
  upload(p, s);
  apply(s);
  // The square of a point is a strip of triangles: neither culled nor offset as polygons are.
  if (key.points) gl_.Disable(GL_CULL_FACE), gl_.Disable(GL_POLYGON_OFFSET_FILL);
  vertices_.upload(p.format, v, count);
  if (list.indices) elements_.write(list.indices, list.count * sizeof(uint32_t));
  materials_.stream(gl_, s.vertex_materials);
  edges_.stream(gl_, s);
  if (capture_) return capture_draw(s, list, p);
  if (s.fragment->line_stipple && (list.mode == GL_LINES || p.info.key.unfilled == GL_LINE) && stippled(s, mode, list, p)) return;
  submit(list);
}

void Renderer::submit(const DrawList& list) {
  if (list.indices)
    gl_.DrawRangeElements(list.mode, 0, GLuint(list.vertices - 1), GLsizei(list.count), GL_UNSIGNED_INT, nullptr);
  else gl_.DrawArrays(list.mode, 0, GLsizei(list.count));
}

// Transform feedback writes each listed vertex's gl_Position and colours, in list order.
void Renderer::capture_draw(const state::SinkState& s, const DrawList& list, const Program& p) {
  captured_.push_back(record(s, list, p));
}

CapturedDraw Renderer::record(const state::SinkState& s, const DrawList& list, const Program& p) {
  const GLenum list_mode = list.mode;
  const size_t n = list.count;
  const size_t floats = 4 * p.info.sources.feedback.size();
  gl_.BindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, tfb_);
  gl_.BufferData(GL_TRANSFORM_FEEDBACK_BUFFER, GLsizeiptr(n * floats * sizeof(float)), nullptr, GL_STREAM_READ);
  gl_.BindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, tfb_);
  gl_.BeginTransformFeedback(list_mode);
  submit(list);
  gl_.EndTransformFeedback();
  std::vector<float> out(n * floats);
  gl_.GetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, GLsizeiptr(out.size() * sizeof(float)), out.data());
  CapturedDraw d;
  d.mode = list_mode, d.flat = s.flat, d.cull = s.cull, d.cull_mode = s.cull_mode, d.front_face = s.front_face;
  d.viewport = s.viewport, d.depth_range = s.depth_range;
  for (size_t i = 0; i < n; ++i) {
    const float* r = &out[i * floats];
    CapturedVertex cv;
    std::memcpy(&cv.clip, r, 4 * sizeof(float));
    std::memcpy(&cv.front, r + 4, 4 * sizeof(float));
    cv.back = cv.front;
    if (floats >= 12) std::memcpy(&cv.back, r + 8, 4 * sizeof(float));
    d.vertices.push_back(cv);
  }
  return d;
}

void Renderer::clear(const state::SinkState& s, GLbitfield mask) {
  apply_fragment(s);
  gl_.ClearColor(s.clear_color.r, s.clear_color.g, s.clear_color.b, s.clear_color.a);
  gl_.ClearDepth(s.clear_depth);
  gl_.Clear(mask & (GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
}

void Renderer::read_back(uint8_t* rgba, int width, int height) {
  const size_t row = size_t(width) * 4;
  read_rows_.resize(row * size_t(height));  // kept: no allocation after the first frame
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_.ReadPixels(0, 0, width, height, read_format_, GL_UNSIGNED_BYTE, read_rows_.data());
  for (int y = 0; y < height; ++y) {  // GL's bottom row first, to the top row first
    const uint8_t* from = read_rows_.data() + size_t(height - 1 - y) * row;
    uint8_t* to = rgba + size_t(y) * row;
    if (read_format_ == GL_RGBA) {
      std::memcpy(to, from, row);
      continue;
    }
    for (size_t x = 0; x < row; x += 4) {  // BGRA to RGBA: bytes 0 and 2 swapped, a word at a time
      uint32_t v;
      std::memcpy(&v, from + x, 4);
      v = (v & 0xFF00FF00u) | (v & 0xFFu) << 16 | (v >> 16 & 0xFFu);
      std::memcpy(to + x, &v, 4);
    }
  }
}

}  // namespace ffc::glsl
