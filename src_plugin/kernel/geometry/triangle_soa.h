// TriangleSoA: one particle's (or wall patch's) triangles as structure of arrays, the
// layout of the paper's section 3. Vertex k (0..2) of triangle t is at index 3*t + k of
// x, y and z; vertices shared by several triangles are replicated so that a kernel reads
// each triangle with unit stride and no indirection. Arrays are 64-byte aligned.
#pragma once

#include "geometry/aligned_vector.h"
#include "geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace tri {

struct TriangleSoA {
  AlignedVector<double> x, y, z; // size 3 * num_triangles()
  // One index into x, y, z per distinct vertex of the mesh (its first copy), so that a pass
  // over the vertices (separating_axis.h: soa_extent) reads each once, not once per triangle
  // around it; empty where not known (every index counts). Kept by transform_soa (a vertex's
  // copies transform to the same bits); resize() clears it.
  std::vector<int> distinct;

  int num_triangles() const { return static_cast<int>(x.size() / 3); }
  void resize(int ntri) {
    distinct.clear();
    x.resize(3 * static_cast<std::size_t>(ntri));
    y.resize(3 * static_cast<std::size_t>(ntri));
    z.resize(3 * static_cast<std::size_t>(ntri));
  }
  Eigen::Vector3d vertex(int t, int k) const {
    const std::size_t i = 3 * static_cast<std::size_t>(t) + k;
    return {x[i], y[i], z[i]};
  }
  void set_vertex(int t, int k, const Eigen::Vector3d &p) {
    const std::size_t i = 3 * static_cast<std::size_t>(t) + k;
    x[i] = p.x();
    y[i] = p.y();
    z[i] = p.z();
  }
};

// Replicates an indexed mesh's vertices into SoA form, triangle order preserved.
TriangleSoA to_soa(const TriangleMesh &mesh);

// world = rotation * body + translation, for every vertex. `world` is resized as needed and
// keeps its capacity, so calling this every step allocates nothing after the first call.
void transform_soa(const TriangleSoA &body, const Eigen::Matrix3d &rotation,
                   const Eigen::Vector3d &translation, TriangleSoA &world);

} // namespace tri
