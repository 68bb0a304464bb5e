#include "body/shape.h"

#include "body/inner_surface.h"
#include "body/mesh_validation.h"
#include "body/smooth_surface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace tri {

namespace {

// Drops vertices no triangle uses (OBJ files may carry them), so that the bounding radius
// and convexity speak about the surface only. Keeps the order of the used ones.
void remove_unreferenced_vertices(TriangleMesh &mesh) {
  std::vector<int> new_index(mesh.vertices.size(), -1);
  for (const auto &t : mesh.triangles)
    for (int v : t)
      new_index[v] = 0;
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (new_index[v] == 0) {
      new_index[v] = static_cast<int>(kept.size());
      kept.push_back(mesh.vertices[v]);
    }
  for (auto &t : mesh.triangles)
    for (int &v : t)
      v = new_index[v];
  mesh.vertices = std::move(kept);
}

Eigen::Vector3d unit_normal(const TriangleMesh &mesh, int t) {
  return (mesh.corner(t, 1) - mesh.corner(t, 0))
      .cross(mesh.corner(t, 2) - mesh.corner(t, 0))
      .normalized();
}

} // namespace

bool is_convex(const TriangleMesh &mesh, double tolerance) {
  auto behind_all_planes = [&](const std::vector<Eigen::Vector3d> &points, int t) {
    const Eigen::Vector3d n = unit_normal(mesh, t);
    const double offset = n.dot(mesh.corner(t, 0));
    for (const Eigen::Vector3d &p : points)
      if (n.dot(p) - offset > tolerance)
        return false;
    return true;
  };
  // Cheap local test first, O(triangles log triangles): across every edge, the neighbouring
  // triangle's corners must be behind this face. Most non-convex meshes fail here, so the
  // quadratic global test below runs in full only for (locally) convex meshes.
  std::vector<std::pair<std::pair<int, int>, int>> directed; // (a, b) -> triangle
  directed.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      directed.push_back({{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]}, t});
  std::sort(directed.begin(), directed.end());
  for (const auto &[edge, t] : directed) {
    const auto twin = std::lower_bound(directed.begin(), directed.end(),
                                       std::make_pair(std::make_pair(edge.second, edge.first), 0));
    if (twin == directed.end() || twin->first != std::make_pair(edge.second, edge.first))
      continue; // not closed; the global test still applies
    const int u = twin->second;
    if (!behind_all_planes({mesh.corner(u, 0), mesh.corner(u, 1), mesh.corner(u, 2)}, t))
      return false;
  }
  // Global test: local convexity alone does not exclude a surface that wraps around twice.
  // O(triangles x vertices): vertices as plain arrays and a max-reduction the compiler
  // vectorises (a 1e5-triangle convex mesh: 5e9 products, ~10x faster than the loop above).
  const std::size_t nv = mesh.vertices.size();
  std::vector<double> vx(nv), vy(nv), vz(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    vx[i] = mesh.vertices[i].x();
    vy[i] = mesh.vertices[i].y();
    vz[i] = mesh.vertices[i].z();
  }
  const double *px = vx.data(), *py = vy.data(), *pz = vz.data();
  for (int t = 0; t < mesh.num_triangles(); ++t) {
    const Eigen::Vector3d n = unit_normal(mesh, t);
    const double nx = n.x(), ny = n.y(), nz = n.z();
    double highest = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(max : highest)
    for (std::size_t i = 0; i < nv; ++i)
      highest = std::max(highest, nx * px[i] + ny * py[i] + nz * pz[i]);
    if (highest - n.dot(mesh.corner(t, 0)) > tolerance)
      return false;
  }
  return true;
}

// A closed, consistently oriented surface that folds through itself (validate_mesh does not
// test self-intersection) can still enclose a positive volume, yet its divergence-theorem
// "inertia" is that of no solid: a moment <= 0, or one larger than the sum of the other two,
// would make the rigid-body integrator accelerate a spin without bound. Every real solid has
// I_k > 0 and I_i + I_j >= I_k (equality only for a flat plate); 1e-9 of the largest absorbs
// rounding.
void check_solid_inertia(const std::string &name, const Eigen::Vector3d &moments) {
  const double largest = moments.maxCoeff(), tol = 1e-9 * std::abs(largest);
  const bool positive = moments.minCoeff() > 0.0;
  const bool triangle = moments.sum() - 2.0 * largest >= -tol;
  if (positive && triangle && std::isfinite(moments.sum()))
    return;
  std::ostringstream os;
  os << "shape '" << name << "': principal moments of inertia per density " << moments.x() << ", "
     << moments.y() << ", " << moments.z()
     << " are not those of a solid (each must be positive and at most the sum of the other "
        "two): the surface probably intersects itself";
  throw ShapeError(os.str());
}

namespace {

// The kernel's surface `inner` (the mesh offset inward by shape.layer) and the numbers the
// contact search reads of it.
void measure_kernel_surface(Shape &shape, const TriangleMesh &inner) {
  shape.soa = to_soa(inner);
  double e2_min = std::numeric_limits<double>::infinity(), e2_max = 0.0, sum = 0.0, r2 = 0.0;
  for (int t = 0; t < inner.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const double e2 = (inner.corner(t, (k + 1) % 3) - inner.corner(t, k)).squaredNorm();
      e2_min = std::min(e2_min, e2);
      e2_max = std::max(e2_max, e2);
      sum += std::sqrt(e2);
    }
  for (const Eigen::Vector3d &p : inner.vertices)
    r2 = std::max(r2, p.squaredNorm());
  shape.min_edge_length = std::sqrt(e2_min);
  shape.max_edge_length = std::sqrt(e2_max);
  shape.mean_edge_length = sum / (3.0 * inner.num_triangles());
  shape.thinnest_extent = thinnest_extent(shape.soa);
  shape.edge_bulge = edge_bulges(inner);
  shape.surface_lift = max_lift(shape.edge_bulge);
  shape.corner_spheres = corner_spheres(inner);
  shape.ball_lift = max_ball_sag(inner, shape.corner_spheres);
  shape.inner_radius = std::sqrt(r2);
}

} // namespace

Shape make_shape(std::string name, TriangleMesh mesh) {
  try {
    validate_mesh(mesh);
  } catch (const ShapeError &e) {
    throw ShapeError("shape '" + name + "': " + e.what());
  }
  remove_unreferenced_vertices(mesh);
  const MassProperties mp = mass_properties(mesh);
  check_solid_inertia(name, mp.principal_moments);

  Shape shape;
  shape.name = std::move(name);
  const Eigen::Matrix3d to_body = mp.principal_axes.transpose();
  for (Eigen::Vector3d &p : mesh.vertices)
    p = to_body * (p - mp.centre_of_mass);
  shape.mesh = std::move(mesh);
  shape.surface = to_soa(shape.mesh);
  shape.principal_axes = mp.principal_axes;
  shape.centre_of_mass = mp.centre_of_mass;
  Eigen::Quaterniond q(mp.principal_axes);
  q.normalize();
  if (q.w() < 0.0) // q and -q are the same rotation; one sign, so the dump is deterministic
    q.coeffs() = -q.coeffs();
  shape.input_orientation = q;
  shape.volume = mp.volume;
  shape.inertia_per_density = mp.principal_moments;

  double r2 = 0.0;
  for (const Eigen::Vector3d &p : shape.mesh.vertices)
    r2 = std::max(r2, p.squaredNorm());
  shape.bounding_radius = std::sqrt(r2);

  shape.convex = is_convex(shape.mesh, kConvexityTolerance * 2.0 * shape.bounding_radius);
  measure_kernel_surface(shape, shape.mesh);
  return shape;
}

Shape with_soft_layer(Shape shape, double layer) {
  TriangleMesh inner;
  try {
    inner = inner_surface(shape.mesh, layer);
  } catch (const ShapeError &e) {
    throw ShapeError("shape '" + shape.name + "': " + e.what());
  }
  shape.layer = layer;
  measure_kernel_surface(shape, inner);
  return shape;
}

double contact_reach(const Shape &shape, double epsilon) {
  return std::max(shape.bounding_radius, shape.inner_radius + epsilon);
}

TriangleMesh scaled(TriangleMesh mesh, double factor) {
  if (!(std::isfinite(factor) && factor > 0.0)) {
    std::ostringstream os;
    os << "scale factor must be positive and finite, got " << factor;
    throw ShapeError(os.str());
  }
  for (Eigen::Vector3d &p : mesh.vertices)
    p *= factor;
  return mesh;
}

double thinnest_extent(const TriangleSoA &body_frame) {
  if (body_frame.x.empty())
    return 0.0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (std::size_t i = 0; i < body_frame.x.size(); ++i) {
    const Eigen::Vector3d p(body_frame.x[i], body_frame.y[i], body_frame.z[i]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).minCoeff();
}

} // namespace tri
