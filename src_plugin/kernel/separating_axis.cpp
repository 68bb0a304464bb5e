#include "separating_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

Extent soa_extent(const TriangleSoA &t, const Eigen::Vector3d &n) {
  const std::size_t count = t.x.size();
  const double *x = t.x.data(), *y = t.y.data(), *z = t.z.data();
  const double nx = n.x(), ny = n.y(), nz = n.z();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, m = 0.0;
  if (!t.distinct.empty()) { // each vertex once: the same extent, a third to a sixth the reads
    const int *index = t.distinct.data();
    const std::size_t distinct = t.distinct.size();
#pragma omp simd reduction(min : lo) reduction(max : hi, m)
    for (std::size_t k = 0; k < distinct; ++k) {
      const int i = index[k];
      const double s = nx * x[i] + ny * y[i] + nz * z[i];
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      m = std::max(m, std::max(std::fabs(x[i]), std::max(std::fabs(y[i]), std::fabs(z[i]))));
    }
    return {lo, hi, m};
  }
#pragma omp simd reduction(min : lo) reduction(max : hi, m)
  for (std::size_t i = 0; i < count; ++i) {
    const double s = nx * x[i] + ny * y[i] + nz * z[i];
    lo = std::min(lo, s);
    hi = std::max(hi, s);
    m = std::max(m, std::max(std::fabs(x[i]), std::max(std::fabs(y[i]), std::fabs(z[i]))));
  }
  return {lo, hi, m};
}

double proven_gap(const TriangleSoA &a, const TriangleSoA &b, const Eigen::Vector3d &axis,
                  double cutoff) {
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length) || a.x.empty() || b.x.empty())
    return -std::numeric_limits<double>::infinity();
  const Eigen::Vector3d n = axis / length;
  const Extent ea = soa_extent(a, n), eb = soa_extent(b, n);
  const double slack = kSeparationSlackRatio * (ea.magnitude + eb.magnitude + std::fabs(cutoff));
  const double gap = eb.lo - ea.hi - slack;
  return std::isfinite(gap) ? gap : -std::numeric_limits<double>::infinity();
}

} // namespace tri
