// An indexed triangle mesh: the form in which shapes are read, generated, validated and
// measured. Contact detection never sees it; it works on TriangleSoA (triangle_soa.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace tri {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;  // metres (or the file's unit before scaling)
  std::vector<std::array<int, 3>> triangles; // vertex indices, counter-clockwise seen from outside

  int num_triangles() const { return static_cast<int>(triangles.size()); }
  int num_vertices() const { return static_cast<int>(vertices.size()); }
  const Eigen::Vector3d &corner(int t, int k) const { return vertices[triangles[t][k]]; }
};

} // namespace tri
