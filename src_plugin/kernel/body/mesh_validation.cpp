#include "body/mesh_validation.h"

#include "body/shape_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace tri {

namespace {

// One use of an undirected edge by a triangle. `forward` is true when the triangle walks
// the edge from its smaller to its larger vertex index.
struct EdgeUse {
  int lo, hi;
  int triangle;
  bool forward;
};

template <typename... Parts> [[noreturn]] void fail(const Parts &...parts) {
  std::ostringstream os;
  (os << ... << parts);
  throw ShapeError(os.str());
}

void check_counts_and_indices(const TriangleMesh &mesh) {
  if (mesh.num_triangles() < 4)
    fail("mesh has ", mesh.num_triangles(),
         " triangles; a closed surface needs at least 4 (a tetrahedron)");
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      if (v < 0 || v >= mesh.num_vertices())
        fail("triangle ", t, " refers to vertex ", v, ", but the mesh has ", mesh.num_vertices(),
             " vertices");
    }
}

void check_finite(const TriangleMesh &mesh) {
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector3d &p = mesh.vertices[v];
    if (!p.allFinite())
      fail("vertex ", v, " has a non-finite coordinate (", p.x(), ", ", p.y(), ", ", p.z(), ")");
  }
}

void check_degenerate(const TriangleMesh &mesh, double length_scale) {
  const double min_double_area = kDegenerateAreaTolerance * length_scale * length_scale;
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const auto &tr = mesh.triangles[t];
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2])
      fail("triangle ", t, " is degenerate: it uses a vertex twice (", tr[0], ", ", tr[1], ", ",
           tr[2], ")");
    const Eigen::Vector3d &a = mesh.vertices[tr[0]];
    const double double_area = (mesh.vertices[tr[1]] - a).cross(mesh.vertices[tr[2]] - a).norm();
    if (!(double_area >= min_double_area))
      fail("triangle ", t, " is degenerate: zero or near-zero area ", 0.5 * double_area,
           " (the limit is ", 0.5 * min_double_area, " = ", kDegenerateAreaTolerance,
           " x size^2 / 2, size = bounding-box diagonal ", length_scale, ")");
  }
}

// Sorted so that the uses of one edge are adjacent.
std::vector<EdgeUse> edge_uses(const TriangleMesh &mesh) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse &p, const EdgeUse &q) {
    return std::tie(p.lo, p.hi, p.triangle) < std::tie(q.lo, q.hi, q.triangle);
  });
  return uses;
}

// Every edge used exactly twice. Returns, for each triangle, the other triangle across each
// of its edges, plus whether the two walk the edge in the same direction.
struct Neighbour {
  int triangle;
  bool same_direction;
};
std::vector<std::vector<Neighbour>> check_closed(const TriangleMesh &mesh) {
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  std::vector<std::vector<Neighbour>> neighbours(mesh.triangles.size());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi)
      ++j;
    const EdgeUse &e = uses[i];
    if (j - i == 1)
      fail("mesh is not closed: edge (", e.lo, ", ", e.hi, ") of triangle ", e.triangle,
           " belongs to no other triangle (a hole or boundary)");
    if (j - i > 2) {
      std::ostringstream list;
      for (std::size_t k = i; k < j; ++k)
        list << (k > i ? ", " : "") << uses[k].triangle;
      fail("mesh is not closed (non-manifold): edge (", e.lo, ", ", e.hi, ") is shared by ", j - i,
           " triangles (", list.str(), "); each edge must belong to exactly two");
    }
    const EdgeUse &f = uses[i + 1];
    const bool same = e.forward == f.forward;
    neighbours[e.triangle].push_back({f.triangle, same});
    neighbours[f.triangle].push_back({e.triangle, same});
    i = j;
  }
  return neighbours;
}

// Flood fill over edge neighbours. A triangle's parity says whether it must be flipped to
// agree with the first triangle of its piece; a consistent mesh needs no flips.
void check_oriented_and_connected(const std::vector<std::vector<Neighbour>> &neighbours) {
  const int n = static_cast<int>(neighbours.size());
  std::vector<int> parity(n, -1);
  int pieces = 0;
  for (int seed = 0; seed < n; ++seed) {
    if (parity[seed] >= 0)
      continue;
    ++pieces;
    std::vector<int> piece{seed}, stack{seed};
    parity[seed] = 0;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (const Neighbour &nb : neighbours[t]) {
        const int want = parity[t] ^ static_cast<int>(nb.same_direction);
        if (parity[nb.triangle] < 0) {
          parity[nb.triangle] = want;
          piece.push_back(nb.triangle);
          stack.push_back(nb.triangle);
        } else if (parity[nb.triangle] != want) {
          fail("mesh is not orientable: no choice of triangle orientations makes triangles ", t,
               " and ", nb.triangle, " agree on their shared edge (a Moebius-like surface)");
        }
      }
    }
    // Name the minority: with one flipped triangle, that triangle.
    std::vector<int> flipped[2];
    for (int t : piece)
      flipped[parity[t]].push_back(t);
    if (!flipped[1].empty()) {
      std::vector<int> &odd = flipped[0].size() < flipped[1].size() ? flipped[0] : flipped[1];
      std::sort(odd.begin(), odd.end());
      std::ostringstream list;
      for (std::size_t k = 0; k < std::min<std::size_t>(odd.size(), 8); ++k)
        list << (k ? ", " : "") << odd[k];
      if (odd.size() > 8)
        list << ", ...";
      fail("mesh is inconsistently oriented: ", odd.size(),
           odd.size() == 1 ? " triangle is flipped relative to its neighbours (triangle "
                           : " triangles are flipped relative to their neighbours (triangles ",
           list.str(),
           "); neighbouring triangles must traverse their shared edge in opposite directions");
    }
  }
  if (pieces > 1)
    fail("mesh is not one connected piece: it has ", pieces,
         " pieces that share no edge (a particle must be a single solid)");
}

void check_outward(const TriangleMesh &mesh, double length_scale) {
  // Tetrahedra from a vertex of the mesh, not the origin, so that a mesh far from the
  // origin loses no digits.
  const Eigen::Vector3d origin = mesh.vertices[mesh.triangles[0][0]];
  double six_volume = 0.0;
  for (int t = 0; t < mesh.num_triangles(); ++t)
    six_volume += (mesh.corner(t, 0) - origin)
                      .dot((mesh.corner(t, 1) - origin).cross(mesh.corner(t, 2) - origin));
  const double volume = six_volume / 6.0;
  const double flat = kFlatVolumeTolerance * length_scale * length_scale * length_scale;
  if (!std::isfinite(volume) || !std::isfinite(flat))
    fail("mesh is too large to measure: its size (bounding-box diagonal) ", length_scale,
         " cubed is not a finite number; check the scale and the file's units");
  if (volume < -flat)
    fail("mesh is inverted (inside out): signed volume ", volume,
         " is negative; triangles must be counter-clockwise seen from outside (flip them all)");
  if (!(volume > flat))
    fail("mesh encloses zero or near-zero volume ", volume, " (the limit is ", flat, " = ",
         kFlatVolumeTolerance, " x size^3, size = bounding-box diagonal ", length_scale, ")");
}

} // namespace

double mesh_length_scale(const TriangleMesh &mesh) {
  if (mesh.vertices.empty())
    return 0.0;
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const Eigen::Vector3d &p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

void validate_mesh(const TriangleMesh &mesh) {
  check_counts_and_indices(mesh);
  check_finite(mesh);
  const double length_scale = mesh_length_scale(mesh);
  check_degenerate(mesh, length_scale);
  check_oriented_and_connected(check_closed(mesh));
  check_outward(mesh, length_scale);
}

} // namespace tri
