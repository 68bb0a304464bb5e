#include "distance/triangle_boxes.h"

#include "distance/triangle_pair_block.h"
#include "geometry/distance_primitives.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

void compute_triangle_boxes(const TriangleSoA &soa, TriangleBoxes &boxes) {
  const int n = soa.num_triangles();
  for (auto *v : {&boxes.lo_x, &boxes.lo_y, &boxes.lo_z, &boxes.hi_x, &boxes.hi_y, &boxes.hi_z})
    v->resize(static_cast<std::size_t>(n));
  const double *coord[3] = {soa.x.data(), soa.y.data(), soa.z.data()};
  double *lo[3] = {boxes.lo_x.data(), boxes.lo_y.data(), boxes.lo_z.data()};
  double *hi[3] = {boxes.hi_x.data(), boxes.hi_y.data(), boxes.hi_z.data()};
  for (int axis = 0; axis < 3; ++axis) {
    const double *c = coord[axis];
    double *l = lo[axis], *h = hi[axis];
    double all_l = std::numeric_limits<double>::infinity();
    double all_h = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(min : all_l) reduction(max : all_h)
    for (int t = 0; t < n; ++t) {
      const double v0 = c[3 * t], v1 = c[3 * t + 1], v2 = c[3 * t + 2];
      const double lt = std::min(v0, std::min(v1, v2));
      const double ht = std::max(v0, std::max(v1, v2));
      l[t] = lt;
      h[t] = ht;
      all_l = std::min(all_l, lt);
      all_h = std::max(all_h, ht);
    }
    boxes.all_lo[axis] = all_l;
    boxes.all_hi[axis] = all_h;
  }
}

int overlapping_boxes(const TriangleBoxes &a, int i, const TriangleBoxes &b, double margin,
                      std::uint8_t *keep) {
  // Box i of a, grown by the margin on every side; then an ordinary interval test per axis.
  const double lx = a.lo_x[i] - margin, ly = a.lo_y[i] - margin, lz = a.lo_z[i] - margin;
  const double hx = a.hi_x[i] + margin, hy = a.hi_y[i] + margin, hz = a.hi_z[i] + margin;
  const double *blx = b.lo_x.data(), *bly = b.lo_y.data(), *blz = b.lo_z.data();
  const double *bhx = b.hi_x.data(), *bhy = b.hi_y.data(), *bhz = b.hi_z.data();
  const int n = b.num_triangles();
  int kept = 0;
#pragma omp simd reduction(+ : kept)
  for (int j = 0; j < n; ++j) {
    const bool overlap = (blx[j] <= hx) & (bhx[j] >= lx) & (bly[j] <= hy) & (bhy[j] >= ly) &
                         (blz[j] <= hz) & (bhz[j] >= lz);
    keep[j] = static_cast<std::uint8_t>(overlap);
    kept += overlap;
  }
  return kept;
}

namespace {

// Turns a 0/1 mask stored in index[0..n) into the list of set positions, in place and without
// branches: index[count] is written only at positions <= t, after mask[t] was read.
int compress_mask(int *index, int n) {
  int count = 0;
  for (int t = 0; t < n; ++t) {
    const int m = index[t];
    index[count] = t;
    count += m;
  }
  return count;
}

} // namespace

int boxes_near_box_as_a(const TriangleBoxes &a, const double lo[3], const double hi[3],
                        double margin, int *index) {
  // The pair test keeps (i, j) only if b.lo[j] <= a.hi[i] + m and b.hi[j] >= a.lo[i] - m;
  // b.lo[j] >= lo and b.hi[j] <= hi, so it needs lo <= a.hi[i] + m and hi >= a.lo[i] - m.
  const int n = a.num_triangles();
  const double *alx = a.lo_x.data(), *aly = a.lo_y.data(), *alz = a.lo_z.data();
  const double *ahx = a.hi_x.data(), *ahy = a.hi_y.data(), *ahz = a.hi_z.data();
  const double lx = lo[0], ly = lo[1], lz = lo[2], hx = hi[0], hy = hi[1], hz = hi[2];
  // The mask goes through the caller's index buffer (int, same width), then is compressed
  // in place: index[count] is written only at positions <= t, after mask[t] is read.
  std::int32_t *mask = reinterpret_cast<std::int32_t *>(index);
#pragma omp simd
  for (int t = 0; t < n; ++t)
    mask[t] = (lx <= ahx[t] + margin) & (hx >= alx[t] - margin) & (ly <= ahy[t] + margin) &
              (hy >= aly[t] - margin) & (lz <= ahz[t] + margin) & (hz >= alz[t] - margin);
  return compress_mask(index, n);
}

int boxes_near_box_as_b(const double lo[3], const double hi[3], const TriangleBoxes &b,
                        double margin, int *index) {
  // Needs b.lo[j] <= a.hi[i] + m <= hi + m and b.hi[j] >= a.lo[i] - m >= lo - m (rounding
  // is monotone, so the inequalities hold in floating point as well).
  const int n = b.num_triangles();
  const double *blx = b.lo_x.data(), *bly = b.lo_y.data(), *blz = b.lo_z.data();
  const double *bhx = b.hi_x.data(), *bhy = b.hi_y.data(), *bhz = b.hi_z.data();
  const double lx = lo[0] - margin, ly = lo[1] - margin, lz = lo[2] - margin;
  const double hx = hi[0] + margin, hy = hi[1] + margin, hz = hi[2] + margin;
  std::int32_t *mask = reinterpret_cast<std::int32_t *>(index);
#pragma omp simd
  for (int t = 0; t < n; ++t)
    mask[t] = (blx[t] <= hx) & (bhx[t] >= lx) & (bly[t] <= hy) & (bhy[t] >= ly) &
              (blz[t] <= hz) & (bhz[t] >= lz);
  return compress_mask(index, n);
}

int cull_triangle_pairs(const TriangleBoxes &a, const TriangleBoxes &b, double margin,
                        CullScratch &s, std::vector<TrianglePairIndex> &pairs) {
  const int na = a.num_triangles(), nb = b.num_triangles();
  s.index_a.resize(static_cast<std::size_t>(na));
  s.index_b.resize(static_cast<std::size_t>(nb));
  const int sb = boxes_near_box_as_b(a.all_lo, a.all_hi, b, margin, s.index_b.data());
  if (sb == 0)
    return 0;
  const int sa = boxes_near_box_as_a(a, b.all_lo, b.all_hi, margin, s.index_a.data());
  if (sa == 0)
    return 0;

  // Compact the boxes of b's survivors (SoA), so that stage 2 runs contiguous simd rows.
  for (auto *v : {&s.lo_x, &s.lo_y, &s.lo_z, &s.hi_x, &s.hi_y, &s.hi_z})
    if (v->size() < static_cast<std::size_t>(sb))
      v->resize(static_cast<std::size_t>(sb));
  if (s.keep.size() < static_cast<std::size_t>(sb))
    s.keep.resize(static_cast<std::size_t>(sb));
  const int *ib = s.index_b.data();
  double *clx = s.lo_x.data(), *cly = s.lo_y.data(), *clz = s.lo_z.data();
  double *chx = s.hi_x.data(), *chy = s.hi_y.data(), *chz = s.hi_z.data();
  for (int k = 0; k < sb; ++k) {
    const int j = ib[k];
    clx[k] = b.lo_x[j];
    cly[k] = b.lo_y[j];
    clz[k] = b.lo_z[j];
    chx[k] = b.hi_x[j];
    chy[k] = b.hi_y[j];
    chz[k] = b.hi_z[j];
  }

  // Stage 2: the pair test of overlapping_boxes, same expressions, among survivors.
  std::int32_t *keep = s.keep.data();
  int count = 0;
  for (int r = 0; r < sa; ++r) {
    // A row writes (branch-free) up to sb entries past `count`.
    if (pairs.size() < static_cast<std::size_t>(count) + sb)
      pairs.resize(std::max(2 * pairs.size(), static_cast<std::size_t>(count) + sb));
    TrianglePairIndex *row = pairs.data() + count;
    const int i = s.index_a[r];
    const double lx = a.lo_x[i] - margin, ly = a.lo_y[i] - margin, lz = a.lo_z[i] - margin;
    const double hx = a.hi_x[i] + margin, hy = a.hi_y[i] + margin, hz = a.hi_z[i] + margin;
#pragma omp simd
    for (int k = 0; k < sb; ++k)
      keep[k] = (clx[k] <= hx) & (chx[k] >= lx) & (cly[k] <= hy) & (chy[k] >= ly) &
                (clz[k] <= hz) & (chz[k] >= lz);
    int kept = 0;
    for (int k = 0; k < sb; ++k) {
      row[kept] = {i, ib[k]};
      kept += keep[k];
    }
    count += kept;
  }
  return count;
}

} // namespace tri

namespace tri {

namespace {

// Stage 1 of the two-frame cull for one side: mask[t] &= (box t of `boxes` overlaps the
// whole box [lo, hi] of the other body), grown as the pair test grows them; `as_a` says on
// which side of the pair test this body stands.
void and_near_box(const TriangleBoxes &boxes, const double lo[3], const double hi[3], double margin,
                  bool as_a, std::int32_t *mask) {
  const int n = boxes.num_triangles();
  const double *bl[3] = {boxes.lo_x.data(), boxes.lo_y.data(), boxes.lo_z.data()};
  const double *bh[3] = {boxes.hi_x.data(), boxes.hi_y.data(), boxes.hi_z.data()};
  if (as_a) {
    const double lx = lo[0], ly = lo[1], lz = lo[2], hx = hi[0], hy = hi[1], hz = hi[2];
#pragma omp simd
    for (int t = 0; t < n; ++t)
      mask[t] &= (lx <= bh[0][t] + margin) & (hx >= bl[0][t] - margin) & (ly <= bh[1][t] + margin) &
                 (hy >= bl[1][t] - margin) & (lz <= bh[2][t] + margin) & (hz >= bl[2][t] - margin);
  } else {
    const double lx = lo[0] - margin, ly = lo[1] - margin, lz = lo[2] - margin;
    const double hx = hi[0] + margin, hy = hi[1] + margin, hz = hi[2] + margin;
#pragma omp simd
    for (int t = 0; t < n; ++t)
      mask[t] &= (bl[0][t] <= hx) & (bh[0][t] >= lx) & (bl[1][t] <= hy) & (bh[1][t] >= ly) &
                 (bl[2][t] <= hz) & (bh[2][t] >= lz);
  }
}

} // namespace

int cull_triangle_pairs_two_frames(const TriangleBoxes &a, const TriangleBoxes &b,
                                   const TriangleBoxes &fa, const TriangleBoxes &fb, double margin,
                                   double frame_margin, CullScratch &s,
                                   std::vector<TrianglePairIndex> &pairs,
                                   const std::uint8_t *skip_b) {
  const int na = a.num_triangles(), nb = b.num_triangles();
  s.index_a.resize(static_cast<std::size_t>(na));
  s.index_b.resize(static_cast<std::size_t>(nb));
  std::int32_t *mask_b = reinterpret_cast<std::int32_t *>(s.index_b.data());
  if (skip_b)
    for (int t = 0; t < nb; ++t)
      mask_b[t] = skip_b[t] == 0;
  else
    std::fill(mask_b, mask_b + nb, 1);
  and_near_box(b, a.all_lo, a.all_hi, margin, false, mask_b);
  and_near_box(fb, fa.all_lo, fa.all_hi, frame_margin, false, mask_b);
  const int sb = compress_mask(s.index_b.data(), nb);
  if (sb == 0)
    return 0;
  std::int32_t *mask_a = reinterpret_cast<std::int32_t *>(s.index_a.data());
  std::fill(mask_a, mask_a + na, 1);
  and_near_box(a, b.all_lo, b.all_hi, margin, true, mask_a);
  and_near_box(fa, fb.all_lo, fb.all_hi, frame_margin, true, mask_a);
  const int sa = compress_mask(s.index_a.data(), na);
  if (sa == 0)
    return 0;

  // Compact both frames' boxes of b's survivors: world in lo_x.., the frame's after them.
  const std::size_t need = 2 * static_cast<std::size_t>(sb);
  for (auto *v : {&s.lo_x, &s.lo_y, &s.lo_z, &s.hi_x, &s.hi_y, &s.hi_z})
    if (v->size() < need)
      v->resize(need);
  if (s.keep.size() < static_cast<std::size_t>(sb))
    s.keep.resize(static_cast<std::size_t>(sb));
  const int *ib = s.index_b.data();
  double *cl[3] = {s.lo_x.data(), s.lo_y.data(), s.lo_z.data()};
  double *ch[3] = {s.hi_x.data(), s.hi_y.data(), s.hi_z.data()};
  const double *wl[3] = {b.lo_x.data(), b.lo_y.data(), b.lo_z.data()};
  const double *wh[3] = {b.hi_x.data(), b.hi_y.data(), b.hi_z.data()};
  const double *fl[3] = {fb.lo_x.data(), fb.lo_y.data(), fb.lo_z.data()};
  const double *fh[3] = {fb.hi_x.data(), fb.hi_y.data(), fb.hi_z.data()};
  for (int k = 0; k < sb; ++k) {
    const int j = ib[k];
    for (int d = 0; d < 3; ++d) {
      cl[d][k] = wl[d][j];
      ch[d][k] = wh[d][j];
      cl[d][sb + k] = fl[d][j];
      ch[d][sb + k] = fh[d][j];
    }
  }
  const double *clx = cl[0], *cly = cl[1], *clz = cl[2], *chx = ch[0], *chy = ch[1], *chz = ch[2];
  const double *flx = cl[0] + sb, *fly = cl[1] + sb, *flz = cl[2] + sb;
  const double *fhx = ch[0] + sb, *fhy = ch[1] + sb, *fhz = ch[2] + sb;

  std::int32_t *keep = s.keep.data();
  int count = 0;
  for (int r = 0; r < sa; ++r) {
    if (pairs.size() < static_cast<std::size_t>(count) + sb)
      pairs.resize(std::max(2 * pairs.size(), static_cast<std::size_t>(count) + sb));
    TrianglePairIndex *row = pairs.data() + count;
    const int i = s.index_a[r];
    const double lx = a.lo_x[i] - margin, ly = a.lo_y[i] - margin, lz = a.lo_z[i] - margin;
    const double hx = a.hi_x[i] + margin, hy = a.hi_y[i] + margin, hz = a.hi_z[i] + margin;
    const double glx = fa.lo_x[i] - frame_margin, gly = fa.lo_y[i] - frame_margin,
                 glz = fa.lo_z[i] - frame_margin;
    const double ghx = fa.hi_x[i] + frame_margin, ghy = fa.hi_y[i] + frame_margin,
                 ghz = fa.hi_z[i] + frame_margin;
#pragma omp simd
    for (int k = 0; k < sb; ++k)
      keep[k] = (clx[k] <= hx) & (chx[k] >= lx) & (cly[k] <= hy) & (chy[k] >= ly) & (clz[k] <= hz) &
                (chz[k] >= lz) & (flx[k] <= ghx) & (fhx[k] >= glx) & (fly[k] <= ghy) &
                (fhy[k] >= gly) & (flz[k] <= ghz) & (fhz[k] >= glz);
    int kept = 0;
    for (int k = 0; k < sb; ++k) {
      row[kept] = {i, ib[k]};
      kept += keep[k];
    }
    count += kept;
  }
  return count;
}

void compute_triangle_planes(const TriangleSoA &soa, TrianglePlanes &p) {
  const int n = soa.num_triangles();
  for (auto *v : {&p.n_x, &p.n_y, &p.n_z, &p.offset})
    v->resize(static_cast<std::size_t>(n));
  const double *x = soa.x.data(), *y = soa.y.data(), *z = soa.z.data();
  double *nx = p.n_x.data(), *ny = p.n_y.data(), *nz = p.n_z.data(), *o = p.offset.data();
#pragma omp simd
  for (int t = 0; t < n; ++t) {
    const double ux = x[3 * t + 1] - x[3 * t], uy = y[3 * t + 1] - y[3 * t],
                 uz = z[3 * t + 1] - z[3 * t];
    const double vx = x[3 * t + 2] - x[3 * t], vy = y[3 * t + 2] - y[3 * t],
                 vz = z[3 * t + 2] - z[3 * t];
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    const double len = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double inv = len > 0.0 ? 1.0 / len : 0.0;
    nx[t] = cx * inv;
    ny[t] = cy * inv;
    nz[t] = cz * inv;
    o[t] = nx[t] * x[3 * t] + ny[t] * y[3 * t] + nz[t] * z[3 * t];
  }
}

namespace {

// The gap of the two triangles along axis n (not normalised), compared with margin * |n|:
// true when every vertex of one lies more than margin beyond every vertex of the other.
TRI_INLINE bool apart_along(geom::P3 n, const geom::P3 a[3], const geom::P3 b[3], double margin) {
  const double a0 = geom::dot(n, a[0]), a1 = geom::dot(n, a[1]), a2 = geom::dot(n, a[2]);
  const double b0 = geom::dot(n, b[0]), b1 = geom::dot(n, b[1]), b2 = geom::dot(n, b[2]);
  const double amin = std::min(a0, std::min(a1, a2)), amax = std::max(a0, std::max(a1, a2));
  const double bmin = std::min(b0, std::min(b1, b2)), bmax = std::max(b0, std::max(b1, b2));
  const double gap = std::max(bmin - amax, amin - bmax);
  // gap > margin |n| without a square root (a call GCC will not vectorise under errno rules)
  return (gap > 0.0) & (gap * gap > margin * margin * geom::dot(n, n));
}

// The same along n = ea x eb for an edge ea of a from vertex pa and an edge eb of b from pb,
// with qa, qb the third vertices: an edge's two ends project alike on n, so two projections
// per triangle. That holds to rounding only if n is not tiny against |ea| |eb| (edges far
// from parallel): axes with sin^2(angle) below 1e-12 are not used (conservative), and above
// it the ends differ by far less than the slack in `margin`.
TRI_INLINE bool apart_along_edges(geom::P3 ea, geom::P3 pa, geom::P3 qa, geom::P3 eb, geom::P3 pb,
                                  geom::P3 qb, double margin) {
  const geom::P3 n = geom::cross(ea, eb);
  const double n2 = geom::dot(n, n);
  const double a0 = geom::dot(n, pa), a1 = geom::dot(n, qa);
  const double b0 = geom::dot(n, pb), b1 = geom::dot(n, qb);
  const double gap =
      std::max(std::min(b0, b1) - std::max(a0, a1), std::min(a0, a1) - std::max(b0, b1));
  const bool usable = n2 > 1e-12 * geom::dot(ea, ea) * geom::dot(eb, eb);
  return usable & (gap > 0.0) & (gap * gap > margin * margin * n2);
}

// One lane of the separating-axis filter: 1 if the pair of lane l is proven farther apart
// than `margin` along a face normal or an edge-edge cross product. Coordinates relative to
// a's first vertex (smaller magnitudes, smaller rounding).
TRI_INLINE void sat_lane(const double (*c)[kPairLanes], int l, double margin, int *apart) {
  using geom::P3;
  const P3 o = {c[0][l], c[1][l], c[2][l]};
  const P3 a[3] = {
      {0.0, 0.0, 0.0}, P3{c[3][l], c[4][l], c[5][l]} - o, P3{c[6][l], c[7][l], c[8][l]} - o};
  const P3 b[3] = {P3{c[9][l], c[10][l], c[11][l]} - o, P3{c[12][l], c[13][l], c[14][l]} - o,
                   P3{c[15][l], c[16][l], c[17][l]} - o};
  // edge k runs from vertex k to vertex k + 1; the third vertex is k + 2
  const P3 ea[3] = {a[1] - a[0], a[2] - a[1], a[0] - a[2]};
  const P3 eb[3] = {b[1] - b[0], b[2] - b[1], b[0] - b[2]};
  // Written out: nested loops inside the lane stop GCC from vectorising across lanes.
  const bool faces = apart_along(geom::cross(ea[0], ea[1]), a, b, margin) |
                     apart_along(geom::cross(eb[0], eb[1]), a, b, margin);
#define TRI_EDGES(i, j)                                                                            \
  apart_along_edges(ea[i], a[i], a[(i + 2) % 3], eb[j], b[j], b[(j + 2) % 3], margin)
  const bool edges0 = TRI_EDGES(0, 0) | TRI_EDGES(0, 1) | TRI_EDGES(0, 2);
  const bool edges1 = TRI_EDGES(1, 0) | TRI_EDGES(1, 1) | TRI_EDGES(1, 2);
  const bool edges2 = TRI_EDGES(2, 0) | TRI_EDGES(2, 1) | TRI_EDGES(2, 2);
#undef TRI_EDGES
  apart[l] = faces | edges0 | edges1 | edges2;
}

} // namespace

int separating_axis_filter(const TriangleSoA &a, const TriangleSoA &b, double margin,
                           TrianglePairIndex *pairs, int count) {
  TrianglePairBlock block;
  alignas(64) int apart[kPairLanes];
  int kept = 0;
  for (int first = 0; first < count; first += kPairLanes) {
    const int n = std::min(kPairLanes, count - first);
    for (int l = 0; l < n; ++l)
      block.set_lane(l, a, pairs[first + l].a, b, pairs[first + l].b);
    for (int l = n; l < kPairLanes; ++l)
      block.copy_lane(0, l);
#pragma omp simd
    for (int l = 0; l < kPairLanes; ++l)
      sat_lane(block.c, l, margin, apart);
    for (int l = 0; l < n; ++l) { // compacted in place: kept <= first + l
      const TrianglePairIndex p = pairs[first + l];
      pairs[kept] = p;
      kept += apart[l] == 0;
    }
  }
  return kept;
}

} // namespace tri
