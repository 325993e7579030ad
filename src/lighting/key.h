// The lighting key: which terms of the equation exist for the current state, as Mesa's
// ffvertex_prog.c state_key. Zeroed, then set bit by bit, so equal states give equal keys.
//
//  bit  0- 7  light i enabled          bit 24     two-sided lighting
//  bit  8-15  light i local (w != 0)   bit 25     local viewer
//  bit 16-23  light i spot (cutoff != 180) bit 26 separate specular
//  (attenuation and specular presence in `extra`)  bit 27 colour material
//                                      bit 28-29  normalize, rescale normal
//  extra: bit 0-7 light i attenuated; bit 8 any specular product non-zero; bit 9 shininess is 0
#pragma once
#include <cstdint>

namespace ffc::lighting {

struct Key {
  uint32_t bits = 0;
  uint32_t extra = 0;

  bool enabled(int i) const { return bits >> i & 1; }
  bool local(int i) const { return bits >> (8 + i) & 1; }
  bool spot(int i) const { return bits >> (16 + i) & 1; }
  bool attenuated(int i) const { return extra >> i & 1; }
  bool two_side() const { return bits >> 24 & 1; }
  bool local_viewer() const { return bits >> 25 & 1; }
  bool separate_specular() const { return bits >> 26 & 1; }
  bool color_material() const { return bits >> 27 & 1; }
  bool normalize() const { return bits >> 28 & 1; }
  bool rescale() const { return bits >> 29 & 1; }
  bool specular() const { return extra >> 8 & 1; }
  bool operator==(const Key& o) const { return bits == o.bits && extra == o.extra; }
};

}  // namespace ffc::lighting
