// The vertex stage: each vertex fetched, transformed, lit and its colours clamped, before
// primitive assembly (GL 2.1 sections 2.11 to 2.14).
#include <algorithm>
#include <cmath>

#include "state/client_arrays.h"
#include "state/context.h"
#include "state/float_matrix.h"

namespace ffc::state {

void Context::update_vertex_constants() {
  if (!lighting_) return;
  if (constants_dirty_) prepare_lighting();
  // Normals transform by the inverse transpose of the modelview's upper 3x3 (the float matrix in
  // the float context: the one positions and lights use).
  const glm::dmat4 mv = modelview();
  if (mv != normal_matrix_of_) {  // the inverse is per modelview, not per vertex
    normal_matrix_of_ = mv;
    // A singular modelview has no inverse: the transformed normal is undefined and the inverse's
    // entries arbitrary (2.11.3). Mesa (m_matrix.c) takes the identity; ours too, not infinities
    // or rounding noise. Singular: |det| within 1e-14 of its largest value for the rows' (or the
    // columns') lengths (Hadamard), a test that does not depend on scale (1e-30 I inverts).
    const glm::dmat3 m3(mv);
    double rows = 1, cols = 1;
    for (int i = 0; i < 3; ++i)
      cols *= glm::length(m3[i]), rows *= glm::length(glm::dvec3(m3[0][i], m3[1][i], m3[2][i]));
    const bool singular = !(std::abs(glm::determinant(m3)) > 1e-14 * std::min(rows, cols));
    normal_matrix_ = singular ? glm::dmat3(1) : glm::inverse(m3);
    // A projective modelview (bottom row not 0, 0, 0, 1): Mesa transforms normals by the upper 3x3
    // of the 4x4 inverse, where GL 2.1 inverts the upper 3x3 (the two agree for every affine matrix).
    if (!spec_ && (mv[0][3] != 0 || mv[1][3] != 0 || mv[2][3] != 0 || mv[3][3] != 1))
      normal_matrix_ = glm::dmat3(glm::inverse(mv));
    for (int k = 0; k < 9; ++k)
      if (!std::isfinite(normal_matrix_[k / 3][k % 3])) normal_matrix_ = glm::dmat3(1);
  }
}

raster::Vertex Context::vertex(const glm::dvec4& obj, const glm::dvec3& normal, const glm::dvec4& color,
                               bool* zero_normal) const {
  raster::Vertex v;
  glm::dvec4 eye;
  if (precision_ == Precision::Float) {  // positions rounded as Mesa rounds them
    const glm::vec4 of(obj);
    v.clip = fmat::transform(mvp_f_, of);
    eye = fmat::transform(modelview_f_.back().values(), of);
  } else {
    eye = modelview_.back() * obj;
    v.clip = projection_.back() * eye;
  }
  // Mesa's fixed-function vertex program (ffvertex_prog.c build_fog): |eye z| for
  // GL_FRAGMENT_DEPTH (its default distance mode, eye plane absolute); for GL_FOG_COORD the
  // current fog coordinate, which stays 0 here (no glFogCoord).
  if (fog_ && fog_coord_src_ == GL_FRAGMENT_DEPTH) v.fog = std::abs(eye.z);
  // GL 2.1 lights the vertex at its eye-space point (x/w, y/w, z/w); Mesa's fixed-function program
  // takes x, y, z as they are (docs/deviations.md). The lighting divides unless w is 1.
  if (!spec_) eye.w = 1;
  if (!lighting_) {
    // Clamped to [0,1]; a NaN (unspecified input, 2.1.1) to 1 as in Mesa, so none reaches the rasterizer.
    for (int k = 0; k < 4; ++k) v.front[k] = !(color[k] < 1) ? 1.0 : color[k] > 0 ? color[k] : 0.0;
    v.back = v.front;
    v.front_sec = v.back_sec = glm::dvec4(0);
    return v;
  }
  const glm::dmat3& inv = normal_matrix_;
  glm::dvec3 n = normal * inv;  // row vector times M^-1
  if (normalize_) {
    const double len = glm::length(n);
    if (len > 0) n /= len;  // a zero normal stays zero: ambient and emission only
    else *zero_normal = true;
  } else if (rescale_normal_) {
    const double f = glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2]));  // M^-1's third row
    if (f > 0) n /= f;
  }
  if (precision_ == Precision::Float) {
    const glm::vec4 pf(eye), cf(color);
    const glm::vec3 nf(n);
    lighting::Lit<float> lit;
    kernel_f_(prepared_f_, &pf, &nf, &cf, 1, &lit);
    v.front = lit.primary[0], v.back = lit.primary[1];
    v.front_sec = lit.secondary[0], v.back_sec = lit.secondary[1];
  } else {
    lighting::Lit<double> lit;
    kernel_d_(prepared_d_, &eye, &n, &color, 1, &lit);
    v.front = lit.primary[0], v.back = lit.primary[1];
    v.front_sec = lit.secondary[0], v.back_sec = lit.secondary[1];
  }
  return v;
}

void Context::process_vertex(const glm::dvec4& obj) {
  if (deferred_) {  // lit with the others at glEnd; only what the lighting reads is kept
    deferred_pos_.push_back(glm::vec4(obj));  // the float path rounds positions so anyway
    if (lighting_) deferred_normal_.push_back(normal_);
    if (!lighting_ || color_material_) deferred_color_.push_back(color_);
    return;
  }
  update_vertex_constants();
  bool zero_normal = false;
  verts_.push_back(vertex(obj, normal_, color_, &zero_normal));
  if (zero_normal) deviations_.insert(kZeroNormal);
  const bool finite = std::isfinite(obj.x) && std::isfinite(obj.y) && std::isfinite(obj.z) && std::isfinite(obj.w) &&
                      (!lighting_ || (std::isfinite(normal_.x) && std::isfinite(normal_.y) && std::isfinite(normal_.z)));
  if (!finite) deviations_.insert(kNonfiniteVertex);
}

// A large glDrawArrays / glDrawElements range: the vertices are independent, so both cores take
// half each.
void Context::fetch_range(GLint first, GLint count) {
  update_vertex_constants();
  verts_.resize(size_t(count));
  auto attribute = [](const ClientArray& a, GLint i, int n, Fixed normalized, glm::dvec4 v) {
    const uint8_t* p = element(a, i);
    for (int k = 0; k < n; ++k) v[k] = read_component(p, a.type, k, normalized);
    return v;
  };
  auto work = [&](GLint lo, GLint hi, bool* zero) {
    for (GLint i = lo; i < hi; ++i) {
      const glm::dvec3 n = normal_array_.enabled ? glm::dvec3(attribute(normal_array_, i, 3, draw_fixed(), glm::dvec4(0)))
                                                 : normal_;
      const glm::dvec4 c = color_array_.enabled ? attribute(color_array_, i, color_array_.size, draw_fixed(), glm::dvec4(1))
                                                : color_;
      verts_[size_t(i - first)] = vertex(attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1)), n, c, zero);
    }
  };
  raster::Workers& w = workers();
  bool zero[raster::Workers::kMax] = {};  // per share: a zero normal met
  w.run([&](int share) {
    bool z = false;
    work(first + GLint(int64_t(count) * share / w.size()), first + GLint(int64_t(count) * (share + 1) / w.size()), &z);
    zero[share] = z;
  });
  if (std::find(zero, zero + w.size(), true) != zero + w.size()) deviations_.insert(kZeroNormal);
}
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

}  // namespace ffc::state
