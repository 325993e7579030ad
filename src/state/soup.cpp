// glDrawArrays(GL_TRIANGLES) of a triangle soup, every corner sent (the way seed 000 draws): a
// corner whose attributes repeat an earlier one's bit for bit (position, and the normal and colour
// where the stage reads them) is that vertex again, lit once. The draw becomes an indexed one:
// the distinct corners copied to a compact interleaved array the stage reads as it reads the
// client's (the same floats, so the same bits), and the triangles drawn from indices in their
// order. A repeat is found in a direct-mapped cache of recent corners holding each one's bits
// (a soup of a mesh repeats a corner within a few triangles); one the cache lost is lit again,
// which changes nothing but the time. On both threads each share of the corners has its cache
// and its distinct corners, laid out one share after the other.
#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "state/client_arrays.h"
#include "pool/workers.h"
#include "state/context.h"

namespace ffc::state {

namespace {

constexpr GLsizei kSoupMin = 192;          // below this the lighting saved costs less than the cache
constexpr GLsizei kSoupParallel = 8192;    // below this one thread finds the repeats
constexpr int kSoupSlotBits = 10;          // per share: 32 KiB for a position and a normal

constexpr uint64_t kOdd[11] = {0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full, 0x165667B19E3779F9ull,
                               0xD6E8FEB86659FD93ull, 0xFF51AFD7ED558CCDull, 0xC4CEB9FE1A85EC53ull,
                               0x94D049BB133111EBull, 0xBF58476D1CE4E5B9ull, 0x2545F4914F6CDD1Dull,
                               0x9FB21C651E98DF25ull, 0xD1B54A32D192ED03ull};

// A slot of the cache: the corner's R words in pairs (the last one's high half 0 for an odd R),
// then the generation that wrote it (high half) and its distinct number (low); 32 bytes where
// that fits (a position and a normal: the table stays in L1), else 64.
constexpr int pairs(int r) { return (r + 1) / 2; }
constexpr int slot_pairs(int r) { return pairs(r) + 1 <= 4 ? 4 : 8; }

// An array read as floats: element i at base + stride * i.
struct Source {
  const uint8_t* base;
  size_t stride;
};
Source source(const ClientArray& a) {
  return {static_cast<const uint8_t*>(a.pointer), a.stride ? size_t(a.stride) : size_t(a.size) * 4};
}

// Corners [lo, hi) of the draw (element first + c): each one's distinct corner into index[c],
// numbered from 0, the new ones' floats staged in order; returns how many. The record's layout
// is fixed per instance (VN position, NN normal, CN colour floats): the key stays in registers,
// its words loaded as the 4 bytes they are (words copied through memory in other sizes stall on
// store forwarding) and paired into 64-bit halves, hashed, compared and stored a pair at a time
// (six products a corner had been the loop's cost).
template <int VN, int NN, int CN>
uint32_t find_repeats(const Source (&src)[3], GLint first, size_t lo, size_t hi, uint64_t* slots,
                      uint32_t generation, uint32_t* index, float* staged) {
  constexpr int R = VN + NN + CN, P = pairs(R), W = slot_pairs(R);
  uint32_t n = 0;
  for (size_t c = lo; c < hi; ++c) {
    const size_t i = size_t(first) + c;
    uint32_t k[2 * P] = {};
    for (int j = 0; j < VN; ++j) std::memcpy(&k[j], src[0].base + src[0].stride * i + 4 * size_t(j), 4);
    for (int j = 0; j < NN; ++j) std::memcpy(&k[VN + j], src[1].base + src[1].stride * i + 4 * size_t(j), 4);
    for (int j = 0; j < CN; ++j) std::memcpy(&k[VN + NN + j], src[2].base + src[2].stride * i + 4 * size_t(j), 4);
    uint64_t w[P];
    for (int p = 0; p < P; ++p) w[p] = k[2 * p] | uint64_t(k[2 * p + 1]) << 32;
    // Independent products summed; the top bits depend on every bit.
    uint64_t h = 0;
    for (int p = 0; p < P; ++p) h += w[p] * kOdd[p];
    uint64_t* slot = slots + (h >> (64 - kSoupSlotBits)) * W;
    bool same = uint32_t(slot[P] >> 32) == generation;
    for (int p = 0; p < P; ++p) same &= slot[p] == w[p];
    if (same) {
      index[c] = uint32_t(slot[P]);
      continue;
    }
    for (int p = 0; p < P; ++p) slot[p] = w[p];
    for (int j = 0; j < R; ++j) std::memcpy(staged + size_t(n) * R + size_t(j), &k[j], 4);
    slot[P] = uint64_t(generation) << 32 | n;
    index[c] = n++;
  }
  return n;
}

using FindRepeats = uint32_t (*)(const Source (&)[3], GLint, size_t, size_t, uint64_t*, uint32_t, uint32_t*,
                                 float*);
template <int VN, int NN>
FindRepeats with_colour(int cn) {
  switch (cn) {
    case 0: return find_repeats<VN, NN, 0>;
    case 3: return find_repeats<VN, NN, 3>;
    case 4: return find_repeats<VN, NN, 4>;
  }
  return nullptr;
}
// The instance for a layout; null for one not worth an instance (two-component positions, a
// colour of one or two components: lit every corner, as before).
FindRepeats find_repeats_for(int vn, int nn, int cn) {
  if (vn == 3) return nn ? with_colour<3, 3>(cn) : with_colour<3, 0>(cn);
  if (vn == 4) return nn ? with_colour<4, 3>(cn) : with_colour<4, 0>(cn);
  return nullptr;
}

}  // namespace

bool Context::draw_soup(GLint first, GLsizei count) {
  const ClientArray va = vertex_array_, na = normal_array_, ca = color_array_;
  if (count < kSoupMin || va.repeated || !float_arrays()) return false;
  const bool normals = lighting_ && na.enabled, colours = ca.enabled;
  const int vn = va.size, cn = colours ? ca.size : 0, nn = normals ? 3 : 0;
  const int record = vn + nn + cn;  // floats per distinct corner
  const FindRepeats find_in = find_repeats_for(vn, nn, cn);
  if (!find_in) return false;
  const size_t corners = size_t(count) / 3 * 3;
  const int shares = count >= kSoupParallel && threads_ > 1 ? workers().size() : 1;
  const size_t table = size_t(1) << kSoupSlotBits;
  const size_t share_words = table * size_t(slot_pairs(11));  // room for the widest layout
  if (soup_slots_.size() < size_t(shares) * share_words) soup_slots_.assign(size_t(shares) * share_words, 0);
  if (++soup_generation_ == 0) {  // wrapped: no slot may look current
    std::fill(soup_slots_.begin(), soup_slots_.end(), 0);
    soup_generation_ = 1;
  }
  soup_index_.resize(corners);
  soup_staged_.resize(corners * size_t(record));
  // Distinct corners found before each share (shares <= Workers::kMax): no allocation per draw.
  std::array<uint32_t, pool::Workers::kMax + 1> distinct{};
  const auto bounds = [&](int s) { return corners * size_t(s) / size_t(shares) / 3 * 3; };
  const Source src[3] = {source(va), source(na), source(ca)};
  // Share s: corners [bounds(s), bounds(s + 1)), its distinct ones staged from bounds(s) on.
  auto find = [&](int s) {
    const size_t lo = bounds(s);
    distinct[size_t(s) + 1] = find_in(src, first, lo, bounds(s + 1), soup_slots_.data() + size_t(s) * share_words,
                                      soup_generation_, soup_index_.data(), soup_staged_.data() + lo * size_t(record));
  };
  const float* compact = soup_staged_.data();
  if (shares == 1) {
    find(0);
  } else {
    pool::Workers& w = workers();
    w.run(find, shares);
    for (int s = 0; s < shares; ++s) distinct[size_t(s) + 1] += distinct[size_t(s)];
    // Each share's distinct corners after the shares before it, its indices moved with them.
    soup_compact_.resize(size_t(distinct[size_t(shares)]) * size_t(record));
    w.run([&](int s) {
      const uint32_t base = distinct[size_t(s)], n = distinct[size_t(s) + 1] - base;
      const size_t lo = bounds(s), hi = bounds(s + 1);
      std::memcpy(soup_compact_.data() + size_t(base) * size_t(record), soup_staged_.data() + lo * size_t(record),
                  size_t(n) * size_t(record) * 4);
      for (size_t c = lo; c < hi; ++c) soup_index_[c] += base;
    }, shares);
    compact = soup_compact_.data();
  }
  // The stage reads the distinct corners as the client's arrays, the same floats.
  const auto stride = GLsizei(record * 4);
  vertex_array_ = {true, vn, GL_FLOAT, stride, compact, false};
  if (normals) normal_array_ = {true, 3, GL_FLOAT, stride, compact + vn, false};
  if (colours) color_array_ = {true, cn, GL_FLOAT, stride, compact + vn + nn, false};
  arrays_to_list(0, GLint(distinct[size_t(shares)]));
  vertex_array_ = va, normal_array_ = na, color_array_ = ca;
  draw_triangle_list(soup_index_.data(), corners / 3);
  return true;
}

}  // namespace ffc::state
