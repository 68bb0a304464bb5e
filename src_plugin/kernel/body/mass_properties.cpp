#include "body/mass_properties.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

namespace tri {

namespace {

// Flips v so that its component of largest magnitude is positive (ties: lowest index).
Eigen::Vector3d sign_fixed(const Eigen::Vector3d &v) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[i]) > std::abs(v[k]))
      k = i;
  return v[k] < 0 ? Eigen::Vector3d(-v) : v;
}

// The unit vector perpendicular to unit u closest to a coordinate axis: the projection of
// the axis along which u has its smallest component (ties: lowest index).
Eigen::Vector3d nearest_axis_perpendicular(const Eigen::Vector3d &u) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(u[i]) < std::abs(u[k]))
      k = i;
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
  return (e - e.dot(u) * u).normalized();
}

} // namespace

void principal_frame(const Eigen::Matrix3d &inertia, Eigen::Vector3d &moments,
                     Eigen::Matrix3d &axes) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  moments = solver.eigenvalues(); // ascending
  const Eigen::Matrix3d &v = solver.eigenvectors();
  const double tol = kDegenerateMomentTolerance * moments.cwiseAbs().maxCoeff();
  const bool low_pair = moments[1] - moments[0] <= tol;
  const bool high_pair = moments[2] - moments[1] <= tol;
  if ((low_pair && high_pair) || moments[2] - moments[0] <= tol) {
    axes.setIdentity(); // every direction is principal: keep the mesh's axes
    moments.setConstant(moments.mean());
  } else if (low_pair) {
    moments.head<2>().setConstant(0.5 * (moments[0] + moments[1]));
    const Eigen::Vector3d unique = sign_fixed(v.col(2));
    axes.col(0) = nearest_axis_perpendicular(unique);
    axes.col(1) = unique.cross(axes.col(0));
    axes.col(2) = unique;
  } else if (high_pair) {
    moments.tail<2>().setConstant(0.5 * (moments[1] + moments[2]));
    const Eigen::Vector3d unique = sign_fixed(v.col(0));
    axes.col(0) = unique;
    axes.col(1) = nearest_axis_perpendicular(unique);
    axes.col(2) = unique.cross(axes.col(1));
  } else {
    axes.col(0) = sign_fixed(v.col(0));
    axes.col(1) = sign_fixed(v.col(1));
    axes.col(2) = axes.col(0).cross(axes.col(1));
  }
}

MassProperties mass_properties(const TriangleMesh &mesh) {
  MassProperties mp;
  if (mesh.vertices.empty())
    return mp;
  // Moments are accumulated about the vertex average, which lies near the centre of mass,
  // so the parallel-axis shift below cancels few digits even for a mesh far from the origin.
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d &p : mesh.vertices)
    reference += p;
  reference /= static_cast<double>(mesh.vertices.size());

  double six_volume = 0.0;                          // sum of det[a b c]
  Eigen::Vector3d first = Eigen::Vector3d::Zero();  // 24 x integral r dV
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero(); // 120 x integral r r^T dV
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const Eigen::Vector3d a = mesh.corner(t, 0) - reference;
    const Eigen::Vector3d b = mesh.corner(t, 1) - reference;
    const Eigen::Vector3d c = mesh.corner(t, 2) - reference;
    const double det = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    six_volume += det;
    first += det * s;
    // Tetrahedron (0, a, b, c): integral r r^T dV = det/120 (a a^T + b b^T + c c^T + s s^T).
    second += det * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  mp.volume = six_volume / 6.0;
  const Eigen::Vector3d com = first / (24.0 * mp.volume);
  const Eigen::Matrix3d covariance = second / 120.0 - mp.volume * com * com.transpose();
  mp.centre_of_mass = reference + com;
  mp.inertia_per_density = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
  principal_frame(mp.inertia_per_density, mp.principal_moments, mp.principal_axes);
  return mp;
}

} // namespace tri
