// The vertex stage, written once (GL 2.1 sections 2.11 to 2.14; what Mesa's ffvertex_prog.c
// builds): fetch, transform to eye and clip space, the normal to eye space (normalized or
// rescaled), lighting through the kernel chosen by the lighting key, or the colour clamped.
// Every path runs it, in batches of up to kBatch vertices (float: on columns, a vector of vertices
// at a time, vertex_stage_simd.cpp and lighting/lighting_simd.cpp):
//   - glVertex, glArrayElement and small draws: process_vertex() keeps them, light_pending()
//     lights the batch into raster::Vertex; glRasterPos in spec mode: vertex(), one;
//   - a large draw on the general path: arrays_to_vertices(), into verts_, on the threads;
//   - the triangle-list path: arrays_to_list() and immediate_to_list() (immediate mode's
//     vertices kept for the list), into raster::ListVertices, on the threads.
// The clip codes are taken where the vertices are consumed: primitive.cpp's Assembly and
// raster::map_list_vertices.
#include "state/vertex_stage.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "lighting/lighting_simd.h"
#include "state/client_arrays.h"
#include "state/context.h"
#include "state/float_matrix.h"

namespace ffc::state {

namespace {

// An unlit colour channel clamped to [0, 1]. A NaN (an unspecified input, 2.1.1) per vertex (a
// glColor inside glBegin, a colour array) Mesa clamps to 1, drawn and fed back; but the current
// colour drawn for every vertex (no colour in the vertex format) llvmpipe draws as 0 in that
// channel, while Mesa's feedback reports 1. Measured in OSMesa programs (seed 223606 stream
// 974178983316683165, repro nan_colour_drawn_as_zero.txt): glColor4fv with a NaN alpha before
// glBegin, points, lines and triangles drawn with alpha 0, fed back with 1; the same NaN inside
// glBegin, or from an array, or sent after an earlier glBegin/glEnd's vertices and before this
// glBegin (still in Mesa's vbo format, stored with each vertex), drawn as 1. So a constant NaN
// becomes -0: drawn as 0, fed back as 1 (feedback.cpp); every other value clamps to +0 at most.
inline double clamp_unlit(double c, bool constant) {
  return c >= 1 ? 1.0 : c > 0 ? c : c <= 0 ? 0.0 : constant ? -0.0 : 1.0;
}
constexpr int kBatch = 64;                // vertices per call of the lighting kernel
constexpr GLint kParallelStage = 2048;   // below this one thread runs the stage for a whole draw
constexpr size_t kPendingBatch = 4 * kBatch;  // vertices kept before the stage runs on them
}  // namespace

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

// What the stage makes of up to N vertices, in the context's precision T (float: positions
// rounded as Mesa rounds them, float_matrix.h).
template <typename T, int N>
struct StageOut {
  glm::vec<4, T> clip[N];       // unless the caller names where the clip positions go
  double fog[N];                // |eye z|, where fog reads it
  lighting::Lit<T> lit[N];      // lighting on: both faces' colours
  glm::dvec4 unlit[N];          // lighting off: the colour clamped
  const lighting::Lit<T>& lit_at(int j) const { return lit[j]; }
};
// The float stage lights columns (lighting_simd.h): its colours stay in columns, padded.
// The kernel writes only the columns the key makes (SoaOut::keyed): `view` reads the back colours
// from the front columns without two-sided lighting, and the secondary ones from a column of
// zeros without a separate specular colour.
template <int N>
struct StageOut<float, N> {
  glm::vec4 clip[N];
  double fog[N];
  glm::dvec4 unlit[N];
  alignas(64) float lit[16][lighting::kSoaPad];  // [primary front, back, secondary front, back][r, g, b, a]
  const float* view[16];
  alignas(64) static constexpr float kZeros[lighting::kSoaPad] = {};
  glm::vec4 colour(int which, int j) const { return {view[4 * which][j], view[4 * which + 1][j], view[4 * which + 2][j], view[4 * which + 3][j]}; }
  lighting::Lit<float> lit_at(int j) const { return {{colour(0, j), colour(1, j)}, {colour(2, j), colour(3, j)}}; }
  lighting::SoaOut columns(const lighting::Key& key) {
    lighting::SoaOut o;
    for (int k = 0; k < 16; ++k) o.col[k >> 3][k >> 2 & 1][k & 3] = lit[k];
    o.keyed = true;
    for (int k = 0; k < 16; ++k) {
      const bool back = k >> 2 & 1, secondary = k >> 3;
      view[k] = secondary && !key.separate_specular() ? kZeros : lit[back && !key.two_side() ? k & ~4 : k];
    }
    return o;
  }
};

// The stage for one draw: the constants it reads, taken from the context once (after
// update_vertex_constants), and the run of a batch.
template <typename T>
class VertexStage {
  using V4 = glm::vec<4, T>;
  using V3 = glm::vec<3, T>;
  using M4 = glm::mat<4, 4, T>;

 public:
  using Scalar = T;
  // from_arrays: fetch(i) is Context::array_vertex(i); where every array it reads holds
  // GL_FLOAT the float stage reads them straight into its columns (fetch_float_arrays).
  explicit VertexStage(const Context& c, bool from_arrays = false)
      : c_(c),
        float_arrays_(from_arrays && c.float_arrays()),
        inv_(c.normal_matrix_),
        rescale_(c.rescale_normal_ ? glm::length(glm::dvec3(inv_[0][2], inv_[1][2], inv_[2][2])) : 0.0),  // M^-1's third row
        fog_depth_(c.fog_ && c.fog_coord_src_ == GL_FRAGMENT_DEPTH),
        constant_color_(!c.color_varies_ && !c.color_in_begin_format_) {}

  bool fog_depth() const { return fog_depth_; }

  // Vertices fetch(first + j), j in [0, m), m <= N, into out[0, m), their clip positions into
  // clip[0, m) (out.clip by default); `zero_normal` set when a normal of length 0 is normalized.
  template <int N, class Fetch>
  void run(const Fetch& fetch, GLint first, int m, StageOut<T, N>& out, bool* zero_normal, V4* clip = nullptr) const {
    if (!clip) clip = out.clip;
    if constexpr (std::is_same_v<T, float>) run_columns(fetch, first, m, out, zero_normal, clip);
    else run_rows(fetch, first, m, out, zero_normal, clip);
  }

 private:
  // The double stage (the reference), a vertex at a time.
  template <int N, class Fetch>
  void run_rows(const Fetch& fetch, GLint first, int m, StageOut<T, N>& out, bool* zero_normal, V4* clip) const {
    V4 eye[N], color[N];
    V3 normal[N];
    glm::dvec3 raw[N];  // object-space normals, to eye space in a second loop (it vectorizes apart)
    // Locals, not the context's members: the stores to `clip` (floats) could alias those, and
    // the loop would load the matrices again for every vertex.
    const bool lit = c_.lighting_, at_w = !c_.spec_;
    const M4 to_clip = c_.projection_.back(), to_eye = c_.modelview_.back();
    for (int j = 0; j < m; ++j) {
      const VertexIn in = fetch(first + j);
      V4& e = eye[j];  // eye space, where the lighting or fog reads it
      e = to_eye * in.obj;
      clip[j] = to_clip * e;
      // Mesa's fixed-function vertex program (ffvertex_prog.c build_fog): |eye z| for
      // GL_FRAGMENT_DEPTH (its default distance mode, eye plane absolute); for GL_FOG_COORD the
      // current fog coordinate, which stays 0 here (no glFogCoord).
      if (fog_depth_) out.fog[j] = std::abs(double(e.z));
      if (!lit) {
        for (int k = 0; k < 4; ++k) out.unlit[j][k] = clamp_unlit(in.color[k], constant_color_);
        continue;
      }
      // GL 2.1 lights the vertex at its eye-space point (x/w, y/w, z/w); Mesa's fixed-function program
      // takes x, y, z as they are (docs/deviations.md). The lighting divides unless w is 1.
      if (at_w) e.w = 1;
      color[j] = V4(in.color);
      raw[j] = in.normal;
    }
    if (!lit) return;
    const glm::dmat3 inv = inv_;  // locals: kept in registers over the loop
    const double rescale = rescale_;
    const bool normalize = c_.normalize_;
    for (int j = 0; j < m; ++j) normal[j] = V3(eye_normal(raw[j], inv, normalize, rescale, zero_normal));
    c_.kernel_d_(c_.prepared_d_, eye, normal, color, size_t(m), out.lit);
  }

  // The float stage on columns, a vector of vertices at a time (vertex_stage_simd.cpp and
  // lighting_simd.cpp): the fetch one vertex at a time (the arrays' types vary), then the
  // transforms, the normals and the lighting on every lane at once. The lanes past m are padding:
  // the origin with normal (0, 0, 1).
  template <int N, class Fetch>
  void run_columns(const Fetch& fetch, GLint first, int m, StageOut<float, N>& out, bool* zero_normal,
                   glm::vec4* clip) const {
    constexpr size_t P = lighting::kSoaPad;
    static_assert(N <= int(P));
    alignas(64) float obj[4][P], color[4][P], eye[4][P], normal[3][P];
    alignas(64) double raw[3][P];
    const bool lit = c_.lighting_, need_eye = lit || fog_depth_;
    const size_t lanes = lighting::soa_lanes();
    const size_t padded = std::min(P, (size_t(m) + lanes - 1) / lanes * lanes);
    if constexpr (std::is_same_v<Fetch, ListFetch>) fetch_list(fetch, first, m, obj, color, raw, out.unlit);
    else if (float_arrays_) fetch_float_arrays(first, m, obj, color, raw, out.unlit);
    else for (int j = 0; j < m; ++j) {
      const VertexIn in = fetch(first + j);
      for (int k = 0; k < 4; ++k) obj[k][j] = float(in.obj[k]);
      if (!lit) {
        for (int k = 0; k < 4; ++k) out.unlit[j][k] = clamp_unlit(in.color[k], constant_color_);
        continue;
      }
      for (int k = 0; k < 4; ++k) color[k][j] = float(in.color[k]);
      for (int k = 0; k < 3; ++k) raw[k][j] = in.normal[k];
    }
    for (size_t j = size_t(m); j < padded; ++j) {
      obj[0][j] = obj[1][j] = obj[2][j] = 0, obj[3][j] = 1;
      color[0][j] = color[1][j] = color[2][j] = color[3][j] = 0;
      raw[0][j] = raw[1][j] = 0, raw[2][j] = 1;
    }
    float* const eye_cols[4] = {eye[0], eye[1], eye[2], eye[3]};
    const float* const obj_cols[4] = {obj[0], obj[1], obj[2], obj[3]};
    const glm::mat4 to_eye = c_.modelview_f_.back().values();
    // GL 2.1 lights the vertex at (x/w, y/w, z/w); Mesa takes x, y, z as they are (see run_rows()):
    // outside spec mode the eye w column is 1 (the fog reads only z).
    transform_columns(c_.mvp_f_, need_eye ? &to_eye : nullptr, obj_cols, size_t(m), clip, eye_cols, lit && !c_.spec_);
    // Mesa's fixed-function vertex program (ffvertex_prog.c build_fog): |eye z| for
    // GL_FRAGMENT_DEPTH; see run_rows().
    if (fog_depth_)
      for (int j = 0; j < m; ++j) out.fog[j] = std::abs(double(eye[2][j]));
    if (!lit) return;
    const double* const raw_cols[3] = {raw[0], raw[1], raw[2]};
    float* const normal_cols[3] = {normal[0], normal[1], normal[2]};
    if (eye_normal_columns(inv_, c_.normalize_, rescale_, raw_cols, size_t(m), normal_cols)) *zero_normal = true;
    const lighting::SoaIn in{{eye[0], eye[1], eye[2], eye[3]}, {normal[0], normal[1], normal[2]},
                             {color[0], color[1], color[2], color[3]}};
    lighting::light_soa(c_.prepared_f_, in, size_t(m), out.columns(c_.prepared_f_.key));
  }
  // Immediate mode's kept vertices first + j, j in [0, m), into the columns: the positions a
  // vector at a time, the colours only where the lighting or the unlit path reads them.
  template <size_t P>
  void fetch_list(const ListFetch& f, GLint first, int m, float (&obj)[4][P], float (&color)[4][P], double (&raw)[3][P],
                  glm::dvec4* unlit) const {
    float* const cols[4] = {obj[0], obj[1], obj[2], obj[3]};
    float_columns(reinterpret_cast<const uint8_t*>(f.pos + first), 4, size_t(m), cols);
    const bool lit = c_.lighting_;
    const glm::dvec4* const colors = f.color ? f.color + first : nullptr;
    if (!lit) {
      for (int j = 0; j < m; ++j) {
        const glm::dvec4 c = colors ? colors[j] : f.cur_color;
        for (int k = 0; k < 4; ++k) unlit[j][k] = clamp_unlit(c[k], constant_color_);  // as run_columns
      }
      return;
    }
    if (f.normal) {
      const glm::dvec3* const normals = f.normal + first;
      for (int j = 0; j < m; ++j)
        for (int k = 0; k < 3; ++k) raw[k][j] = normals[j][k];
    } else {
      for (int k = 0; k < 3; ++k) std::fill(raw[k], raw[k] + m, f.cur_normal[k]);
    }
    // The lighting reads the colour only for colour material (lighting_simd.cpp).
    if (!c_.prepared_f_.key.color_material()) return;
    for (int j = 0; j < m; ++j) {
      const glm::dvec4 c = colors ? colors[j] : f.cur_color;
      for (int k = 0; k < 4; ++k) color[k][j] = float(c[k]);
    }
  }
  // array_vertex(first + j), j in [0, m), into the columns when every array read holds floats:
  // the values it would give (a float in double, then back to float, is the float), without the
  // record in double between. Components an array leaves out as array_vertex fills them.
  template <size_t P>
  void fetch_float_arrays(GLint first, int m, float (&obj)[4][P], float (&color)[4][P], double (&raw)[3][P],
                          glm::dvec4* unlit) const {
    const auto at = [](const uint8_t* p, int k) {
      float f;
      std::memcpy(&f, p + 4 * k, 4);
      return f;
    };
    const ClientArray &va = c_.vertex_array_, &na = c_.normal_array_, &ca = c_.color_array_;
    const int vn = va.size, cn = ca.size;
    // Elements of 3 or 4 floats side by side: a vector of elements at a time (float_columns).
    const auto packed = [](const ClientArray& a) {
      return !a.repeated && (a.size == 3 || a.size == 4) && (a.stride == 0 || size_t(a.stride) == size_t(a.size) * 4);
    };
    if (packed(va)) {
      float* const cols[4] = {obj[0], obj[1], obj[2], obj[3]};
      float_columns(element(va, first), vn, size_t(m), cols);
      if (vn == 3) std::fill(obj[3], obj[3] + m, 1.0f);
    } else {
      for (int j = 0; j < m; ++j) {
        const uint8_t* p = element(va, first + j);
        obj[0][j] = at(p, 0), obj[1][j] = vn > 1 ? at(p, 1) : 0.0f;
        obj[2][j] = vn > 2 ? at(p, 2) : 0.0f, obj[3][j] = vn > 3 ? at(p, 3) : 1.0f;
      }
    }
    const bool lit = c_.lighting_;
    if (lit && na.enabled && na.size == 3 && packed(na)) {
      double* const cols[3] = {raw[0], raw[1], raw[2]};
      double_columns(element(na, first), size_t(m), cols);
    } else if (lit) {
      for (int j = 0; j < m; ++j) {
        if (na.enabled) {
          const uint8_t* p = element(na, first + j);
          for (int k = 0; k < 3; ++k) raw[k][j] = at(p, k);
        } else {
          for (int k = 0; k < 3; ++k) raw[k][j] = c_.normal_[k];
        }
      }
    }
    // The lighting reads the colour only for colour material (lighting_simd.cpp).
    if (lit && !c_.prepared_f_.key.color_material()) return;
    if (lit && ca.enabled && packed(ca)) {
      float* const cols[4] = {color[0], color[1], color[2], color[3]};
      float_columns(element(ca, first), cn, size_t(m), cols);
      if (cn == 3) std::fill(color[3], color[3] + m, 1.0f);
      return;
    }
    float current[4];
    for (int k = 0; k < 4; ++k) current[k] = float(c_.color_[k]);
    for (int j = 0; j < m; ++j) {
      double rgba[4];
      if (ca.enabled) {
        const uint8_t* p = element(ca, first + j);
        for (int k = 0; k < 4; ++k) rgba[k] = k < cn ? at(p, k) : 1.0f;
      } else {
        for (int k = 0; k < 4; ++k) rgba[k] = c_.color_[k];
      }
      if (!lit) {  // as run_columns clamps it
        for (int k = 0; k < 4; ++k) unlit[j][k] = clamp_unlit(rgba[k], constant_color_);
        continue;
      }
      for (int k = 0; k < 4; ++k) color[k][j] = ca.enabled ? float(rgba[k]) : current[k];
    }
  }

  // An object-space normal to eye space: a row vector times M^-1 (the inverse transpose), then
  // normalized (a zero normal stays zero, ambient and emission only, and is reported) or rescaled,
  // in double as glm computes them.
  static glm::dvec3 eye_normal(const glm::dvec3& raw, const glm::dmat3& inv, bool normalize, double rescale,
                               bool* zero_normal) {
    glm::dvec3 n = raw * inv;
    if (normalize) {
      const double len = glm::length(n);
      if (len > 0) n /= len;
      else *zero_normal = true;
    } else if (rescale > 0) {
      n /= rescale;
    }
    return n;
  }

  const Context& c_;

  const bool float_arrays_;
  const glm::dmat3 inv_;
  const double rescale_;  // 0: no rescale
  const bool fog_depth_;
  const bool constant_color_;  // the current colour drawn for every vertex, none per vertex in Mesa (clamp_unlit)
};

namespace {

// A stage result as the general path keeps it.
template <typename T, int N>
raster::Vertex general_vertex(const StageOut<T, N>& out, int j, bool lit, bool fog) {
  raster::Vertex v;
  v.clip = out.clip[j];
  if (fog) v.fog = out.fog[j];
  if (!lit) {
    v.front = v.back = out.unlit[j];
    v.front_sec = v.back_sec = glm::dvec4(0);
    return v;
  }
  const lighting::Lit<T> l = out.lit_at(j);
  v.front = l.primary[0], v.back = l.primary[1];
  v.front_sec = l.secondary[0], v.back_sec = l.secondary[1];
  return v;
}

}  // namespace

// One vertex through the stage, in the context's precision.
raster::Vertex Context::vertex(const glm::dvec4& obj, const glm::dvec3& normal, const glm::dvec4& color,
                               bool* zero_normal) const {
  const auto fetch = [&](GLint) { return VertexIn{obj, normal, color}; };
  if (precision_ == Precision::Float) {
    const VertexStage<float> stage(*this);
    StageOut<float, 1> out;
    stage.run(fetch, 0, 1, out, zero_normal);
    return general_vertex(out, 0, lighting_, stage.fog_depth());
  }
  const VertexStage<double> stage(*this);
  StageOut<double, 1> out;
  stage.run(fetch, 0, 1, out, zero_normal);
  return general_vertex(out, 0, lighting_, stage.fog_depth());
}

void Context::process_vertex(const glm::dvec4& obj) {
  if (immediate_list_) {  // lit with the others at glEnd
    keep_list_vertex(float(obj.x), float(obj.y), float(obj.z), float(obj.w));  // immediate.cpp
    return;
  }
  // Kept for the batch: a store here, the stage later for many vertices at once. A vertex equal
  // to the one before (position, normal and colour, bit for bit) under the same state is the same
  // lit vertex, so it shares that one's entry.
  const VertexIn in{obj, normal_, color_};
  if (pending_in_.empty() || std::memcmp(&pending_in_.back(), &in, sizeof in) != 0) {
    if (pending_in_.size() == kPendingBatch) light_pending();
    pending_in_.push_back(in);
  }
  pending_slot_.push_back(uint32_t(pending_in_.size() - 1));
  verts_.emplace_back();
  const bool finite = std::isfinite(obj.x) && std::isfinite(obj.y) && std::isfinite(obj.z) && std::isfinite(obj.w) &&
                      (!lighting_ || (std::isfinite(normal_.x) && std::isfinite(normal_.y) && std::isfinite(normal_.z)));
  if (!finite) deviations_.insert(kNonfiniteVertex);
}

void Context::light_pending() {
  if (pending_slot_.empty()) return;
  update_vertex_constants();
  const size_t base = verts_.size() - pending_slot_.size();
  const auto fetch = [this](GLint i) { return pending_in_[size_t(i)]; };
  bool zero_normal = false;
  auto batches = [&](auto stage) {
    using T = typename decltype(stage)::Scalar;
    StageOut<T, kBatch> out;
    size_t slot = 0;
    for (size_t b = 0; b < pending_in_.size(); b += kBatch) {
      const int m = int(std::min<size_t>(kBatch, pending_in_.size() - b));
      stage.run(fetch, GLint(b), m, out, &zero_normal);
      for (; slot < pending_slot_.size() && pending_slot_[slot] < b + size_t(m); ++slot)
        verts_[base + slot] = general_vertex(out, int(pending_slot_[slot] - b), lighting_, stage.fog_depth());
    }
  };
  if (precision_ == Precision::Float) batches(VertexStage<float>(*this));
  else batches(VertexStage<double>(*this));
  if (zero_normal) deviations_.insert(kZeroNormal);
  // The slots lit, the batch starts again; a vertex sent next is never merged with one lit here.
  pending_in_.clear(), pending_slot_.clear();
}

// Array element i as the stage takes it: each attribute from its array when enabled, else the
// current value (the normal only where the lighting reads it).
// Inlined into the stage's loop: a call per vertex, returning the record through memory, costs
// as much as a quarter of the stage (measured on the depth-5 icosphere from arrays).
[[gnu::always_inline]] inline VertexIn Context::array_vertex(GLint i) const {
  VertexIn v;
  v.obj = attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1));
  v.color = color_array_.enabled ? attribute(color_array_, i, color_array_.size, draw_fixed(), glm::dvec4(1)) : color_;
  v.normal = lighting_ && normal_array_.enabled ? glm::dvec3(attribute(normal_array_, i, 3, draw_fixed(), glm::dvec4(0)))
                                                : normal_;
  return v;
}

// Whether array_vertex reads only GL_FLOAT arrays (the float stage's direct fetch).
bool Context::float_arrays() const {
  return vertex_array_.type == GL_FLOAT && (!color_array_.enabled || color_array_.type == GL_FLOAT) &&
         (!lighting_ || !normal_array_.enabled || normal_array_.type == GL_FLOAT);
}

// Vertices [first, first + count) in batches, batch(lo, hi, zero_normal) for each share of the
// range: on one thread below kParallelStage vertices, else in more shares than threads (a late
// thread's share is taken by another). The vertices are independent, so the split changes nothing.
template <class Batches>
void Context::run_stage(GLint first, GLint count, const Batches& batches) {
  bool zero[8] = {};  // per share: a zero normal met
  if (count < kParallelStage || threads_ == 1) {
    batches(first, first + count, &zero[0]);
  } else {
    pool::Workers& w = workers();
    const int shares = std::min(4 * w.size(), 8);
    w.run([&](int s) {
      batches(first + GLint(int64_t(count) * s / shares), first + GLint(int64_t(count) * (s + 1) / shares), &zero[s]);
    }, shares);
  }
  if (std::find(std::begin(zero), std::end(zero), true) != std::end(zero)) deviations_.insert(kZeroNormal);
}

// A large glDrawArrays / glDrawElements range on the general path: array elements [first,
// first + count) into verts_.
void Context::arrays_to_vertices(GLint first, GLint count) {
  update_vertex_constants();
  verts_.resize(size_t(count));
  const auto fetch = [this](GLint i) { return array_vertex(i); };
  auto batches = [&](auto stage, GLint lo, GLint hi, bool* zero) {
    using T = typename decltype(stage)::Scalar;
    StageOut<T, kBatch> out;
    for (GLint b = lo; b < hi; b += kBatch) {
      const int m = int(std::min<GLint>(kBatch, hi - b));
      stage.run(fetch, b, m, out, zero);
      for (int j = 0; j < m; ++j) verts_[size_t(b + j - first)] = general_vertex(out, j, lighting_, stage.fog_depth());
    }
  };
  if (precision_ == Precision::Float)
    run_stage(first, count, [&](GLint lo, GLint hi, bool* zero) { batches(VertexStage<float>(*this, true), lo, hi, zero); });
  else
    run_stage(first, count, [&](GLint lo, GLint hi, bool* zero) { batches(VertexStage<double>(*this), lo, hi, zero); });
}

// The triangle-list path's vertices (float): count vertices, vertex o from fetch(first + o), lit
// into list_vertices_[at + o] and mapped to the window, on the threads.
template <class Fetch>
void Context::stage_to_list(const Fetch& fetch, GLint first, GLint count, bool from_arrays, size_t at) {
  update_vertex_constants();
  const raster::State rs = raster_state();
  list_vertices_.resize(at + size_t(count), rs.two_side, rs.add_secondary);
  run_stage(first, count, [&](GLint lo, GLint hi, bool* zero) { stage_list_part(fetch, first, lo, hi, from_arrays, at, rs, zero); });
}

// Vertices [lo, hi) of stage_to_list's numbering, on the calling thread; list_vertices_ is sized.
// Also immediate mode's early job (immediate.cpp), on its own thread: it reads only the context's
// constants, which stay as they are meanwhile.
template <class Fetch>
void Context::stage_list_part(const Fetch& fetch, GLint first, GLint lo, GLint hi, bool from_arrays, size_t at,
                              const raster::State& rs, bool* zero) {
  raster::ListVertices& out = list_vertices_;
  // Read once: the stores below could alias the vectors' sizes, which would be loaded per vertex.
  const bool back = !out.back.empty(), front_sec = !out.front_sec.empty(), back_sec = !out.back_sec.empty();
  const VertexStage<float> stage(*this, from_arrays);
  StageOut<float, kBatch> s;
  for (GLint b = lo; b < hi; b += kBatch) {
    const int m = int(std::min<GLint>(kBatch, hi - b));
    const size_t o0 = at + size_t(b - first);
    stage.run(fetch, b, m, s, zero, &out.clip[o0]);  // straight to the list
    if (!lighting_)
      for (int j = 0; j < m; ++j) out.hot[o0 + size_t(j)].color = glm::vec4(s.unlit[j]);
    else if (back || front_sec || back_sec)
      for (int j = 0; j < m; ++j) {
        const size_t o = o0 + size_t(j);
        if (back) out.back[o] = s.colour(1, j);
        if (front_sec) out.front_sec[o] = s.colour(2, j);
        if (back_sec) out.back_sec[o] = s.colour(3, j);
      }
    // The front colours from their columns, with the positions (a vector at a time).
    raster::map_list_vertices(out, o0, size_t(m), rs, lighting_ ? &s.view[0] : nullptr);
  }
}

void Context::arrays_to_list(GLint first, GLint count) {
  stage_to_list([this](GLint i) { return array_vertex(i); }, first, count, true);
}

// Immediate mode's kept vertices (process_vertex), as they were at each glVertex: what was not
// kept is not read, and the current value stands in.
// Those lit early (early_.lit) are in place already; the early job in flight is joined here.
void Context::immediate_to_list() {
  const ListFetch fetch{list_pos_.data(), list_normal_.empty() ? nullptr : list_normal_.data(),
                        list_color_.empty() ? nullptr : list_color_.data(), normal_, color_};
  const size_t n = list_pos_.size();
  if (early_.in_flight && !constants_dirty_ && n > early_.lit) {
    // The rest lit on this thread while the job finishes: other records of list_vertices_, the
    // same constants (unchanged since its handoff), so long as nothing must grow under it.
    const raster::State rs = raster_state();
    if (list_vertices_.holds(n, rs.two_side, rs.add_secondary)) {
      bool zero = false;
      stage_list_part(fetch, 0, GLint(early_.lit), GLint(n), false, 0, rs, &zero);
      if (zero) deviations_.insert(kZeroNormal);
      early_.lit = n;
    }
  }
  early_join();
  const size_t lit = early_.lit;
  stage_to_list(fetch, GLint(lit), GLint(n - lit), false, lit);
}

// On a worker thread: reads only what early_handoff took (early_job_) and the lists' complete part.
void Context::early_job() {
  EarlyJob& j = early_job_;
  const ListFetch fetch{j.pos, j.normal, j.color, j.cur_normal, j.cur_color};
  bool zero = false;
  stage_list_part(fetch, 0, GLint(j.first), GLint(j.lit), false, 0, j.rs, &zero);
  const uint64_t slivers = counters_.clipped_slivers.load(std::memory_order_relaxed);
  // A chunk at a time, in order: stopped between two, the triangles drawn are [tri_first, reached)
  // on every row, and the caller draws the rest after them.
  raster::ClearRequest clear = j.clear;  // with the first chunk (or alone, with none)
  do {
    const size_t n = std::min(j.chunk, j.drawn - j.reached);
    raster::draw_triangle_list(fb_, j.rs, list_vertices_, j.corners + 3 * j.reached, n, early_workers_, early_bins_, clear);
    clear = {};
    j.reached += n;
  } while (j.reached < j.drawn && !j.stop.load(std::memory_order_relaxed));
  j.zero_normal |= zero;
  j.sliver |= counters_.clipped_slivers.load(std::memory_order_relaxed) != slivers;
}

}  // namespace ffc::state
