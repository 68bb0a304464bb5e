#include "triangle_boxes.h"

#include <algorithm>
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
