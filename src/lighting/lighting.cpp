#include "lighting/lighting.h"

#include <algorithm>
#include <array>
#include <type_traits>
#include <utility>
#include <cmath>

#include "simd/pow.h"

namespace ffc::lighting {

namespace {

constexpr unsigned kAmbient = 0x1200, kDiffuse = 0x1201, kSpecular = 0x1202, kEmission = 0x1600;

template <typename T>
V3<T> rgb(const glm::dvec4& c) {
  return V3<T>(T(c.r), T(c.g), T(c.b));
}

// Clamped to [0,1], a NaN going to 1 as in Mesa's fixed-function clamp (min(max(x, 0), 1) with a
// NaN-propagating max and a NaN-dropping min): a NaN (inf * 0 from an infinite attenuation, a NaN
// input; unspecified by GL 2.1, 2.1.1) never leaves the lighting stage.
template <typename T>
[[gnu::always_inline]] inline V4<T> saturate(const V4<T>& v) {
  V4<T> r;
  for (int k = 0; k < 4; ++k) r[k] = !(v[k] < T(1)) ? T(1) : v[k] > T(0) ? v[k] : T(0);
  return r;
}

// The powers (spot exponent, shininess) of bases max(0, x): in float the shared exp2(log2)
// (simd/pow.h), the bits every SIMD target gives; the double reference keeps the C library's pow.
template <typename T>
[[gnu::always_inline]] inline T power(T base, T e) {
  if constexpr (std::is_same_v<T, float>) return simd::pow_float(base, e);
  else return std::pow(base, e);
}

}  // namespace

template <typename T>
Prepared<T> prepare(const LightParams (&lights)[8], const MaterialParams (&mat)[2], const ModelParams& model,
                    Key key) {
  Prepared<T> c;
  c.key = key;
  c.model = model;
  c.global_ambient = rgb<T>(model.ambient);
  for (int f = 0; f < 2; ++f) {
    c.mat[f] = mat[f];
    c.scene[f] = rgb<T>(mat[f].emission) + rgb<T>(mat[f].ambient) * c.global_ambient;
    c.alpha[f] = T(mat[f].diffuse.a);
    c.shininess[f] = T(mat[f].shininess);
  }
  for (const LightParams& l : lights) {
    if (!l.enabled) continue;
    PreparedLight<T>& p = c.light[c.count++];
    p.la = rgb<T>(l.ambient), p.ld = rgb<T>(l.diffuse), p.ls = rgb<T>(l.specular);
    for (int f = 0; f < 2; ++f) {
      p.amb[f] = p.la * rgb<T>(mat[f].ambient);
      p.dif[f] = p.ld * rgb<T>(mat[f].diffuse);
      p.spe[f] = p.ls * rgb<T>(mat[f].specular);
    }
    p.local = l.position.w != 0;
    if (p.local) {
      p.pos = V3<T>(glm::dvec3(l.position) / l.position.w);
    } else {
      const glm::dvec3 d(l.position);
      const double len = glm::length(d);
      p.pos = len > 0 ? V3<T>(d / len) : V3<T>(0);
      // With an infinite viewer and a directional light, h does not depend on the vertex.
      const glm::dvec3 h = glm::dvec3(p.pos) + glm::dvec3(0, 0, 1);
      const double hl = glm::length(h);
      p.half = hl > 0 ? V3<T>(h / hl) : V3<T>(0);
    }
    p.spot = l.spot_cutoff != 180;
    if (p.spot) {
      const double len = glm::length(l.spot_direction);
      p.spot_dir = len > 0 ? V3<T>(l.spot_direction / len) : V3<T>(0);
      // cos 90 is 0 exactly (cos(pi/2) rounds to 6e-17): 2.14.1 lights cos >= cos(cutoff), so a
      // vertex exactly on a 90-degree cone's boundary is lit.
      p.spot_cos = T(l.spot_cutoff == 90 ? 0.0 : std::cos(l.spot_cutoff * M_PI / 180));
      p.spot_exp = T(l.spot_exponent);
    }
    p.k0 = T(l.constant_attenuation), p.k1 = T(l.linear_attenuation), p.k2 = T(l.quadratic_attenuation);
    p.attenuated = p.local && (p.k0 != 1 || p.k1 != 0 || p.k2 != 0);
    const auto finite = [](const V3<T>& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    p.finite = finite(p.la) && finite(p.ld) && finite(p.ls);
    for (int f = 0; f < 2; ++f) p.finite = p.finite && finite(p.amb[f]) && finite(p.dif[f]) && finite(p.spe[f]);
  }
  return c;
}

// Runtime shape: every choice read from the key and the lights (the generic kernel).
struct RuntimeShape {
  static bool two_side(const Key& k) { return k.two_side(); }
  static bool local_viewer(const Key& k) { return k.local_viewer(); }
  static bool specular(const Key& k) { return k.specular(); }
  static bool color_material(const Key& k) { return k.color_material(); }
  static bool separate_specular(const Key& k) { return k.separate_specular(); }
  template <typename L>
  static bool local(const L& l) { return l.local; }
  template <typename L>
  static bool attenuated(const L& l) { return l.attenuated; }
  template <typename L>
  static bool spot(const L& l) { return l.spot; }
};

// What every enabled light is, when they agree: the kernel then has no per-light branches.
enum LightKind : unsigned { kMixed = 0, kDirectional = 1, kPoint = 2, kPointAttenuated = 3 };

// Compile-time shape: the terms a key leaves out are not in the code at all. Directional lights
// without spot have L and (with an infinite viewer) h as per-light constants; point lights
// without spot skip the cone, and without attenuation the division too.
template <bool TwoSide, bool LocalViewer, bool Specular, bool ColorMaterial, bool Separate, unsigned Kind>
struct StaticShape {
  static constexpr bool two_side(const Key&) { return TwoSide; }
  static constexpr bool local_viewer(const Key&) { return LocalViewer; }
  static constexpr bool specular(const Key&) { return Specular; }
  static constexpr bool color_material(const Key&) { return ColorMaterial; }
  static constexpr bool separate_specular(const Key&) { return Separate; }
  template <typename L>
  static bool local(const L& l) { return Kind == kMixed ? l.local : Kind != kDirectional; }
  template <typename L>
  static bool attenuated(const L& l) { return Kind == kMixed ? l.attenuated : Kind == kPointAttenuated && l.attenuated; }
  template <typename L>
  static bool spot(const L& l) { return Kind == kMixed && l.spot; }
};

template <typename T, typename S>
inline Lit<T> light_impl(const Prepared<T>& c, const V4<T>& p4, const V3<T>& n, const V4<T>& color) {
  const Key& key = c.key;
  const V3<T> p = (p4.w != 0 && p4.w != 1) ? V3<T>(p4) / p4.w : V3<T>(p4);
  const V3<T> cm = V3<T>(color);
  // The eye direction for a local viewer: from the vertex toward the origin of eye space.
  V3<T> to_eye(0, 0, 1);
  if (S::local_viewer(key)) {
    const T len = glm::length(p);
    to_eye = len > 0 ? -p / len : V3<T>(0);
  }
  // A key without the specular term (every light's specular times the material's is 0) still has
  // it where Mesa's result shows it: Mesa's program keys on no colour, so it raises n.h to the
  // shininess whatever the colour, and a power overflowing to infinity times the colour's 0 is a
  // NaN, which the clamp makes 1 (docs/deviations.md, row 69). Since n.h <= |n|
  // and the shininess is at most 128, only a normal longer than 2 (not normalised, or scaled by
  // the modelview) can overflow: the term is computed for those alone, below 2 it adds a zero.
  const bool long_normal = !S::specular(key) && glm::dot(n, n) >= kLongNormal2<T>;
  Lit<T> out;
  const int faces = S::two_side(key) ? 2 : 1;
  for (int f = 0; f < faces; ++f) {
    const V3<T> nf = f == 0 ? n : -n;
    const bool cm_on = S::color_material(key) && (c.model.cm_faces >> f & 1);
    V3<T> prim = c.scene[f], sec(0);
    T alpha = c.alpha[f];
    bool track_amb = false, track_dif = false, track_spe = false;
    if (cm_on) {
      const ModelParams& m = c.model;
      track_amb = tracks(m, kAmbient), track_dif = tracks(m, kDiffuse), track_spe = tracks(m, kSpecular);
      const V3<T> ma = track_amb ? cm : rgb<T>(c.mat[f].ambient);
      const V3<T> me = tracks(m, kEmission) ? cm : rgb<T>(c.mat[f].emission);
      prim = me + ma * c.global_ambient;
      if (track_dif) alpha = color.a;
    }
    for (int i = 0; i < c.count; ++i) {
      const PreparedLight<T>& L = c.light[i];
      V3<T> vp = L.pos;
      T att = 1;
      if (S::local(L)) {
        const V3<T> d = L.pos - p;
        const T dist = glm::length(d);
        vp = dist > 0 ? d / dist : V3<T>(0);
        if (S::attenuated(L)) att = T(1) / (L.k0 + L.k1 * dist + L.k2 * dist * dist);
      }
      if (S::spot(L)) {
        const T cos_angle = glm::dot(-vp, L.spot_dir);
        // Outside the cone Mesa's program multiplies the light's terms by a spot factor of 0 rather
        // than leaving them out: the same wherever they are finite, a NaN (clamped to 1) where one
        // is not, such as a specular power overflowing for a long normal. max(0, NaN) is 0, as in Mesa.
        att *= cos_angle < L.spot_cos ? T(0) : power(std::max(T(0), cos_angle), L.spot_exp);
      }
      const V3<T> amb = track_amb ? L.la * cm : L.amb[f];
      const V3<T> dif = track_dif ? L.ld * cm : L.dif[f];
      const T ndotl = glm::dot(nf, vp);
      V3<T> sum = amb + std::max(T(0), ndotl) * dif;  // a NaN n.L (NaN normal) drops out, as in Mesa
      if (S::specular(key) || long_normal) {
        // LIT's specular factor: the power where n.L > 0, else 0. Mesa's program multiplies the
        // colour by it either way, so a colour that is not finite (a tracked colour of inf) shows
        // as a NaN even where the light is behind the face.
        T factor = 0;
        if (ndotl > 0) {
          V3<T> h = L.half;
          if (S::local_viewer(key) || S::local(L)) {
            h = vp + to_eye;
            const T hl = glm::length(h);
            h = hl > 0 ? h / hl : V3<T>(0);
          }
          factor = power(std::max(T(0), glm::dot(nf, h)), c.shininess[f]);
        }
        const V3<T> spe = track_spe ? L.ls * cm : L.spe[f];
        const V3<T> s = factor * spe;
        if (S::separate_specular(key))
          sec += att * s;
        else
          sum += s;
      }
      prim += att * sum;
    }
    out.primary[f] = saturate(V4<T>(prim, alpha));
    out.secondary[f] = saturate(V4<T>(sec, T(0)));
  }
  if (faces == 1) out.primary[1] = out.primary[0], out.secondary[1] = out.secondary[0];
  return out;
}

template <typename T>
Lit<T> light(const Prepared<T>& c, const V4<T>& p, const V3<T>& n, const V4<T>& color) {
  return light_impl<T, RuntimeShape>(c, p, n, color);
}

namespace {

template <typename T, typename S>
void batch(const Prepared<T>& c, const V4<T>* p, const V3<T>* n, const V4<T>* color, size_t count, Lit<T>* out) {
  for (size_t i = 0; i < count; ++i) out[i] = light_impl<T, S>(c, p[i], n[i], color[i]);
}

// Shape index: bit 0 two-sided, 1 local viewer, 2 specular, 3 colour material, 4 separate
// specular, bits 5-6 the light kind. Every combination is instantiated once, at compile time.
template <typename T, unsigned I>
constexpr Kernel<T> instance() {
  return &batch<T, StaticShape<(I & 1) != 0, (I & 2) != 0, (I & 4) != 0, (I & 8) != 0, (I & 16) != 0, (I >> 5) & 3>>;
}

template <typename T, unsigned... I>
constexpr std::array<Kernel<T>, sizeof...(I)> table(std::integer_sequence<unsigned, I...>) {
  return {instance<T, I>()...};
}

}  // namespace

unsigned shape_index(const Key& k) {
  bool directional = true, point = true, spot = false, attenuated = false;
  for (int i = 0; i < 8; ++i) {
    if (!k.enabled(i)) continue;
    directional &= !k.local(i), point &= k.local(i);
    spot |= k.spot(i), attenuated |= k.attenuated(i);
  }
  const unsigned kind = spot ? kMixed
                        : directional ? kDirectional
                        : point ? (attenuated ? kPointAttenuated : kPoint)
                                : kMixed;
  return unsigned(k.two_side()) | unsigned(k.local_viewer()) << 1 | unsigned(k.specular()) << 2 |
         unsigned(k.color_material()) << 3 | unsigned(k.separate_specular()) << 4 | kind << 5;
}

Key make_key(const LightParams (&lights)[8], const MaterialParams (&materials)[2], const ModelParams& model,
             bool normalize, bool rescale) {
  Key k;
  bool specular = false;
  for (int i = 0; i < 8; ++i) {
    const LightParams& l = lights[i];
    if (!l.enabled) continue;
    const bool local = l.position.w != 0;
    const bool attenuated =
        local && (l.constant_attenuation != 1 || l.linear_attenuation != 0 || l.quadratic_attenuation != 0);
    k.set_light(i, local, l.spot_cutoff != 180, attenuated);
    for (const MaterialParams& m : materials) specular |= glm::dvec3(l.specular) * glm::dvec3(m.specular) != glm::dvec3(0);
  }
  constexpr unsigned kGlSpecular = 0x1202;  // GL_SPECULAR: the tracked colour may bring the term
  if (model.color_material && model.cm_mode == kGlSpecular) specular = true;
  k.set(Key::kTwoSide, model.two_side);
  k.set(Key::kLocalViewer, model.local_viewer);
  k.set(Key::kSeparateSpecular, model.separate_specular);
  k.set(Key::kColorMaterial, model.color_material);
  k.set(Key::kNormalize, normalize);
  k.set(Key::kRescale, rescale);
  k.set(Key::kSpecular, specular);
  k.set(Key::kShininessZero, materials[0].shininess == 0);
  return k;
}

template <typename T>
Kernel<T> specialised(const Key& key) {
  static constexpr auto kernels = table<T>(std::make_integer_sequence<unsigned, 128>());
  return kernels[shape_index(key)];
}

template <typename T>
Kernel<T> generic() {
  return &batch<T, RuntimeShape>;
}

template Prepared<float> prepare(const LightParams (&)[8], const MaterialParams (&)[2], const ModelParams&, Key);
template Prepared<double> prepare(const LightParams (&)[8], const MaterialParams (&)[2], const ModelParams&, Key);
template Lit<float> light(const Prepared<float>&, const V4<float>&, const V3<float>&, const V4<float>&);
template Lit<double> light(const Prepared<double>&, const V4<double>&, const V3<double>&, const V4<double>&);
template Kernel<float> specialised<float>(const Key&);
template Kernel<double> specialised<double>(const Key&);
template Kernel<float> generic<float>();
template Kernel<double> generic<double>();

}  // namespace ffc::lighting
