// The triangle-list path: GL_TRIANGLES from glDrawArrays, glDrawElements and immediate mode
// (Context::End lends the kept vertices as client arrays) while rendering in float. Vertices are
// lit in batches on every thread into compact records, and the rasterizer reads them in place
// (raster/triangle_list.h). The same pixels as the general path, which takes every other
// primitive, feedback and the double pipeline.
#include <algorithm>

#include "raster/isa.h"
#if FFCOMPAT_X86
#include <immintrin.h>

// GCC 12's AVX-512 headers start some results from _mm512_undefined_*, which -Wuninitialized
// reports wherever they are inlined.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "state/client_arrays.h"
#include "state/context.h"
#include "state/float_matrix.h"

namespace ffc::state {

namespace {

constexpr int kBatch = 64;                 // vertices per call of the lighting kernel
constexpr GLint kParallelShading = 2048;  // below this one thread lights them all

// Components [0, n) of an element of T, the others from `v`, a fixed-size copy each: straight to
// registers (a copy of a run-time size is a library call, and one copy of several components
// to the stack, read back one by one, stalls on store forwarding).
template <typename T>
glm::dvec4 direct(const uint8_t* p, int n, glm::dvec4 v) {
  auto at = [p](int k) {
    T t;
    std::memcpy(&t, p + size_t(k) * sizeof(T), sizeof(T));
    return double(t);
  };
  switch (n) {
    case 4: v.w = at(3); [[fallthrough]];
    case 3: v.z = at(2); [[fallthrough]];
    case 2: v.y = at(1); [[fallthrough]];
    default: v.x = at(0);
  }
  return v;
}

// Components [0, n) of element i, the others from `v`; float and double arrays (immediate mode's
// kept vertices among them) read directly.
inline glm::dvec4 attribute(const ClientArray& a, GLint i, int n, Fixed normalized, glm::dvec4 v) {
  const uint8_t* p = element(a, i);
  if (a.type == GL_FLOAT) return direct<float>(p, n, v);
  if (a.type == GL_DOUBLE) return direct<double>(p, n, v);
  for (int k = 0; k < n; ++k) v[k] = read_component(p, a.type, k, normalized);
  return v;
}

// Object-space normals to eye space: a row vector times M^-1 (the inverse transpose), then
// normalized (a zero normal stays zero, ambient and emission only, and is reported) or rescaled
// (rescale > 0), in double as glm computes them, then to float.
void eye_normals(const glm::dvec3* raw, int m, const glm::dmat3& inv, bool normalize, double rescale,
                        glm::vec3* out, bool* zero_normal) {
  for (int j = 0; j < m; ++j) {
    glm::dvec3 n = raw[j] * inv;
    if (normalize) {
      const double len = glm::length(n);
      if (len > 0) n /= len;
      else *zero_normal = true;
    } else if (rescale > 0) {
      n /= rescale;
    }
    out[j] = glm::vec3(n);
  }
}

}  // namespace

// Sixteen at a time with AVX-512 where the CPU has it, else four at a time in SSE2 (which
// compares signed: the top bit is flipped first); without x86 intrinsics, one at a time.
#if FFCOMPAT_X86
namespace {
__attribute__((target("avx512f"))) void index_range_wide(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) {
  __m512i vlo = _mm512_set1_epi32(-1), vhi = _mm512_setzero_si512();
  size_t i = 0;
  for (; i + 16 <= n; i += 16) {
    const __m512i v = _mm512_loadu_si512(u + i);
    vlo = _mm512_min_epu32(vlo, v), vhi = _mm512_max_epu32(vhi, v);
  }
  lo = _mm512_reduce_min_epu32(vlo), hi = _mm512_reduce_max_epu32(vhi);
  for (; i < n; ++i) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
}
}  // namespace

void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) {
  static const bool wide = __builtin_cpu_supports("avx512f");
  if (wide) return index_range_wide(u, n, lo, hi);
  const __m128i flip = _mm_set1_epi32(INT32_MIN);
  __m128i vlo = _mm_set1_epi32(INT32_MAX), vhi = _mm_set1_epi32(INT32_MIN);
  size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(u + i)), flip);
    const __m128i less = _mm_cmplt_epi32(v, vlo), more = _mm_cmpgt_epi32(v, vhi);
    vlo = _mm_or_si128(_mm_and_si128(less, v), _mm_andnot_si128(less, vlo));
    vhi = _mm_or_si128(_mm_and_si128(more, v), _mm_andnot_si128(more, vhi));
  }
  alignas(16) uint32_t l[4], h[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(l), _mm_xor_si128(vlo, flip));
  _mm_store_si128(reinterpret_cast<__m128i*>(h), _mm_xor_si128(vhi, flip));
  lo = UINT32_MAX, hi = 0;
  for (int k = 0; k < 4 && i >= 4; ++k) lo = std::min(lo, l[k]), hi = std::max(hi, h[k]);
  for (; i < n; ++i) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
}
#else
void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) {
  lo = UINT32_MAX, hi = 0;
  for (size_t i = 0; i < n; ++i) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
}
#endif

bool Context::shaded_path(GLenum mode) const {
  // Fog and polygon offset are applied by the general path only (raster/fragment_ops.cpp): the
  // triangle list's kernels have neither a fog coordinate nor a depth offset.
  return triangle_lists_ && mode == GL_TRIANGLES && render_mode_ == GL_RENDER && precision_ == Precision::Float &&
         !fog_ && !offset_fill_;
}

raster::Workers& Context::workers() {
  if (!workers_) workers_ = std::make_unique<raster::Workers>(threads_);
  return *workers_;
}

raster::State Context::raster_state() const {
  raster::State rs;
  rs.viewport = viewport_;
  rs.depth_range = depth_range_;
  rs.flat = shade_model_ == GL_FLAT;
  rs.depth_test = depth_test_;
  rs.depth_func = depth_func_;
  rs.cull = cull_face_;
  rs.cull_mode = cull_mode_;
  rs.front_face = front_face_;
  rs.two_side = lighting_ && model_.two_side;
  rs.add_secondary = lighting_ && model_.separate_specular;
  rs.float_window = precision_ == Precision::Float;
  rs.fb_height = fb_.height;
  rs.line_width = line_width_;
  rs.point_size = point_size_;
  fog_raster_state(rs);
  return rs;
}

void Context::shade_range(GLint first, GLint count) {
  update_vertex_constants();
  const raster::State rs = raster_state();
  raster::ShadedVertices& out = shaded_;
  out.resize(size_t(count), rs.two_side, rs.add_secondary);
  const glm::mat4 modelview = modelview_f_.back().values();
  const glm::dmat3 inv = normal_matrix_;
  const double rescale = glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2]));  // M^-1's third row

  auto work = [&](GLint lo, GLint hi, bool* zero_normal) {
    glm::vec4 eye[kBatch], color[kBatch];
    glm::vec3 normal[kBatch];
    glm::dvec3 raw[kBatch];
    lighting::Lit<float> lit[kBatch];
    for (GLint b = lo; b < hi; b += kBatch) {
      const int m = int(std::min<GLint>(kBatch, hi - b));
      for (int j = 0; j < m; ++j) {
        const GLint i = b + j;
        // Positions rounded as Mesa rounds them (float_matrix.h).
        const glm::vec4 obj(attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1)));
        const size_t o = size_t(i - first);
        out.clip[o] = fmat::transform(mvp_f_, obj);
        const glm::dvec4 c = color_array_.enabled ? attribute(color_array_, i, color_array_.size, draw_fixed(), glm::dvec4(1))
                                                  : color_;
        if (!lighting_) {
          // Clamped to [0,1]; a NaN (unspecified input, 2.1.1) to 1 as in Mesa.
          glm::vec4& f = out.hot[o].color;
          for (int k = 0; k < 4; ++k) f[k] = float(!(c[k] < 1) ? 1.0 : c[k] > 0 ? c[k] : 0.0);
          continue;
        }
        eye[j] = fmat::transform(modelview, obj);
        if (!spec_) eye[j].w = 1;  // Mesa lights at x, y, z (Context::vertex)
        color[j] = glm::vec4(c);
        raw[j] = normal_array_.enabled ? glm::dvec3(attribute(normal_array_, i, 3, draw_fixed(), glm::dvec4(0))) : normal_;
      }
      if (lighting_) eye_normals(raw, m, inv, normalize_, rescale_normal_ ? rescale : 0.0, normal, zero_normal);
      raster::map_shaded(out, size_t(b - first), size_t(m), rs);
      if (!lighting_) continue;
      kernel_f_(prepared_f_, eye, normal, color, size_t(m), lit);
      for (int j = 0; j < m; ++j) {
        const size_t o = size_t(b + j - first);
        out.hot[o].color = lit[j].primary[0];
        if (!out.back.empty()) out.back[o] = lit[j].primary[1];
        if (!out.front_sec.empty()) out.front_sec[o] = lit[j].secondary[0];
        if (!out.back_sec.empty()) out.back_sec[o] = lit[j].secondary[1];
      }
    }
  };
  bool zero[8] = {};
  if (count < kParallelShading || threads_ == 1) {
    work(first, first + count, &zero[0]);
  } else {
    raster::Workers& w = workers();
    const int shares = std::min(4 * w.size(), 8);  // more than threads: a late thread's share is taken
    w.run([&](int s) { work(first + GLint(int64_t(count) * s / shares), first + GLint(int64_t(count) * (s + 1) / shares), &zero[s]); },
          shares);
  }
  if (std::find(std::begin(zero), std::end(zero), true) != std::end(zero)) deviations_.insert(kZeroNormal);
}

void Context::read_top_down(uint8_t* out) {
  flush_clear();
  const size_t row = size_t(fb_.width) * 4;
  raster::Workers& w = workers();
  const int shares = 4 * w.size();
  w.run([&](int share) {
    for (int y = fb_.height * share / shares; y < fb_.height * (share + 1) / shares; ++y)  // GL's row 0 is the bottom one
      std::memcpy(out + size_t(y) * row, &fb_.color[size_t(fb_.height - 1 - y) * row], row);
  }, shares);
}

void Context::draw_shaded(const uint32_t* indices, size_t triangles) {
  raster::draw_triangle_list(fb_, raster_state(), shaded_, indices, triangles, workers(), bins_, pending_clear_);
  pending_clear_ = {};
}

}  // namespace ffc::state
