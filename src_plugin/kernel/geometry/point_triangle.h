// The point of a triangle closest to a point (Voronoi regions of the corners, edges and face;
// Ericson, Real-Time Collision Detection, 5.1.5). Exact for any non-degenerate triangle; for a
// degenerate one (zero area) it returns a point of the triangle's edges closest to p, as the
// regions collapse onto them. Lengths in any unit.
#pragma once

#include <Eigen/Core>

namespace tri {

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d &p, const Eigen::Vector3d &a,
                                          const Eigen::Vector3d &b, const Eigen::Vector3d &c);

} // namespace tri
