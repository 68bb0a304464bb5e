#include "geometry/triangle_soa.h"

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
  // The coefficients as locals: read through the references, g++ reloaded and broadcast all
  // twelve every iteration (a store to `world` might have changed them).
  const double r00 = rotation(0, 0), r01 = rotation(0, 1), r02 = rotation(0, 2);
  const double r10 = rotation(1, 0), r11 = rotation(1, 1), r12 = rotation(1, 2);
  const double r20 = rotation(2, 0), r21 = rotation(2, 1), r22 = rotation(2, 2);
  const double tx = translation.x(), ty = translation.y(), tz = translation.z();
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    wx[i] = r00 * bx[i] + r01 * by[i] + r02 * bz[i] + tx;
    wy[i] = r10 * bx[i] + r11 * by[i] + r12 * bz[i] + ty;
    wz[i] = r20 * bx[i] + r21 * by[i] + r22 * bz[i] + tz;
  }
}

} // namespace tri
