// Small closed test meshes with known geometry, shared by the mesh, shape and mesh-file tests
// (tests/kernel and tests/io; the latter include it as "../kernel/test_meshes.h"). All are
// oriented with outward normals (counter-clockwise seen from outside) and built in a fixed
// order, so vertex and triangle indices are stable and tests may refer to them.
#pragma once

#include "body/shape_error.h"
#include "geometry/triangle_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tri_test {

// Box [0,a] x [0,b] x [0,c] (12 triangles); vertex i has x = a (i&1), y = b (i&2), z = c (i&4).
inline tri::TriangleMesh box(double a = 1, double b = 1, double c = 1) {
  tri::TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(a * (i & 1), b * ((i >> 1) & 1), c * ((i >> 2) & 1));
  m.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  return m;
}

// Unit right tetrahedron: corners 0, e_x, e_y, e_z (volume 1/6).
inline tri::TriangleMesh tetrahedron() {
  tri::TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// `m` with every vertex v replaced by r v + t.
inline tri::TriangleMesh transformed(tri::TriangleMesh m, const Eigen::Matrix3d &r,
                                     const Eigen::Vector3d &t) {
  for (auto &v : m.vertices)
    v = r * v + t;
  return m;
}

// An L-shaped prism (non-convex), extruded along z from the outline
// (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), height h. The caps are fans from corner (0,0), which
// sees the whole L.
inline tri::TriangleMesh l_prism(double h) {
  const double outline[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  tri::TriangleMesh m;
  for (double z : {0.0, h})
    for (const auto &p : outline)
      m.vertices.emplace_back(p[0], p[1], z);
  // Sides: outline counter-clockwise seen from +z, so (i, i+1, top i+1) faces outward.
  for (int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    m.triangles.push_back({i, j, j + 6});
    m.triangles.push_back({i, j + 6, i + 6});
  }
  // Top (+z, counter-clockwise).
  m.triangles.insert(m.triangles.end(), {{6, 7, 8}, {6, 8, 9}, {6, 9, 10}, {6, 10, 11}});
  // Bottom (-z): the same, reversed.
  m.triangles.insert(m.triangles.end(), {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}});
  return m;
}

// Splits every triangle of `m` (vertices on the unit sphere) into 4, `levels` times, pushing
// each new edge midpoint onto the unit sphere. Triangle count grows by 4^levels; an edge
// shared by two triangles gets one midpoint vertex.
inline void subdivide_onto_unit_sphere(tri::TriangleMesh &m, int levels) {
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = midpoint.find(key); it != midpoint.end())
        return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return midpoint[key] = m.num_vertices() - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto &t : m.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    m.triangles = std::move(finer);
  }
}

// Icosahedron inscribed in the unit sphere, each face subdivided into 4^level triangles
// whose new vertices are pushed onto the sphere (20 4^level triangles).
inline tri::TriangleMesh icosphere(int level) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  tri::TriangleMesh m;
  for (int s1 : {-1, 1})
    for (int s2 : {-1, 1}) {
      m.vertices.emplace_back(0, s1, s2 * phi);
      m.vertices.emplace_back(s1, s2 * phi, 0);
      m.vertices.emplace_back(s2 * phi, 0, s1);
    }
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k) {
        auto edge = [&](int p, int q) {
          return std::abs((m.vertices[p] - m.vertices[q]).norm() - 2.0) < 1e-9;
        };
        if (edge(i, j) && edge(j, k) && edge(i, k)) {
          const Eigen::Vector3d n =
              (m.vertices[j] - m.vertices[i]).cross(m.vertices[k] - m.vertices[i]);
          if (n.dot(m.vertices[i]) > 0)
            m.triangles.push_back({i, j, k});
          else
            m.triangles.push_back({i, k, j});
        }
      }
  for (auto &v : m.vertices)
    v.normalize();
  subdivide_onto_unit_sphere(m, level);
  return m;
}

// Octahedron inscribed in the unit sphere, subdivided like icosphere (8 4^level triangles).
inline tri::TriangleMesh octasphere(int level) {
  tri::TriangleMesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  subdivide_onto_unit_sphere(m, level);
  return m;
}

// The message of the tri::ShapeError that f() throws, or "" if it returns: lets a test
// check the wording of mesh and shape errors in one EXPECT.
template <class F> std::string shape_error_message(F &&f) {
  try {
    f();
  } catch (const tri::ShapeError &e) {
    return e.what();
  }
  return "";
}

} // namespace tri_test
