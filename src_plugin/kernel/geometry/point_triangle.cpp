#include "geometry/point_triangle.h"

#include <algorithm>

namespace tri {

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d &p, const Eigen::Vector3d &a,
                                          const Eigen::Vector3d &b, const Eigen::Vector3d &c) {
  using V = Eigen::Vector3d;
  const V ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const V bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + (d1 / (d1 - d3)) * ab;
  const V cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) { // zero area: the closest of the three edges
    auto on_segment = [&p](const V &s, const V &t) {
      const V d = t - s;
      const double len2 = d.squaredNorm();
      const double u = len2 > 0.0 ? std::min(1.0, std::max(0.0, (p - s).dot(d) / len2)) : 0.0;
      return V(s + u * d);
    };
    V best = on_segment(a, b);
    for (const V &q : {on_segment(b, c), on_segment(c, a)})
      if ((q - p).squaredNorm() < (best - p).squaredNorm())
        best = q;
    return best;
  }
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

} // namespace tri
