// Clipping, triangle and line setup, flat and smooth interpolation, depth: from lit vertices in
// clip space to pixels.
#pragma once
#include <GL/gl.h>

#include <array>
#include <atomic>
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace ffc::pool {
class Workers;  // pool/workers.h: the threads a draw is shared out on
}  // namespace ffc::pool

namespace ffc::raster {

// A vertex after the vertex stage: clip-space position and its lit colours.
struct Vertex {
  glm::dvec4 clip;
  glm::dvec4 front, back;            // primary colours, clamped
  glm::dvec4 front_sec, back_sec;    // secondary (separate specular) colours
  double fog = 0;                    // fog coordinate (state/fog.cpp), interpolated like a colour
};

// Threads share the rows out in interleaved bands of this many: a triangle across two bands is
// set up by both threads, and at 64 rows few are (measured on the icosphere: 16 rows cost 8%).
constexpr int kBandRows = 64;

// GL's window: row 0 at the bottom.
struct Framebuffer {
  int width = 0, height = 0;
  std::vector<uint8_t> color;   // RGBA8
  std::vector<uint32_t> depth;  // 24-bit
  // Counts the draws and clears that wrote the buffer (not glBitmap's fragments): glBitmap tells
  // by it whether anything else drew since the last bitmap (state/bitmap.cpp).
  uint64_t writes = 0;
  // A new buffer's contents are undefined in GL; llvmpipe's start at 0, colour and depth alike, and
  // so do ours (a program that depth-tests without clearing then draws what it draws on Mesa).
  Framebuffer(int w, int h) : width(w), height(h), color(size_t(w) * h * 4, 0), depth(size_t(w) * h, 0) {}
};

// What a context's draws count, read by whoever asked for the draw (the stress runner, the
// deviations a draw names). One per context, not per process: two contexts drawing at once on two
// threads must not see each other's counts. Atomic: a draw's worker threads add to it together.
struct Counters {
  std::atomic<uint64_t> nonfinite_fragments{0};  // written from a non-finite colour (before the clamp)
  std::atomic<uint64_t> clipped_slivers{0};      // smooth slivers of clipped fans set up (sliver())
};

struct State {
  glm::ivec4 viewport;
  glm::dvec2 depth_range{0, 1};
  bool flat = false;
  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  bool cull = false;
  GLenum cull_mode = GL_BACK, front_face = GL_CCW;
  bool two_side = false;      // lighting on with two-sided model: back faces take the back colour
  bool add_secondary = false; // separate specular: colour sum after interpolation
  // Window positions as llvmpipe computes them: float, y flipped to the framebuffer's rows
  // (fb_height - y) with fused multiply-adds, then snapped there. Off: exact double maths.
  bool float_window = false;
  int fb_height = 0;
  float line_width = 1, point_size = 1;  // glLineWidth, glPointSize
  // GL_FOG: each fragment's colour blended towards fog_color by a factor from its interpolated
  // fog coordinate (apply_fog). fog_params are Mesa's STATE_FOG_PARAMS_OPTIMIZED.
  bool fog = false;
  GLenum fog_mode = GL_EXP;
  float fog_params[4] = {0, 0, 0, 0};
  float fog_color[3] = {0, 0, 0};
  // GL_POLYGON_OFFSET_FILL: filled triangles' depth moved by factor * max slope + units' step
  // (setup, Triangle::offset).
  bool offset_fill = false;
  float offset_factor = 0, offset_units = 0;
  // The per-fragment operations of GL 2.1 chapter 4.1 after coverage, in their order: scissor,
  // alpha test, depth (written only under depth_write), blending, colour mask (fragment.h).
  struct Ops {
    bool scissor = false;
    int scissor_x0 = 0, scissor_y0 = 0, scissor_x1 = 0, scissor_y1 = 0;  // [x0, x1) x [y0, y1), GL rows
    bool alpha_test = false;
    GLenum alpha_func = GL_ALWAYS;
    uint8_t alpha_ref = 0;  // the reference in 8 bits: llvmpipe compares the buffer's unorm8 values
    bool depth_write = true;
    bool blend = false;
    GLenum src_rgb = GL_ONE, dst_rgb = GL_ZERO, src_alpha = GL_ONE, dst_alpha = GL_ZERO;
    GLenum eq_rgb = GL_FUNC_ADD, eq_alpha = GL_FUNC_ADD;
    uint8_t blend_color[4] = {0, 0, 0, 0};
    unsigned color_mask = 0xF;  // bit k: channel k (r, g, b, a) written
    bool any() const { return scissor || alpha_test || !depth_write || blend || color_mask != 0xF; }
  } ops;
  // GL_LINE_STIPPLE (GL 2.1 section 3.4.2): lines cut into the pattern's runs (draw_line), the
  // pattern's counter kept by the context across a strip's segments (reset_stipple).
  bool line_stipple = false;
  int stipple_factor = 1;
  uint16_t stipple_pattern = 0xFFFF;
  int* stipple_counter = nullptr;
  // Where this draw's counts go (the context's); none: not counted.
  Counters* counters = nullptr;
  // Fog, polygon offset or any of ops: triangles take the scalar row loop
  // (row_loop.h rasterize_fragment_ops).
  bool fragment_ops() const { return fog || offset_fill || ops.any(); }
};

// A vector of at most N elements kept in place: clipping makes at most nine vertices of a
// triangle, and the pipeline allocates nothing per primitive.
template <typename T, size_t N>
class Fixed {
 public:
  Fixed() = default;
  Fixed(std::initializer_list<T> l) {
    for (const T& v : l) push_back(v);
  }
  void push_back(const T& v) { data_[n_++] = v; }  // the callers stay within N
  void clear() { n_ = 0; }
  size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  const T* begin() const { return data_.data(); }
  const T* end() const { return data_.data() + n_; }
  T* begin() { return data_.data(); }
  T* end() { return data_.data() + n_; }

 private:
  std::array<T, N> data_{};
  size_t n_ = 0;
};

// A clipped primitive in window coordinates, as feedback reports it.
struct WindowVertex {
  glm::dvec3 pos;    // x, y, z in window coordinates
  glm::dvec4 color;  // the colour chosen for the facing
  double inv_w;      // 1 / clip w, for perspective-correct interpolation
  float y_down = 0;  // y counted down from the framebuffer's top, as llvmpipe has it (depth_plane)
  glm::dvec4 sec;
  bool snapped = false;  // sx, sy hold the position in 1/256 pixel (pixel centres at +128)
  int64_t sx = 0, sy = 0;
  // Window x in float, what llvmpipe's point and line setup reads with y_down (the float path's
  // values; the double path's rounded).
  float fx = 0;
  double fog = 0;  // the fog coordinate
};

// How llvmpipe's multiply-adds round where soft copies them (the window mapping, a fragment's
// depth): its shaders use llvm.fmuladd, which LLVM fuses (one rounding) only on a CPU with FMA;
// on an x86 CPU without (or under GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 and below) they are a product
// and a sum, and ties between triangles land elsewhere (docs/deviations.md row 74). Fused by
// default; FFCOMPAT_LLVMPIPE_FMA=0 (read at the first context) or set_llvmpipe_fma(false) for the
// other. Process-wide, as Mesa's choice is; the lab sets it to the Mesa it runs beside.
namespace detail {
extern bool g_llvmpipe_fma;
}
inline bool llvmpipe_fma() { return detail::g_llvmpipe_fma; }
inline void set_llvmpipe_fma(bool fused) { detail::g_llvmpipe_fma = fused; }
// Applies FFCOMPAT_LLVMPIPE_FMA (0 or 1) once per process; throws std::invalid_argument for
// another value. Whether the variable was set.
bool configure_llvmpipe_fma_from_environment();
// a * b + c as llvmpipe rounds it (above): std::fma, or a product and a sum.
inline float llvmpipe_mul_add(float a, float b, float c) { return llvmpipe_fma() ? std::fma(a, b, c) : a * b + c; }

// The float path of map_to_window: window x, y (GL rows, up), z, and the snapped position.
struct FloatWindow {
  float x, y, z;
  float y_down;  // y counted from the top, before GL's flip: what llvmpipe's setup reads
  int64_t sx, sy;
};
FloatWindow map_float(const glm::vec4& clip, const State& s);
// A clip-space position in window coordinates (see State::float_window); colours left empty.
WindowVertex map_to_window(const glm::dvec4& clip, const State& s);
// Whether 1/w is a normal float, so that the divide and the 1/w planes of setup stay finite.
inline bool w_mappable(double w) { return std::abs(w) >= 0x1p-126 && std::abs(w) <= 0x1p126; }

// Bit i set: outside view-volume plane i (x>w, x<-w, y>w, y<-w, z>w, z<-w, w<=0). 0: inside.
// Bit 7: no window position exists: a NaN or infinite coordinate (which compares false against
// every plane), or a w whose 1/w is not a normal float. Never "inside". For float or double
// coordinates (the same answer for a float's value in either).
template <typename V>
unsigned outside_planes(const V& c) {
  return unsigned(c.x > c.w) | unsigned(c.x < -c.w) << 1 | unsigned(c.y > c.w) << 2 | unsigned(c.y < -c.w) << 3 |
         unsigned(c.z > c.w) << 4 | unsigned(c.z < -c.w) << 5 | unsigned(!(c.w > 0)) << 6 |
         unsigned(!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && w_mappable(c.w))) << 7;
}
bool back_facing_triangle(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, const State& s);
bool culled(bool back_facing, const State& s);

// Clips a triangle (or a line, count 2) against the view volume as Mesa's draw module does
// (draw_pipe_clip.c) and maps it to the window. Returns the clipped polygon with colours chosen by
// facing, in Mesa's order (its fan is (v[i], v[i+1], v[0])); empty when culled or clipped away.
// `provoking` is the vertex whose colours a flat primitive takes (it may be outside `prim`: a quad
// split in two keeps its 4th vertex); null keeps every vertex's own colours. Drawing flat, every
// vertex takes them; in `feedback` (non-null), only the vertices Mesa's clipper gives them (the
// polygon's first, a line's clip-made ends), for a primitive whose last vertex provokes.
// Feedback keeps Mesa's clipper's temporary vertices' colours from one primitive to the next
// (see clip_and_map_in), one set per context: front, back, front_sec, back_sec.
struct ClipTemps {
  static constexpr unsigned kSlots = 16;  // a triangle against six planes makes at most 13
  glm::vec4 c[kSlots][4]{};
  // Mesa allocates its temporaries uninitialised (malloc): what one holds before any clipped
  // primitive wrote it is undefined (zeros in a fresh process, garbage later). Set when feedback
  // reported such a slot's colours.
  bool written[kSlots]{};
  bool read_unwritten = false;
};
using WindowPolygon = Fixed<WindowVertex, 10>;
// A triangle of a clipped polygon's fan whose corners are collinear up to float rounding: its
// determinant in float (llvmpipe's setup arithmetic) below 1e-4 of its longest edge squared. Its
// snapped edges may still cover pixels, where an attribute plane through it is rounding noise:
// llvmpipe's planes (float, from 1 / area) and soft's (double, kept in float) disagree there, each
// leaving the vertices' range of colours (docs/deviations.md, row 63).
bool sliver(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c);
// Counts a smooth sliver set up for drawing in s.counters: the triangle-list path draws clipped
// triangles on the worker threads, and its caller names the deviation when its context's count
// moved during its draw.
void count_if_sliver(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, const State& s);
WindowPolygon clip_and_map(const Vertex* prim, size_t count, const State& s, const Vertex* provoking, bool is_line,
                           bool* back_facing = nullptr, ClipTemps* feedback = nullptr);

// A triangle set up for rasterization: edges snapped to 1/256 pixel (llvmpipe's 8 subpixel bits),
// attribute planes from the unsnapped positions, as llvmpipe builds them.
struct Triangle {
  int64_t x[3], y[3], area;  // snapped, counter-clockwise
  bool inclusive[3];         // edge i (from vertex i+1 to i+2) owns the pixels exactly on it
  int xmin, xmax, ymin, ymax;
  // Planes: value at pixel centre (X, Y) = p0 + px X + py Y: 1/w and colour / w (secondary colour
  // summed in) in float, as llvmpipe's. Depth: llvmpipe's own plane, {a0, dz/dx, dz/dy} at pixel
  // (X, row from the top) (setup.h depth_plane, pixel_rules.h depth_at).
  float z[3];
  float inv_w[3], c0[4], cx[4], cy[4];  // one after another: the box kernel reads them as 15 floats
  // Set only under State::fragment_ops(): the planes of fog coordinate / w and of 1/w (inv_w is
  // constant when flat), and the depth offset added to every fragment's z (polygon offset).
  float fog[3], fog_w[3];
  float offset;
};

// False when the triangle covers no pixel centre once snapped.
bool setup(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, const State& s, Triangle& out);
// The same with the colours apart from the positions (no copies of shared window vertices).
struct SetupVertex {
  const WindowVertex* w;
  const glm::dvec4* color;
  const glm::dvec4* sec;
};
bool setup(const std::array<SetupVertex, 3>& v, const State& s, Triangle& out);

// Rasterizes in order, rows shared out between the workers in interleaved bands: every pixel is
// written by one thread, in primitive order, so the picture does not depend on their number.
void draw_triangles(Framebuffer& fb, const std::vector<Triangle>* const* lists, size_t count, const State& s,
                    pool::Workers& workers);  // the `count` lists one after the other

// A new line (each of GL_LINES, the first of a strip) starts the stipple pattern again.
inline void reset_stipple(const State& s) {
  if (s.stipple_counter) *s.stipple_counter = 0;
}

// A line of width s.line_width and a point of size s.point_size as llvmpipe rasterizes them
// (lp_setup_line.c, lp_setup_point.c). Colours: the line's interpolated, the point's its own.
void draw_line(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const State& s);
void draw_point(Framebuffer& fb, const WindowVertex& v, const State& s);
// One fragment at pixel (x, y) (GL rows), window depth z, through the per-fragment operations of
// s (glBitmap's fragments); outside the framebuffer, none.
void draw_fragment(Framebuffer& fb, int x, int y, double z, const glm::dvec4& color, const State& s);
// glClear's request: which buffers, to what. A context keeps it until something reads or draws:
// the triangle-list path has each thread clear the bands it is about to draw.
struct ClearRequest {
  bool color = false, depth = false;
  glm::vec4 clear_color{0};
  double clear_depth = 1;
  bool pending() const { return color || depth; }
  uint32_t depth24() const { return uint32_t((clear_depth < 0 ? 0 : clear_depth > 1 ? 1 : clear_depth) * 0xFFFFFF + 0.5); }
};
void clear(Framebuffer& fb, const ClearRequest& c, pool::Workers& workers);
void clear_band(Framebuffer& fb, const ClearRequest& c, int band);  // rows [64 band, 64 band + 64)
// glClear under a colour or depth mask or the scissor test (GL 2.1 section 4.2.3): the masked
// channels and what lies outside the box are kept. Not banded: such clears are rare.
void clear_masked(Framebuffer& fb, const ClearRequest& c, const State::Ops& ops);

// Adds n fragments written from a non-finite colour (a NaN or an infinity in any channel before
// the clamp) to s.counters, for the stress suite: a fresh context, draw, read.
inline void count_nonfinite(const State& s, uint64_t n) {
  if (n && s.counters) s.counters->nonfinite_fragments.fetch_add(n, std::memory_order_relaxed);
}

// The fragment's colour after fog (State::fog), from its interpolated fog coordinate.
glm::dvec4 apply_fog(const glm::dvec4& c, float fog_coord, const State& s);

// GL's float-to-unorm8 conversion, rounding half to even as llvmpipe does.
uint8_t to_unorm8(double c);

}  // namespace ffc::raster
