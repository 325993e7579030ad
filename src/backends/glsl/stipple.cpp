#include "backends/glsl/stipple.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "backends/glsl/renderer.h"
#include "raster/raster.h"
#include "state/fragment.h"

namespace ffc::glsl {

namespace {

// A line's end in window terms, the values the draw module's stipple stage lerps.
struct WindowEnd {
  float x, y_down;     // window x; y counted down from the top (llvmpipe's rows)
  float z, inv_w;
  glm::vec4 color;
  glm::vec4 clip;      // the captured clip position (an uncut end is drawn from it)
  bool cut = false;    // made by the cut: drawn from the window position
};

// The point of a-b at t: every value linear in t, in float (draw_pipe_stipple.c's screen_interp,
// soft's raster `along`: the same expression, so the same roundings).
WindowEnd along(const WindowEnd& a, const WindowEnd& b, float t) {
  auto lerp = [t](float u, float v) { return u + t * (v - u); };
  WindowEnd w;
  w.x = lerp(a.x, b.x), w.y_down = lerp(a.y_down, b.y_down), w.z = lerp(a.z, b.z), w.inv_w = lerp(a.inv_w, b.inv_w);
  for (int k = 0; k < 4; ++k) w.color[k] = lerp(a.color[k], b.color[k]);
  w.cut = true;
  return w;
}

// A clip coordinate c with fma(c * (1 / w), scale, offset) == target in float, the core context's
// divide and viewport transform (raster::map_float's expression): first the closed form, then
// the nearest floats either side, since each of those steps rounds.
float solve(float target, float w, float scale, float offset) {
  const float fiw = 1.0f / w;
  const auto image = [&](float c) { return std::fma(c * fiw, scale, offset); };
  float best = scale != 0 ? float((double(target) - offset) / scale * w) : 0.0f;
  if (scale == 0 || image(best) == target) return best;
  float c = best;
  double miss = std::fabs(double(image(best)) - target);
  for (float dir : {INFINITY, -INFINITY}) {
    float probe = best;
    for (int k = 0; k < 8; ++k) {
      probe = std::nextafter(probe, dir);
      const double m = std::fabs(double(image(probe)) - target);
      if (m < miss) miss = m, c = probe;
      if (m == 0) return c;
    }
  }
  return c;
}

}  // namespace

void cut_stippled(const std::vector<CapturedVertex>& lines, const StippleRule& r, std::vector<StippleVertex>& out) {
  out.clear();
  raster::State rs;
  rs.viewport = r.viewport, rs.depth_range = r.depth_range, rs.fb_height = r.fb_height, rs.float_window = true;
  const glm::ivec4 vp = r.viewport;
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f;
  const float x_offset = float(vp[0]) + hw, y_offset = float(r.fb_height) - (float(vp[1]) + hh);
  const float dn = float(r.depth_range.x), df = float(r.depth_range.y);
  rs.flat = r.flat;
  // An end as Mesa's clipper leaves it (raster::clip_and_map, soft's own): an end inside the
  // view volume is the captured vertex, drawn from its clip position; one the clipper made is
  // drawn from its window position, like a cut point.
  auto end = [](const raster::WindowVertex& w, const CapturedVertex& v, bool kept) {
    WindowEnd e;
    e.x = w.fx, e.y_down = w.y_down, e.z = float(w.pos.z), e.inv_w = float(w.inv_w);
    e.color = glm::vec4(w.color), e.clip = v.clip, e.cut = !kept;
    return e;
  };
  const glm::vec4* provoking = nullptr;
  auto put = [&](const WindowEnd& e) {
    StippleVertex s;
    s.color = r.flat ? *provoking : e.color;
    if (!e.cut) {
      s.clip = e.clip;
    } else {
      const float w = 1.0f / e.inv_w;
      s.clip = {solve(e.x, w, hw, x_offset), solve(e.y_down, w, -hh, y_offset), solve(e.z, w, (df - dn) * 0.5f, (df + dn) * 0.5f), w};
    }
    out.push_back(s);
  };
  auto piece = [&](const WindowEnd& a, const WindowEnd& b) { put(a), put(b); };
  int counter = 0;
  for (size_t l = 0; l + 1 < lines.size(); l += 2) {
    if (r.restart_each) counter = 0;
    raster::Vertex ends[2];
    for (int k = 0; k < 2; ++k) {
      const CapturedVertex& v = lines[l + size_t(k)];
      ends[k].clip = glm::dvec4(v.clip), ends[k].front = ends[k].back = glm::dvec4(v.front);
    }
    const raster::WindowPolygon clipped = raster::clip_and_map(ends, 2, rs, &ends[1], true);
    if (clipped.size() != 2) continue;  // outside the view volume: no pixel, no pattern bit
    const WindowEnd a = end(clipped[0], lines[l], raster::outside_planes(lines[l].clip) == 0);
    const WindowEnd b = end(clipped[1], lines[l + 1], raster::outside_planes(lines[l + 1].clip) == 0);
    provoking = &lines[l + 1].front;
    // One pattern bit per pixel of the major axis (soft's raster::draw_line, the same steps).
    const float length = std::max(std::fabs(a.x - b.x), std::fabs(a.y_down - b.y_down));
    const int n = std::isfinite(length) ? int(std::ceil(length)) : 0;
    bool on = false;
    float start = 0;
    for (int i = 0; i < n; ++i, ++counter) {
      const bool bit = (r.pattern >> ((counter / r.factor) & 15)) & 1;
      if (bit == on) continue;
      if (on && start != float(i)) piece(start > 0 ? along(a, b, start / length) : a, along(a, b, float(i) / length));
      if (!on) start = float(i);
      on = bit;
    }
    if (on && start < length) piece(start > 0 ? along(a, b, start / length) : a, b);
  }
}

namespace {

const char* const kVertex[2] = {
    "#version 330 core\nlayout(location = 0) in vec4 a_clip;\nlayout(location = 1) in vec4 a_color;\n"
    "out vec4 v_color;\nvoid main() {\n  gl_Position = a_clip;\n  v_color = a_color;\n}\n",
    "#version 330 core\nlayout(location = 0) in vec4 a_clip;\nlayout(location = 1) in vec4 a_color;\n"
    "flat out vec4 v_color;\nvoid main() {\n  gl_Position = a_clip;\n  v_color = a_color;\n}\n"};
const char* const kFragment[2] = {
    "#version 330 core\nin vec4 v_color;\nout vec4 o_color;\nvoid main() {\n  o_color = v_color;\n}\n",
    "#version 330 core\nflat in vec4 v_color;\nout vec4 o_color;\nvoid main() {\n  o_color = v_color;\n}\n"};

// Both stages compiled and linked.
GLuint link(const CoreGl& gl, const char* vertex, const char* fragment) {
  const GLuint program = gl.CreateProgram();
  for (const auto& [type, src] : {std::pair<GLenum, const char*>{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}) {
    const GLuint stage = compile_shader(gl, type, src, "the line stipple program");
    gl.AttachShader(program, stage), gl.DeleteShader(stage);
  }
  link_program(gl, program, "the line stipple program");
  return program;
}

}  // namespace

void StippleLines::draw(const CoreGl& gl, const std::vector<StippleVertex>& lines, bool flat) {
  if (lines.empty()) return;
  GLuint& program = programs_[flat ? 1 : 0];
  if (!program) program = link(gl, kVertex[flat], kFragment[flat]);
  GLint vao = 0;
  gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao);
  if (!vao_) {
    gl.GenVertexArrays(1, &vao_), gl.GenBuffers(1, &buffer_);
    gl.BindVertexArray(vao_);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffer_);
    for (GLuint a = 0; a < 2; ++a) {
      gl.EnableVertexAttribArray(a);
      gl.VertexAttribPointer(a, 4, GL_FLOAT, GL_FALSE, sizeof(StippleVertex),
                             reinterpret_cast<const void*>(a * sizeof(glm::vec4)));
    }
  }
  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, buffer_);
  gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(lines.size() * sizeof(StippleVertex)), lines.data(), GL_STREAM_DRAW);
  gl.UseProgram(program);
  gl.DrawArrays(GL_LINES, 0, GLsizei(lines.size()));
  gl.BindVertexArray(GLuint(vao));
}

void StippleLines::destroy(const CoreGl& gl) {
  for (GLuint& p : programs_)
    if (p) gl.DeleteProgram(p), p = 0;
  if (vao_) gl.DeleteVertexArrays(1, &vao_), gl.DeleteBuffers(1, &buffer_), vao_ = 0;
}

}  // namespace ffc::glsl

namespace ffc::glsl {

// The draw's lines recorded (nothing rasterized), cut, and drawn as their pieces. What the cut
// does not handle yet is reported, and the draw goes on solid (false).
bool Renderer::stippled(const state::SinkState& s, GLenum mode, const DrawList& list, const Program& p) {
  const ProgramKey& k = p.info.key;
  // The pass-through program writes the recorded colour: the fragment stage's own terms are not in it.
  const char* lacking = k.unfilled == GL_LINE ? "line stipple of glPolygonMode GL_LINE polygons"
                        : k.fog               ? "line stipple with fog"
                        : k.alpha_test()      ? "line stipple with the alpha test"
                        : k.secondary()       ? "line stipple with a separate specular colour"
                        : k.phong             ? "line stipple lit per fragment"
                                              : nullptr;
  if (lacking) return report(lacking), false;
  gl_.Enable(GL_RASTERIZER_DISCARD);
  const CapturedDraw d = record(s, list, p);
  gl_.Disable(GL_RASTERIZER_DISCARD);
  StippleRule r;
  r.factor = std::clamp(int(s.fragment->stipple_factor), 1, 256), r.pattern = s.fragment->stipple_pattern;
  r.restart_each = mode == GL_LINES, r.flat = s.flat;
  r.viewport = s.viewport, r.depth_range = s.depth_range, r.fb_height = fb_height_;
  cut_stippled(d.vertices, r, pieces_);
  stipple_.draw(gl_, pieces_, s.flat);
  return true;
}

}  // namespace ffc::glsl
