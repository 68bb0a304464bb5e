#include "triangle_boxes.h"

#include <algorithm>

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
#pragma omp simd
    for (int t = 0; t < n; ++t) {
      const double v0 = c[3 * t], v1 = c[3 * t + 1], v2 = c[3 * t + 2];
      l[t] = std::min(v0, std::min(v1, v2));
      h[t] = std::max(v0, std::max(v1, v2));
    }
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

} // namespace tri
