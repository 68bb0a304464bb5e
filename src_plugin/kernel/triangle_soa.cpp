#include "triangle_soa.h"

namespace tri {

TriangleSoA to_soa(const TriangleMesh &mesh) {
  TriangleSoA soa;
  soa.resize(mesh.num_triangles());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      soa.set_vertex(t, k, mesh.corner(t, k));
  std::vector<char> seen(mesh.vertices.size(), 0);
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (!seen[v]) {
        seen[v] = 1;
        soa.distinct.push_back(3 * t + k);
      }
    }
  return soa;
}

void transform_soa(const TriangleSoA &body, const Eigen::Matrix3d &rotation,
                   const Eigen::Vector3d &translation, TriangleSoA &world) {
  const std::size_t n = body.x.size();
  world.x.resize(n);
  world.y.resize(n);
  world.z.resize(n);
  world.distinct = body.distinct;
  const double *bx = body.x.data(), *by = body.y.data(), *bz = body.z.data();
  double *wx = world.x.data(), *wy = world.y.data(), *wz = world.z.data();
  const Eigen::Matrix3d &r = rotation;
  const Eigen::Vector3d &t = translation;
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    wx[i] = r(0, 0) * bx[i] + r(0, 1) * by[i] + r(0, 2) * bz[i] + t.x();
    wy[i] = r(1, 0) * bx[i] + r(1, 1) * by[i] + r(1, 2) * bz[i] + t.y();
    wz[i] = r(2, 0) * bx[i] + r(2, 1) * by[i] + r(2, 2) * bz[i] + t.z();
  }
}

} // namespace tri
