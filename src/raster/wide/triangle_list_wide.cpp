// The triangle lists' draw loop and binning (triangle_list.cpp's draw_bins and bin_range)
// compiled once per Highway target: the kernels of kernels-inl.h inlined into the loop (no call per
// triangle), triangles set up a group at a time where the state allows it (setup_group-inl.h), and
// binned a vector of triangles at a time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/wide/triangle_list_wide.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <climits>
#include <cstring>

#include "raster/triangle_list_parts.h"
#include "raster/wide/kernels-inl.h"
#include "raster/wide/setup_group-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::raster::detail::HWY_NAMESPACE {

template <DepthMode Mode>
uint64_t DrawOne(const List& l, const Bands& mine, const std::array<size_t, 3>& vi, const Snapped (&p)[3]) {
  Triangle t;
  bool back, swapped;
  std::array<size_t, 3> order;
  if (!setup_one(l, vi, p, t, back, swapped, order)) return 0;
  return Rasterize<Mode>(l.fb, t, l.s.depth_func, mine, [&] { return list_planes(l, vi, t, back, swapped, order); });
}

template <DepthMode Mode>
void DrawBins(const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  uint64_t nonfinite = 0;
  for_each_binned(l, mine, in, counts, shares, [&](const std::array<size_t, 3>& vi, const Snapped (&p)[3]) { nonfinite += DrawOne<Mode>(l, mine, vi, p); });
  count_nonfinite(l.s, nonfinite);
}

#if FFCOMPAT_SETUP_GROUP
// The corners of the list entries [0, lanes) (lanes past them repeat the last), built as vectors
// (the setup loads them as vectors, which lane-by-lane stores would stall). Returns the lanes to
// clip. Corner numbers in 31 bits and twice them in 32 (the caller checks).
HWY_INLINE unsigned GroupCorners(const List& l, const uint32_t* entries, size_t lanes, int32_t (&corner)[3][kGroup]) {
  const hn::RebindToSigned<GroupF> di;
  const hn::RebindToUnsigned<GroupF> du;
  const auto entry = hn::IfThenElse(hn::FirstN(du, lanes), hn::LoadU(du, entries), hn::Set(du, entries[lanes - 1]));
  const auto tri = hn::BitCast(di, hn::And(entry, hn::Set(du, ~kClipped)));
  const auto first = hn::Add(tri, hn::Add(tri, tri));  // 3 tri
  for (int k = 0; k < 3; ++k) {
    const auto c = l.idx ? hn::GatherIndex(di, reinterpret_cast<const int32_t*>(l.idx) + k, first)
                         : hn::Add(first, hn::Set(di, int32_t(3 * l.base) + k));
    hn::Store(c, di, corner[k]);
  }
  return MaskBits(di, hn::Lt(hn::BitCast(di, entry), hn::Zero(di)));
}

// The triangles of a group that draw something, queued in order for their planes (SetupPlanes,
// the costlier half of the setup): at depth 7 nearly half of an icosphere's triangles cover no
// pixel centre, and their planes were solved for nothing. A lane's edges, coverage and kind come
// from SetupEdges, moved into the queue a vector at a time (compressed); its planes are solved
// with the next kGroup queued lanes. Triangles are drawn in the order they come, as before.
struct Queue {
  static constexpr size_t kCap = 2 * kGroup;  // below kGroup before a group joins: room for a whole vector
  alignas(64) int32_t corner[3][kCap];
  alignas(64) int32_t edges[kEdgeFields][kCap];
  alignas(64) int32_t cover[kCap];
  alignas(64) int32_t kind[kCap];
  size_t n = 0;
};

// For each mask of kGroup lanes, the lanes it holds in order (the rest 0): a compression by a
// table lookup. (Highway's CompressStore on AVX2 copied a table of its own onto the stack at every
// call: the frame twice as slow.)
struct CompressTable {
  alignas(64) int32_t lanes[1u << kGroup][kGroup];
  constexpr CompressTable() : lanes{} {
    for (unsigned m = 0; m < (1u << kGroup); ++m)
      for (unsigned lane = 0, k = 0; lane < kGroup; ++lane)
        if (m >> lane & 1) lanes[m][k++] = int32_t(lane);
  }
};
static constexpr CompressTable kCompress{};

// Draws `count` lanes (count <= kGroup) of the triangles of `corner`, their edges and coverage in
// rows laid out `stride` apart: the queue's first, or, after the queue, a group's own where every
// lane draws (the queue's moves cost more than they save where the triangles are larger: depth 5).
// swap: the lanes whose vertices 1 and 2 SetupEdges exchanged; planes: the lanes the box kernels
// draw, whose planes are solved.
template <DepthMode Mode>
uint64_t DrawLanes(const List& l, const Bands& mine, const int32_t (&corner)[3][kGroup], const int32_t* edges,
                   const int32_t* cover, const int32_t* kinds, size_t stride, size_t count, unsigned swap, unsigned planes) {
  SetupGroup g;
  if (planes) SetupPlanes(l.vs, corner, l.fb.height, swap, g);
  uint64_t nonfinite = 0;
  const GLenum func = l.s.depth_func;
  for (size_t lane = 0; lane < count; ++lane) {
    const std::array<size_t, 3> vi = {size_t(corner[0][lane]), size_t(corner[1][lane]), size_t(corner[2][lane])};
    const KernelPlanes kp{&g.z[0][lane], &g.f[0][lane], int(kGroup)};
    const int32_t k = kinds[lane];
    if (k & kClippedLane) {
      draw_clipped(l, vi, mine);
    } else if (k & (kTinyLane | kBoxLane)) {
      if (!(g.ok >> lane & 1)) continue;  // not drawn, as smooth_planes decides
      const int xmin = edges[kXmin * stride + lane], ymin = edges[kYmin * stride + lane];
      const int w = edges[kXmax * stride + lane] - xmin + 1;
      if (k & kTinyLane) {
        unsigned bits = unsigned(cover[lane]);
        if (!mine.owns(ymin / kBandRows)) bits &= 0xC;
        if (!mine.owns((ymin + 1) / kBandRows)) bits &= 0x3;
        if (bits) nonfinite += TinyShade<Mode>(l.fb, kp, xmin, ymin, w, bits, func);
      }
      else nonfinite += BoxDraw<Mode>(l.fb, {edges + lane, int(stride)}, kp, mine, func);
    } else {
      const Snapped p[3] = {l.vs.snapped[vi[0]], l.vs.snapped[vi[1]], l.vs.snapped[vi[2]]};
      nonfinite += DrawOne<Mode>(l, mine, vi, p);
    }
  }
  return nonfinite;
}

// Draws the first `count` queued lanes and moves the rest to the front.
template <DepthMode Mode>
uint64_t DrawQueued(const List& l, const Bands& mine, Queue& q, size_t count) {
  const hn::RebindToSigned<GroupF> di;
  alignas(64) int32_t corner[3][kGroup];
  for (int c = 0; c < 3; ++c) {
    hn::Store(hn::Load(di, q.corner[c]), di, corner[c]);
    for (size_t lane = count; lane < kGroup; ++lane) corner[c][lane] = corner[c][count - 1];  // lanes past the end repeat the last
  }
  // The lanes whose vertices 1 and 2 swap, and those whose planes the box kernels read.
  const auto kind = hn::Load(di, q.kind);
  const unsigned lanes = (1u << count) - 1;
  const auto has = [&](int32_t bits, int32_t want) {
    return MaskBits(di, hn::Eq(hn::And(kind, hn::Set(di, bits)), hn::Set(di, want))) & lanes;
  };
  const uint64_t nonfinite = DrawLanes<Mode>(l, mine, corner, &q.edges[0][0], q.cover, q.kind, Queue::kCap, count,
                                             has(kSwapLane, kSwapLane), has(kClippedLane | kBoxLane, kBoxLane));
  q.n -= count;
  if (q.n > 0) {  // fewer than kGroup: a vector a row
    auto front = [&](int32_t* row) { hn::Store(hn::LoadU(di, row + count), di, row); };
    for (auto& row : q.corner) front(row);
    for (auto& row : q.edges) front(row);
    front(q.cover), front(q.kind);
  }
  return nonfinite;
}

// draw_bins for states the grouped setup covers (setup_group-inl.h): kGroup triangles' edges at once, the lanes that draw
// queued, each then drawn by the box kernel (nearly all of a subdivided sphere's) or, larger, by
// Rasterize.
template <DepthMode Mode>
void DrawBinsGrouped(const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  const hn::RebindToSigned<GroupF> di;
  uint64_t nonfinite = 0;
  Queue q;
  for (int share = 0; share < shares; ++share) {
    const uint32_t* list = in[share];
    const size_t n = counts[share];
    for (size_t e = 0; e < n; e += kGroup) {
      const size_t lanes = std::min(kGroup, n - e);
      for (size_t a = e + kGroup; a < std::min(e + 2 * kGroup, n); ++a)
        for (size_t v : l.corners(list[a] & ~kClipped)) __builtin_prefetch(&l.vs.snapped[v]), __builtin_prefetch(&l.vs.hot[v]);
      alignas(64) int32_t corner[3][kGroup];
      const unsigned clipped = GroupCorners(l, list + e, lanes, corner);
      SetupGroup g;
      const unsigned swap = SetupEdges(l.vs, corner, l.fb.width, l.fb.height, g);
      // A lane draws unless it covers no pixel centre: most tiny ones (at most 2x2 centres, their
      // coverage known) at high subdivision. (Whether this thread's bands hold them is asked as
      // they are drawn: a tiny triangle across two bands is rare.)
      const unsigned uncovered = MaskBits(di, hn::Eq(hn::Load(di, g.cover), hn::Zero(di)));
      const unsigned keep = (clipped | ((g.box | ~g.none) & ~(g.tiny & uncovered))) & ((1u << lanes) - 1);
      if (!keep) continue;
      for (unsigned c = clipped & ((1u << lanes) - 1); c; c &= c - 1) g.kind[__builtin_ctz(c)] |= kClippedLane;
      const int32_t* kind = g.kind;
      if (keep == (1u << kGroup) - 1) {  // every lane draws: the queue first, then the group as it is
        if (q.n > 0) nonfinite += DrawQueued<Mode>(l, mine, q, q.n);
        nonfinite += DrawLanes<Mode>(l, mine, corner, &g.edges[0][0], g.cover, kind, kGroup, kGroup, swap, g.box & ~clipped);
        continue;
      }
      const auto order = hn::SetTableIndices(di, kCompress.lanes[keep]);
      auto push = [&](const int32_t* from, int32_t* to) { hn::StoreU(hn::TableLookupLanes(hn::Load(di, from), order), di, to + q.n); };
      for (int c = 0; c < 3; ++c) push(corner[c], q.corner[c]);
      for (int f = 0; f < kEdgeFields; ++f) push(g.edges[f], q.edges[f]);
      push(g.cover, q.cover), push(kind, q.kind);
      q.n += size_t(__builtin_popcount(keep));
      if (q.n >= kGroup) nonfinite += DrawQueued<Mode>(l, mine, q, kGroup);
    }
  }
  if (q.n > 0) nonfinite += DrawQueued<Mode>(l, mine, q, q.n);
  count_nonfinite(l.s, nonfinite);
}
#endif

void DrawBinsWide(DepthMode mode, const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
#if FFCOMPAT_SETUP_GROUP
  const State& s = l.s;
  // Corner numbers, three times a triangle's and twice a corner's in 31 bits: vectors of them.
  const bool fits = 3 * (l.base + l.count) < size_t(INT32_MAX) && l.vs.snapped.size() <= size_t(INT32_MAX / 2);
  if (fits && !s.flat && !s.add_secondary && !s.cull && !s.two_side) {
    switch (mode) {
      case kNoDepth: return DrawBinsGrouped<kNoDepth>(l, mine, in, counts, shares);
      case kLess: return DrawBinsGrouped<kLess>(l, mine, in, counts, shares);
      case kLequal: return DrawBinsGrouped<kLequal>(l, mine, in, counts, shares);
      case kAnyDepth: return DrawBinsGrouped<kAnyDepth>(l, mine, in, counts, shares);
    }
  }
#endif
  switch (mode) {
    case kNoDepth: return DrawBins<kNoDepth>(l, mine, in, counts, shares);
    case kLess: return DrawBins<kLess>(l, mine, in, counts, shares);
    case kLequal: return DrawBins<kLequal>(l, mine, in, counts, shares);
    case kAnyDepth: return DrawBins<kAnyDepth>(l, mine, in, counts, shares);
  }
}

// bin_range's binning a vector of triangles at a time (lanes are triangles); returns the first
// triangle not binned (fewer than a vector remain).
size_t BinWide(const List& l, size_t first, size_t last, int units, uint32_t** out) {
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  (void)l, (void)last, (void)units, (void)out;
  return first;
#else
  static_assert((kBandRows & (kBandRows - 1)) == 0, "bands by a shift");
  constexpr int kShift = __builtin_ctz(kBandRows);
  const hn::ScalableTag<int32_t> di;
  const hn::RebindToUnsigned<decltype(di)> du;
  const hn::RebindToFloat<decltype(di)> df;
  using VI = hn::Vec<decltype(di)>;
  const size_t n = hn::Lanes(di);
  static_assert(hn::MaxLanes(decltype(di)()) <= kBinSlack, "the lists have room for a vector's store past their end");
  const VI lane = hn::Iota(di, 0), three = hn::Set(di, 3);
  const VI k127 = hn::Set(di, 127), k128 = hn::Set(di, 128), zero = hn::Zero(di);
  const VI last_col = hn::Set(di, l.fb.width - 1), last_row = hn::Set(di, l.fb.height - 1);
  const VI not_mapped = hn::Set(di, kNotMapped), span = hn::Set(di, units - 1), vunits = hn::Set(di, units);
  const auto per_unit = hn::Set(df, 1.0f / float(units));
  const int32_t* snapped = &l.vs.snapped.data()->x;
  size_t tri = first;
  for (; tri + n <= last; tri += n) {
    VI c[3];
    if (l.idx) {
      hn::Vec<decltype(du)> u[3];
      hn::LoadInterleaved3(du, l.idx + 3 * tri, u[0], u[1], u[2]);
      for (int k = 0; k < 3; ++k) c[k] = hn::BitCast(di, u[k]);
    } else {
      for (int k = 0; k < 3; ++k) c[k] = hn::Add(hn::Set(di, int32_t(3 * (l.base + tri)) + k), hn::Mul(lane, three));
    }
    VI x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      const VI at = hn::ShiftLeft<1>(c[k]);
      x[k] = hn::GatherIndex(di, snapped, at), y[k] = hn::GatherIndex(di, snapped + 1, at);
    }
    const auto clipped = hn::Or(hn::Or(hn::Eq(x[0], not_mapped), hn::Eq(x[1], not_mapped)), hn::Eq(x[2], not_mapped));
    const VI ylo = hn::Min(y[0], hn::Min(y[1], y[2])), yhi = hn::Max(y[0], hn::Max(y[1], y[2]));
    const VI xlo = hn::Min(x[0], hn::Min(x[1], x[2])), xhi = hn::Max(x[0], hn::Max(x[1], x[2]));
    const VI row_lo = hn::Max(zero, hn::ShiftRight<8>(hn::Add(ylo, k127))), row_hi = hn::Min(last_row, hn::ShiftRight<8>(hn::Sub(yhi, k128)));
    const VI col_lo = hn::Max(zero, hn::ShiftRight<8>(hn::Add(xlo, k127))), col_hi = hn::Min(last_col, hn::ShiftRight<8>(hn::Sub(xhi, k128)));
    const auto keep = hn::AndNot(clipped, hn::Not(hn::Or(hn::Gt(row_lo, row_hi), hn::Gt(col_lo, col_hi))));
    const VI band_lo = hn::ShiftRight<kShift>(row_lo);
    const VI bands = hn::Min(hn::Sub(hn::ShiftRight<kShift>(row_hi), band_lo), span);  // met, less one
    // band_lo % units: the quotient of (band_lo + 0.5) / units is never near a whole number.
    const VI q = hn::ConvertTo(di, hn::Mul(hn::Add(hn::ConvertTo(df, band_lo), hn::Set(df, 0.5f)), per_unit));
    const VI first_owner = hn::Sub(band_lo, hn::Mul(q, vunits));
    const VI ids = hn::Add(hn::Set(di, int32_t(tri)), lane);
    const VI marked = hn::IfThenElse(clipped, hn::Or(ids, hn::Set(di, int32_t(kClipped))), ids);
    for (int o = 0; o < units; ++o) {
      // Owner o's distance past the first owner, around the units.
      VI d = hn::Sub(hn::Set(di, o), first_owner);
      d = hn::IfThenElse(hn::Lt(d, zero), hn::Add(d, vunits), d);
      const auto mine = hn::Or(clipped, hn::AndNot(hn::Gt(d, bands), keep));
#if FFCOMPAT_SETUP_GROUP
      if constexpr (hn::MaxLanes(decltype(di)()) == kGroup) {
        // Eight lanes or four (AVX2, SSE4, NEON): compressed by a table lookup, as the setup's queue
        // is (Highway's Compress on AVX2 copied its table onto the stack at every call).
        const unsigned bits = MaskBits(di, mine);
        hn::StoreU(hn::TableLookupLanes(marked, hn::SetTableIndices(di, kCompress.lanes[bits])), di,
                   reinterpret_cast<int32_t*>(out[o]));
        out[o] += unsigned(__builtin_popcount(bits));
        continue;
      }
#endif
      // Compress, then a plain store: Zen 4 runs AVX-512's compressing store to memory slowly.
      hn::StoreU(hn::Compress(marked, mine), di, reinterpret_cast<int32_t*>(out[o]));
      out[o] += hn::CountTrue(di, mine);
    }
  }
  return tri;
#endif
}

// map_one a vector of vertices at a time (lanes are vertices): outside_planes and map_float's
// operations in the same order, the products and sums in float, the multiply-adds fused. A vector
// with a lane map_one would find too far out (|snapped| from 2^29, or NaN: beyond the range the
// conversion rounds in) is left to map_one, lane by lane.
size_t MapListWide(ListVertices& vs, size_t first, size_t end, const State& s, const float* const* front) {
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  (void)vs, (void)end, (void)s, (void)front;
  return first;
#else
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  using VF = hn::Vec<decltype(df)>;
  const size_t n = hn::Lanes(df);
  const glm::ivec4 vp = s.viewport;
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f, fbh = float(s.fb_height);
  const float near = float(s.depth_range.x), far = float(s.depth_range.y);
  const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), half = hn::Set(df, 0.5f), k256 = hn::Set(df, 256.0f);
  const VF x_scale = hn::Set(df, hw), x_add = hn::Set(df, float(vp[0]) + hw);
  const VF y_scale = hn::Set(df, -hh), y_add = hn::Set(df, fbh - (float(vp[1]) + hh));
  const VF z_scale = hn::Set(df, (far - near) * 0.5f), z_add = hn::Set(df, (far + near) * 0.5f);
  const VF limit = hn::Set(df, 0x1p29f), tiny = hn::Set(df, 0x1p-126f), huge = hn::Set(df, 0x1p126f);
  const auto k128 = hn::Set(di, 128), top = hn::Set(di, (s.fb_height - 1) * 256 + 128);
  const auto not_mapped = hn::Set(di, kNotMapped), zero_i = hn::Zero(di);
  alignas(64) float window[4 * kMaxLanes32], colour[4 * kMaxLanes32];  // a vertex's x, y, z, w and r, g, b, a
  size_t i = first;
  for (; i + n <= end; i += n) {
    if (front) {  // the front colours, interleaved for the 32-byte records
      const size_t j = i - first;
      hn::StoreInterleaved4(hn::LoadU(df, front[0] + j), hn::LoadU(df, front[1] + j), hn::LoadU(df, front[2] + j),
                            hn::LoadU(df, front[3] + j), df, colour);
      for (size_t k = 0; k < n; ++k) std::memcpy(&vs.hot[i + k].color, colour + 4 * k, 4 * sizeof(float));
    }
    VF X, Y, Z, W;
    hn::LoadInterleaved4(df, &vs.clip[i].x, X, Y, Z, W);
    const VF neg_w = hn::Sub(zero, W);
    auto out = hn::Or(hn::Or(hn::Gt(X, W), hn::Lt(X, neg_w)), hn::Or(hn::Gt(Y, W), hn::Lt(Y, neg_w)));
    out = hn::Or(out, hn::Or(hn::Gt(Z, W), hn::Lt(Z, neg_w)));
    // A NaN or an infinity anywhere: x * 0 is NaN then.
    out = hn::Or(out, hn::IsNaN(hn::Add(hn::Add(hn::Mul(X, zero), hn::Mul(Y, zero)), hn::Add(hn::Mul(Z, zero), hn::Mul(W, zero)))));
    const VF aw = hn::Abs(W);
    out = hn::Or(out, hn::Or(hn::Le(W, zero), hn::Or(hn::Lt(aw, tiny), hn::Gt(aw, huge))));
    const VF inv_w = hn::Div(one, W);
    const VF x = FusedMulAdd(df, hn::Mul(X, inv_w), x_scale, x_add);
    const VF y_down = FusedMulAdd(df, hn::Mul(Y, inv_w), y_scale, y_add);
    const VF z = FusedMulAdd(df, hn::Mul(Z, inv_w), z_scale, z_add);
    const VF sxf = hn::Mul(hn::Sub(x, half), k256), syf = hn::Mul(hn::Sub(y_down, half), k256);
    const auto beyond = hn::Or(hn::Not(hn::Lt(hn::Abs(sxf), limit)), hn::Not(hn::Lt(hn::Abs(syf), limit)));
    if (!hn::AllFalse(df, hn::AndNot(out, beyond))) {
      for (size_t k = i; k < i + n; ++k) map_one(vs, k, s);
      continue;
    }
    const auto out_i = hn::RebindMask(di, out);
    const auto sx = hn::IfThenElse(out_i, not_mapped, hn::Add(hn::NearestInt(sxf), k128));
    const auto sy = hn::IfThenElse(out_i, zero_i, hn::Sub(top, hn::NearestInt(syf)));
    hn::StoreInterleaved2(sx, sy, di, &vs.snapped[i].x);
    hn::StoreInterleaved4(x, y_down, z, W, df, window);
    for (size_t k = 0; k < n; ++k) std::memcpy(&vs.hot[i + k].x, window + 4 * k, 4 * sizeof(float));
  }
  return i;
#endif
}

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::raster::detail {

HWY_EXPORT(DrawBinsWide);
HWY_EXPORT(BinWide);
HWY_EXPORT(MapListWide);

size_t map_list_wide(ListVertices& vs, size_t first, size_t end, const State& s, const float* const* front) {
  return HWY_DYNAMIC_DISPATCH(MapListWide)(vs, first, end, s, front);
}

void draw_bins_wide(DepthMode mode, const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  HWY_DYNAMIC_DISPATCH(DrawBinsWide)(mode, l, mine, in, counts, shares);
}

size_t bin_wide(const List& l, size_t first, size_t last, int units, uint32_t** out) {
  if (l.vs.snapped.size() > size_t(INT32_MAX / 2) || 3 * (l.base + last) >= size_t(INT32_MAX)) return first;  // 32-bit lanes
  return HWY_DYNAMIC_DISPATCH(BinWide)(l, first, last, units, out);
}

}  // namespace ffc::raster::detail
#endif  // HWY_ONCE
