#include "body/inner_surface.h"

#include "body/shape_error.h"
#include "geometry/point_triangle.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace tri {

namespace {

using Eigen::Vector3d;

Vector3d unit_normal(const TriangleMesh &mesh, int t) {
  return (mesh.corner(t, 1) - mesh.corner(t, 0))
      .cross(mesh.corner(t, 2) - mesh.corner(t, 0))
      .normalized();
}

// The minimum-norm d with n_k . d = -layer for the rows of `rows` (1 to 3 normals), or false
// when they are dependent.
bool equality_offset(const Vector3d *rows[], int count, double layer, Vector3d &d) {
  Eigen::Matrix<double, 3, Eigen::Dynamic> a(3, count);
  for (int k = 0; k < count; ++k)
    a.col(k) = *rows[k];
  const Eigen::MatrixXd gram = a.transpose() * a;
  // A Gram determinant this small means the normals are (nearly) dependent: the subset's
  // solution is either another subset's or infinitely far.
  if (!(std::abs(gram.determinant()) > 1e-24))
    return false;
  const Eigen::VectorXd lambda = gram.ldlt().solve(Eigen::VectorXd::Constant(count, -layer));
  d = a * lambda;
  return d.allFinite();
}

// A grid of cells holding the triangles whose boxes, grown by `reach`, overlap them: the
// triangles within `reach` of a point are among those of its cell.
class TriangleGrid {
public:
  TriangleGrid(const TriangleMesh &mesh, double reach) : mesh_(mesh) {
    lo_ = hi_ = mesh.vertices.front();
    for (const Vector3d &p : mesh.vertices) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
    lo_.array() -= reach;
    hi_.array() += reach;
    // At most 48 cells a side: a fine layer on a large body must not cost a huge grid.
    cell_ = std::max(reach, (hi_ - lo_).maxCoeff() / 48.0);
    for (int k = 0; k < 3; ++k)
      n_[k] = std::max(1, static_cast<int>(std::ceil((hi_[k] - lo_[k]) / cell_)));
    cells_.resize(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2]);
    for (int t = 0; t < mesh.num_triangles(); ++t) {
      Vector3d a = mesh.corner(t, 0), b = a;
      for (int k = 1; k < 3; ++k) {
        a = a.cwiseMin(mesh.corner(t, k));
        b = b.cwiseMax(mesh.corner(t, k));
      }
      const Eigen::Array3i i0 = index(a.array() - reach), i1 = index(b.array() + reach);
      for (int x = i0[0]; x <= i1[0]; ++x)
        for (int y = i0[1]; y <= i1[1]; ++y)
          for (int z = i0[2]; z <= i1[2]; ++z)
            cells_[flat(x, y, z)].push_back(t);
    }
  }

  // The distance from p to the nearest triangle within reach (reach itself when none is),
  // and that triangle's index in `nearest` (-1 when none).
  double distance(const Vector3d &p, double reach, int &nearest) const {
    const Eigen::Array3i i = index(p.array());
    double best = reach;
    nearest = -1;
    for (int t : cells_[flat(i[0], i[1], i[2])]) {
      const double dist =
          (closest_point_on_triangle(p, mesh_.corner(t, 0), mesh_.corner(t, 1), mesh_.corner(t, 2)) -
           p)
              .norm();
      if (dist < best) {
        best = dist;
        nearest = t;
      }
    }
    return best;
  }

private:
  Eigen::Array3i index(const Eigen::Array3d &p) const {
    Eigen::Array3i i;
    for (int k = 0; k < 3; ++k)
      i[k] = std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_)), 0, n_[k] - 1);
    return i;
  }
  std::size_t flat(int x, int y, int z) const {
    return (static_cast<std::size_t>(x) * n_[1] + y) * n_[2] + z;
  }

  const TriangleMesh &mesh_;
  Vector3d lo_, hi_;
  double cell_ = 1.0;
  int n_[3] = {1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

std::string where(const Vector3d &p) {
  std::ostringstream os;
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}

// The inner mesh in `out`, or what is wrong (empty when nothing is).
std::string try_inner_surface(const TriangleMesh &mesh, double layer, TriangleMesh &out) {
  out = mesh;
  const int nv = mesh.num_vertices();
  std::vector<std::vector<Vector3d>> normals(static_cast<std::size_t>(nv));
  std::vector<Vector3d> face(static_cast<std::size_t>(mesh.num_triangles()));
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    face[t] = unit_normal(mesh, t);
    for (int v : mesh.triangles[t])
      normals[v].push_back(face[t]);
  }
  for (int v = 0; v < nv; ++v) {
    Vector3d d;
    if (!shortest_inward_offset(normals[v], layer, d))
      return "vertex " + std::to_string(v) + " at " + where(mesh.vertices[v]) +
             " joins faces that no point lies behind by the layer (a knife edge)";
    out.vertices[v] += d;
  }
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const Vector3d n = (out.corner(t, 1) - out.corner(t, 0)).cross(out.corner(t, 2) - out.corner(t, 0));
    if (!(n.dot(face[t]) > 0.0))
      return "triangle " + std::to_string(t) + " turns over when its corners move in by the " +
             "layer (the shape is thinner than 2 layers there)";
  }
  const double keep = (1.0 - kInnerSurfaceTolerance) * layer;
  const TriangleGrid grid(mesh, layer);
  for (int v = 0; v < nv; ++v) {
    int nearest = -1;
    const double dist = grid.distance(out.vertices[v], layer, nearest);
    if (dist < keep) {
      std::ostringstream os;
      os << "vertex " << v << " of the inner surface, " << where(out.vertices[v])
         << ", lies only " << dist << " m from triangle " << nearest
         << " of the surface: the shape has a feature thinner than 2 layers there";
      return os.str();
    }
  }
  return "";
}

} // namespace

bool shortest_inward_offset(const std::vector<Vector3d> &normals, double layer, Vector3d &d) {
  std::vector<Vector3d> unique;
  for (const Vector3d &n : normals)
    if (std::none_of(unique.begin(), unique.end(),
                     [&](const Vector3d &u) { return (u - n).norm() < 1e-12; }))
      unique.push_back(n);
  const int m = static_cast<int>(unique.size());
  const double keep = -(1.0 - 1e-9) * layer;
  auto feasible = [&](const Vector3d &c) {
    return std::all_of(unique.begin(), unique.end(),
                       [&](const Vector3d &n) { return n.dot(c) <= keep; });
  };
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](const Vector3d *rows[], int count) {
    Vector3d c;
    if (equality_offset(rows, count, layer, c) && c.squaredNorm() < best && feasible(c)) {
      best = c.squaredNorm();
      d = c;
    }
  };
  for (int i = 0; i < m; ++i) {
    const Vector3d *one[] = {&unique[i]};
    consider(one, 1);
    for (int j = i + 1; j < m; ++j) {
      const Vector3d *two[] = {&unique[i], &unique[j]};
      consider(two, 2);
      for (int k = j + 1; k < m; ++k) {
        const Vector3d *three[] = {&unique[i], &unique[j], &unique[k]};
        consider(three, 3);
      }
    }
  }
  return best < std::numeric_limits<double>::infinity();
}

TriangleMesh inner_surface(const TriangleMesh &mesh, double layer) {
  if (!(std::isfinite(layer) && layer >= 0.0))
    throw ShapeError("the soft layer must be finite and >= 0, got " + std::to_string(layer));
  if (layer == 0.0)
    return mesh;
  TriangleMesh out;
  const std::string problem = try_inner_surface(mesh, layer, out);
  if (problem.empty())
    return out;
  std::ostringstream os;
  os << "the surface offset inward by the soft layer (epsilon " << layer << " m) is not valid: "
     << problem << "; ";
  const double fits = largest_fitting_layer(mesh, layer);
  if (fits > 0.0)
    os << "epsilon " << fits << " m would fit";
  else
    os << "no epsilon down to " << layer / (1 << 30) << " m fits: the mesh itself is too thin";
  throw ShapeError(os.str());
}

double largest_fitting_layer(const TriangleMesh &mesh, double layer) {
  TriangleMesh scratch;
  for (int k = 0; k < 30; ++k) {
    layer *= 0.5;
    if (try_inner_surface(mesh, layer, scratch).empty())
      return layer;
  }
  return 0.0;
}

} // namespace tri
