// The lighting key: which terms of the equation exist for the current state, as Mesa's
// ffvertex_prog.c state_key. One writer fills it from zero (make_key, lighting.cpp), so equal
// states give equal keys; the kernels are chosen from it (shape_index).
//
//   bits   0- 7  light i enabled            extra  0- 7  light i attenuated (local, k != (1, 0, 0))
//   bits   8-15  light i local (w != 0)     extra  8     a specular term exists
//   bits  16-23  light i spot (cutoff != 180)   extra  9  the front shininess is 0
//   bit   24     two-sided lighting
//   bit   25     local viewer
//   bit   26     separate specular colour
//   bit   27     colour material, the colour varying per vertex
//   bits  28-29  GL_NORMALIZE, GL_RESCALE_NORMAL
#pragma once
#include <cstdint>

namespace ffc::lighting {

struct Key {
  // Where each term lives (the table above); nothing else spells these positions.
  enum Bit : unsigned {
    kEnabled = 0, kLocal = 8, kSpot = 16, kTwoSide = 24, kLocalViewer = 25, kSeparateSpecular = 26,
    kColorMaterial = 27, kNormalize = 28, kRescale = 29,
  };
  enum ExtraBit : unsigned { kAttenuated = 0, kSpecular = 8, kShininessZero = 9 };

  uint32_t bits = 0;
  uint32_t extra = 0;

  bool enabled(int i) const { return test(bits, kEnabled + unsigned(i)); }
  bool local(int i) const { return test(bits, kLocal + unsigned(i)); }
  bool spot(int i) const { return test(bits, kSpot + unsigned(i)); }
  bool attenuated(int i) const { return test(extra, kAttenuated + unsigned(i)); }
  bool two_side() const { return test(bits, kTwoSide); }
  bool local_viewer() const { return test(bits, kLocalViewer); }
  bool separate_specular() const { return test(bits, kSeparateSpecular); }
  bool color_material() const { return test(bits, kColorMaterial); }
  bool normalize() const { return test(bits, kNormalize); }
  bool rescale() const { return test(bits, kRescale); }
  bool specular() const { return test(extra, kSpecular); }
  bool shininess_zero() const { return test(extra, kShininessZero); }
  bool any_light() const { return (bits & 0xFFu) != 0; }
  bool operator==(const Key& o) const { return bits == o.bits && extra == o.extra; }

  void set(Bit b, bool on = true) { put(bits, b, on); }
  void set(ExtraBit b, bool on = true) { put(extra, b, on); }
  void set_light(int i, bool local, bool spot, bool attenuated) {
    put(bits, kEnabled + unsigned(i), true);
    put(bits, kLocal + unsigned(i), local);
    put(bits, kSpot + unsigned(i), spot);
    put(extra, kAttenuated + unsigned(i), attenuated);
  }

 private:
  static bool test(uint32_t w, unsigned b) { return w >> b & 1u; }
  static void put(uint32_t& w, unsigned b, bool on) { w = (w & ~(1u << b)) | (uint32_t(on) << b); }
};

}  // namespace ffc::lighting
