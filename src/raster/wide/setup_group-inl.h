// A group of a list's triangles set up at once, a triangle a lane (kGroup: 8 where a vector holds
// eight floats, AVX2 and AVX-512; 4 on SSE4 and NEON), for the box kernel of kernels-inl.h: the
// edges of setup_edges and KernelEdgesOf, llvmpipe's depth plane (setup.h depth_plane) and the
// planes of smooth_planes (triangle_list.cpp), the same operations in the same order lane by
// lane, so the same bits. For states drawn smooth without secondary colour, culling or two-sided
// lighting (what smooth_planes covers). Included per target by triangle_list_wide.cpp, hence the
// toggled guard.
#if defined(FFCOMPAT_RASTER_WIDE_SETUP_GROUP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FFCOMPAT_RASTER_WIDE_SETUP_GROUP_INL_H_
#undef FFCOMPAT_RASTER_WIDE_SETUP_GROUP_INL_H_
#else
#define FFCOMPAT_RASTER_WIDE_SETUP_GROUP_INL_H_
#endif

#include <hwy/highway.h>

#include "raster/triangle_list_parts.h"
#include "raster/wide/kernels.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::raster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Vector targets with doubles: the others draw triangle by triangle.
#undef FFCOMPAT_SETUP_GROUP
#if HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128 && HWY_HAVE_FLOAT64
#define FFCOMPAT_SETUP_GROUP 1

using GroupF = hn::CappedTag<float, 8>;
constexpr size_t kGroup = hn::MaxLanes(GroupF());
static_assert(kGroup == 4 || kGroup == 8, "groups of a 128-bit or a 256-bit vector");

// What draws a lane (SetupGroup::kind): bits.
enum LaneKind : int32_t { kClippedLane = 1, kTinyLane = 2, kBoxLane = 4, kSwapLane = 8 };

struct SetupGroup {
  alignas(64) int32_t edges[kEdgeFields][kGroup];  // KernelEdges, stride kGroup
  alignas(64) float z[3][kGroup];                  // depth_plane's
  alignas(64) float f[kPlaneFloats][kGroup];       // KernelPlanes' f
  alignas(64) int32_t cover[kGroup];  // of a tiny lane: bits for (0,0) (1,0) (0,1) (1,1) from the box's corner
  unsigned box;   // lanes for the box kernel: box at most 8x8, vertex extents below 31 pixels
  unsigned none;  // lanes that cover no pixel centre
  unsigned ok;    // lanes whose planes are within float (the others are not drawn)
  unsigned tiny;  // box lanes of at most 2x2 pixel centres (their coverage in `cover`)
  alignas(64) int32_t kind[kGroup];  // a lane's LaneKind bits from SetupEdges (kClippedLane: the caller's)
};

template <class D>
HWY_INLINE unsigned MaskBits(D d, hn::Mask<D> m) {
  uint8_t b[8] = {};
  hn::StoreMaskBits(d, m, b);
  return b[0];
}

// Four rows of four lanes made columns, in each 128-bit block: lanes interleaved, then pairs.
template <class DF, class V>
HWY_INLINE void TransposeBlocks(DF df, V& a, V& b, V& c, V& d) {
  const hn::Repartition<uint64_t, DF> d64;
  const V t0 = hn::InterleaveLower(df, a, b), t1 = hn::InterleaveUpper(df, a, b);
  const V t2 = hn::InterleaveLower(df, c, d), t3 = hn::InterleaveUpper(df, c, d);
  auto lo = [&](V x, V y) { return hn::BitCast(df, hn::InterleaveLower(d64, hn::BitCast(d64, x), hn::BitCast(d64, y))); };
  auto hi = [&](V x, V y) { return hn::BitCast(df, hn::InterleaveUpper(d64, hn::BitCast(d64, x), hn::BitCast(d64, y))); };
  a = lo(t0, t2), b = hi(t0, t2), c = lo(t1, t3), d = hi(t1, t3);
}

// The eight floats of each lane's vertex (x, y down, z, w, r, g, b, a), one vector an attribute.
HWY_INLINE void VertexColumns(const ShadedVertex* hot, const int32_t (&corner)[kGroup], hn::Vec<GroupF> (&out)[8]) {
  const GroupF df;
  if constexpr (kGroup == 8) {  // 256-bit: both 128-bit halves of a row transposed, then joined
    hn::Vec<GroupF> r[8];
    for (size_t k = 0; k < 8; ++k) r[k] = hn::Load(df, &hot[corner[k]].x);
    TransposeBlocks(df, r[0], r[1], r[2], r[3]);
    TransposeBlocks(df, r[4], r[5], r[6], r[7]);
    for (int a = 0; a < 4; ++a) out[a] = hn::ConcatLowerLower(df, r[4 + a], r[a]), out[4 + a] = hn::ConcatUpperUpper(df, r[4 + a], r[a]);
  } else {
    for (int h = 0; h < 2; ++h) {
      hn::Vec<GroupF> r[4];
      for (size_t k = 0; k < 4; ++k) r[k] = hn::Load(df, &hot[corner[k]].x + 4 * h);
      TransposeBlocks(df, r[0], r[1], r[2], r[3]);
      for (int a = 0; a < 4; ++a) out[4 * h + a] = r[a];
    }
  }
}

// The triangles' edges from their snapped corners: the box, its coverage, which kernel draws
// each lane (box, none, tiny, cover, edges); returns the lanes whose vertices 1 and 2 SetupPlanes
// exchanges (counter-clockwise).
HWY_INLINE unsigned SetupEdges(const ListVertices& vs, const int32_t (&corner)[3][kGroup], int fb_w, int fb_h, SetupGroup& out) {
  const hn::RebindToSigned<GroupF> di;
  using VI = hn::Vec<decltype(di)>;
  // Snapped positions: box, extents, area.
  const int32_t* snapped = &vs.snapped.data()->x;
  VI sx[3], sy[3];
  for (int c = 0; c < 3; ++c) {
    const VI at = hn::ShiftLeft<1>(hn::Load(di, corner[c]));
    sx[c] = hn::GatherIndex(di, snapped, at), sy[c] = hn::GatherIndex(di, snapped + 1, at);
  }
  const VI xlo = hn::Min(sx[0], hn::Min(sx[1], sx[2])), xhi = hn::Max(sx[0], hn::Max(sx[1], sx[2]));
  const VI ylo = hn::Min(sy[0], hn::Min(sy[1], sy[2])), yhi = hn::Max(sy[0], hn::Max(sy[1], sy[2]));
  const VI zero = hn::Zero(di), k127 = hn::Set(di, 127), k128 = hn::Set(di, 128);
  // First pixel centre at or after the low end, last at or before the high end, in the framebuffer.
  const VI xmin = hn::Max(zero, hn::ShiftRight<8>(hn::Add(xlo, k127))), ymin = hn::Max(zero, hn::ShiftRight<8>(hn::Add(ylo, k127)));
  const VI xmax = hn::Min(hn::Set(di, fb_w - 1), hn::ShiftRight<8>(hn::Sub(xhi, k128)));
  const VI ymax = hn::Min(hn::Set(di, fb_h - 1), hn::ShiftRight<8>(hn::Sub(yhi, k128)));
  const auto empty = hn::Or(hn::Gt(xmin, xmax), hn::Gt(ymin, ymax));
  const hn::RebindToUnsigned<GroupF> du;
  const auto limit = hn::Set(du, 31 * 256);
  const VI seven = hn::Set(di, 7);
  const auto narrow = hn::And(hn::Lt(hn::BitCast(du, hn::Sub(xhi, xlo)), limit), hn::Lt(hn::BitCast(du, hn::Sub(yhi, ylo)), limit));
  const auto small = hn::AndNot(empty, hn::And(hn::RebindMask(di, narrow),
                                               hn::And(hn::Not(hn::Gt(hn::Sub(xmax, xmin), seven)), hn::Not(hn::Gt(hn::Sub(ymax, ymin), seven)))));
  // 32 bits hold the area of a small triangle.
  const VI area = hn::Sub(hn::Mul(hn::Sub(sx[1], sx[0]), hn::Sub(sy[2], sy[0])), hn::Mul(hn::Sub(sx[2], sx[0]), hn::Sub(sy[1], sy[0])));
  const auto flat = hn::Eq(area, zero);
  out.none = MaskBits(di, hn::Or(empty, hn::And(small, flat)));
  out.box = MaskBits(di, hn::AndNot(flat, small));
  // Counter-clockwise: vertices 1 and 2 exchanged where the area is negative.
  const auto swap = hn::Lt(area, zero);
  const unsigned swap_bits = MaskBits(di, swap);
  auto exchange = [&](VI& a, VI& b) {
    const VI a2 = hn::IfThenElse(swap, b, a);
    b = hn::IfThenElse(swap, a, b), a = a2;
  };
  exchange(sx[1], sx[2]), exchange(sy[1], sy[2]);
  hn::Store(xmin, di, out.edges[kXmin]), hn::Store(ymin, di, out.edges[kYmin]);
  hn::Store(xmax, di, out.edges[kXmax]), hn::Store(ymax, di, out.edges[kYmax]);
  const VI ox = hn::Add(hn::ShiftLeft<8>(xmin), k128), oy = hn::Add(hn::ShiftLeft<8>(ymin), k128);
  const auto all = hn::FirstN(di, kGroup);
  hn::Mask<decltype(di)> in[4] = {all, all, all, all};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const VI ex = hn::Sub(sx[k], sx[j]), ey = hn::Sub(sy[k], sy[j]);
    const VI e0 = hn::Sub(hn::Mul(ex, hn::Sub(oy, sy[j])), hn::Mul(ey, hn::Sub(ox, sx[j])));
    // pixel_rules.h's owns_centres_on_edge, lane by lane: the limit -1 where it owns them, else 0.
    const VI lim = hn::VecFromMask(di, hn::Or(hn::Lt(ey, zero), hn::And(hn::Eq(ey, zero), hn::Gt(ex, zero))));
    const VI px = hn::ShiftLeft<8>(hn::Neg(ey)), py = hn::ShiftLeft<8>(ex);
    hn::Store(e0, di, out.edges[kE0 + i]), hn::Store(px, di, out.edges[kPerX + i]);
    hn::Store(py, di, out.edges[kPerY + i]), hn::Store(lim, di, out.edges[kLimit + i]);
    // The box's four first centres, as BoxCover tests them (e > limit).
    in[0] = hn::And(in[0], hn::Gt(e0, lim)), in[1] = hn::And(in[1], hn::Gt(hn::Add(e0, px), lim));
    in[2] = hn::And(in[2], hn::Gt(hn::Add(e0, py), lim)), in[3] = hn::And(in[3], hn::Gt(hn::Add(e0, hn::Add(px, py)), lim));
  }
  const auto one_col = hn::Eq(xmin, xmax), one_row = hn::Eq(ymin, ymax);
  in[1] = hn::AndNot(one_col, in[1]), in[2] = hn::AndNot(one_row, in[2]), in[3] = hn::AndNot(hn::Or(one_col, one_row), in[3]);
  VI cover = zero;
  for (int q = 0; q < 4; ++q) cover = hn::Or(cover, hn::IfThenElseZero(in[q], hn::Set(di, 1 << q)));
  hn::Store(cover, di, out.cover);
  const VI k1 = hn::Set(di, 1);
  const auto tiny = hn::And(hn::Not(hn::Gt(hn::Sub(xmax, xmin), k1)), hn::Not(hn::Gt(hn::Sub(ymax, ymin), k1)));
  out.tiny = out.box & MaskBits(di, tiny);
  const auto box = hn::AndNot(flat, small);
  hn::Store(hn::Or(hn::IfThenElseZero(swap, hn::Set(di, kSwapLane)),
                   hn::IfThenElseZero(box, hn::IfThenElse(tiny, hn::Set(di, kTinyLane | kBoxLane), hn::Set(di, kBoxLane)))),
            di, out.kind);
  return swap_bits;
}

// The depth plane and the smooth planes of the triangles of corner[c][lane], vertices 1 and 2
// exchanged in the lanes of swap_bits (SetupEdges' result).
HWY_INLINE void SetupPlanes(const ListVertices& vs, const int32_t (&corner)[3][kGroup], int fb_h, unsigned swap_bits, SetupGroup& out) {
  const GroupF df;
  const hn::RebindToSigned<GroupF> di;
  using VF = hn::Vec<GroupF>;
  uint8_t swap_byte = uint8_t(swap_bits);
  const auto swap = hn::RebindMask(di, hn::LoadMaskBits(df, &swap_byte));
  // Window positions and colours, an attribute a vector.
  VF v[3][8];  // x, y down, z, w, r, g, b, a
  for (int c = 0; c < 3; ++c) VertexColumns(vs.hot.data(), corner[c], v[c]);
  {  // depth_plane, lane by lane: llvmpipe's order is (0, 1, 2), or (1, 0, 2) where swapped
    const auto fswap = hn::RebindMask(df, swap);
    const VF x0 = hn::IfThenElse(fswap, v[1][0], v[0][0]), x1 = hn::IfThenElse(fswap, v[0][0], v[1][0]), x2 = v[2][0];
    const VF y0 = hn::IfThenElse(fswap, v[1][1], v[0][1]), y1 = hn::IfThenElse(fswap, v[0][1], v[1][1]), y2 = v[2][1];
    const VF z0 = hn::IfThenElse(fswap, v[1][2], v[0][2]), z1 = hn::IfThenElse(fswap, v[0][2], v[1][2]), z2 = v[2][2];
    const VF half = hn::Set(df, 0.5f);
    const VF x0c = hn::Sub(x0, half), y0c = hn::Sub(y0, half);
    const VF dx01 = hn::Sub(x0, x1), dy01 = hn::Sub(y0, y1), dx20 = hn::Sub(x2, x0), dy20 = hn::Sub(y2, y0);
    const VF ooa = hn::Div(hn::Set(df, 1.0f), hn::Sub(hn::Mul(dx01, dy20), hn::Mul(dy01, dx20)));
    const VF dx20o = hn::Mul(dx20, ooa), dy20o = hn::Mul(dy20, ooa), dx01o = hn::Mul(dx01, ooa), dy01o = hn::Mul(dy01, ooa);
    const VF da01 = hn::Sub(z0, z1), da20 = hn::Sub(z2, z0);
    const VF dzdx = hn::Sub(hn::Mul(da01, dy20o), hn::Mul(da20, dy01o));
    const VF dzdy = hn::Sub(hn::Mul(da20, dx01o), hn::Mul(da01, dx20o));
    hn::Store(hn::Sub(z0, hn::Add(hn::Mul(dzdx, x0c), hn::Mul(dzdy, y0c))), df, out.z[0]);
    hn::Store(dzdx, df, out.z[1]), hn::Store(dzdy, df, out.z[2]);
  }
  // smooth_planes in double, kParts vectors of doubles a group. The inputs stored as floats
  // (y counted up, as map_float's GL y), read back a part at a time.
  alignas(64) float in_f[3][7][kGroup];  // x, y up, w, r, g, b, a
  const VF fbh = hn::Set(df, float(fb_h));
  for (int c = 0; c < 3; ++c) {
    const VF row[7] = {v[c][0], hn::Sub(fbh, v[c][1]), v[c][3], v[c][4], v[c][5], v[c][6], v[c][7]};
    for (int a = 0; a < 7; ++a) hn::Store(row[a], df, in_f[c][a]);
  }
  const hn::CappedTag<double, kGroup> dd;
  constexpr size_t kPart = hn::MaxLanes(decltype(dd)());
  const hn::CappedTag<float, kPart> dh;  // the floats of a part
  using VD = hn::Vec<decltype(dd)>;
  unsigned ok = 0;
  for (size_t part = 0; part < kGroup / kPart; ++part) {
    const size_t at = part * kPart;
    const uint8_t swap_part = uint8_t(swap_bits >> at);
    const auto dswap = hn::LoadMaskBits(dd, &swap_part);
    VD w[3][7];
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 7; ++a) w[c][a] = hn::PromoteTo(dd, hn::Load(dh, &in_f[c][a][at]));
    for (int a = 0; a < 7; ++a) {
      const VD w1 = hn::IfThenElse(dswap, w[2][a], w[1][a]);
      w[2][a] = hn::IfThenElse(dswap, w[1][a], w[2][a]), w[1][a] = w1;
    }
    // PlaneSolver, lane by lane.
    const VD x0 = w[0][0], y0 = w[0][1];
    const VD x1 = hn::Sub(w[1][0], x0), y1 = hn::Sub(w[1][1], y0), x2 = hn::Sub(w[2][0], x0), y2 = hn::Sub(w[2][1], y0);
    const VD det = hn::Sub(hn::Mul(x1, y2), hn::Mul(x2, y1));
    const VD one = hn::Set(dd, 1.0);
    const VD inv = hn::IfThenZeroElse(hn::Eq(det, hn::Zero(dd)), hn::Div(one, det));  // a NaN det keeps 1/det
    VD a[3][5];  // 1/w, r/w, g/w, b/w, a/w
    for (int c = 0; c < 3; ++c) {
      const VD iw = hn::Div(one, w[c][2]);
      a[c][0] = iw;
      for (int k = 0; k < 4; ++k) a[c][1 + k] = hn::Mul(w[c][3 + k], iw);
    }
    auto probe = hn::Zero(dh);
    for (int q = 0; q < 5; ++q) {
      const VD d1 = hn::Sub(a[1][q], a[0][q]), d2 = hn::Sub(a[2][q], a[0][q]);
      const VD p1 = hn::Mul(hn::Sub(hn::Mul(d1, y2), hn::Mul(d2, y1)), inv);
      const VD p2 = hn::Mul(hn::Sub(hn::Mul(x1, d2), hn::Mul(x2, d1)), inv);
      const VD p0 = hn::Sub(hn::Sub(a[0][q], hn::Mul(p1, x0)), hn::Mul(p2, y0));
      const VD p[3] = {p0, p1, p2};
      for (int m = 0; m < 3; ++m) {
        const auto f = hn::DemoteTo(dh, p[m]);
        probe = hn::Add(probe, hn::Mul(f, hn::Zero(dh)));  // x * 0 is NaN unless x is finite
        hn::Store(f, dh, &out.f[q == 0 ? m : 3 + 4 * m + (q - 1)][at]);
      }
    }
    ok |= MaskBits(dh, hn::Not(hn::IsNaN(probe))) << at;
  }
  out.ok = ok;
}

#endif  // vector targets with doubles

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // the toggled guard
