#include "body/random_rock.h"

#include "body/mass_properties.h"
#include "body/shape_error.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <libqhull_r/qhull_ra.h>

namespace tri {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Uniform in [0, 1) from the top 53 bits of one raw draw: the same on every platform.
double uniform01(std::mt19937_64 &engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Uniformly distributed direction (Archimedes: z uniform in [-1, 1], azimuth uniform).
Eigen::Vector3d random_direction(std::mt19937_64 &engine) {
  const double z = 2.0 * uniform01(engine) - 1.0;
  const double phi = 2.0 * kPi * uniform01(engine);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Edge of a regular hexagonal tiling of the unit sphere's area 4 pi by n vertices
// (each vertex owns sqrt(3)/2 edge^2): the typical neighbour spacing of n spread points.
double tiling_edge(int n) { return std::sqrt(8.0 * kPi / (std::sqrt(3.0) * n)); }

// n directions no two closer than min_chord (dart throwing); empty if the darts run out,
// which makes the caller draw again.
std::vector<Eigen::Vector3d> spread_directions(std::mt19937_64 &engine, int n, double min_chord) {
  constexpr int kDartsPerPoint = 1000;
  std::vector<Eigen::Vector3d> points;
  points.reserve(n);
  const double min_chord2 = min_chord * min_chord;
  for (int darts = 0; static_cast<int>(points.size()) < n; ++darts) {
    if (darts > kDartsPerPoint * n)
      return {};
    const Eigen::Vector3d p = random_direction(engine);
    const bool far = std::all_of(points.begin(), points.end(), [&](const Eigen::Vector3d &q) {
      return (p - q).squaredNorm() >= min_chord2;
    });
    if (far)
      points.push_back(p);
  }
  return points;
}

// Triangles of the convex hull of `points` (Qhull, option Qt: triangulated output), as
// indices into `points`, in Qhull's vertex order (orientation not yet fixed). Empty if Qhull
// reports an error (e.g. the points are coplanar); the caller then draws again.
std::vector<std::array<int, 3>> hull_triangles(const std::vector<Eigen::Vector3d> &points) {
  std::vector<coordT> coords;
  coords.reserve(3 * points.size());
  for (const Eigen::Vector3d &p : points)
    coords.insert(coords.end(), {p.x(), p.y(), p.z()});

  // Qhull writes diagnostics to a FILE; keep them off stderr (a rejected draw is normal).
  char *err_text = nullptr;
  std::size_t err_size = 0;
  FILE *err_file = open_memstream(&err_text, &err_size);

  qhT qh_storage;
  qhT *qh = &qh_storage;
  qh_zero(qh, err_file);
  char command[] = "qhull Qt";
  const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(points.size()), coords.data(), False,
                                     command, nullptr, err_file);
  std::vector<std::array<int, 3>> triangles;
  if (exit_code == 0) {
    facetT *facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
      std::array<int, 3> t{-1, -1, -1};
      int k = 0;
      FOREACHvertex_(facet->vertices) {
        if (k < 3)
          t[k] = qh_pointid(qh, vertex->point);
        ++k;
      }
      if (k != 3) { // not triangulated: cannot happen with Qt, but never emit a bad triangle
        triangles.clear();
        break;
      }
      triangles.push_back(t);
    }
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  if (err_file)
    std::fclose(err_file);
  std::free(err_text);
  return triangles;
}

double smallest_angle(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                      const Eigen::Vector3d &c) {
  auto angle = [](const Eigen::Vector3d &u, const Eigen::Vector3d &v) {
    return std::atan2(u.cross(v).norm(), u.dot(v));
  };
  return std::min({angle(b - a, c - a), angle(a - b, c - b), angle(a - c, b - c)});
}

bool has_sliver(const std::vector<Eigen::Vector3d> &points,
                const std::vector<std::array<int, 3>> &triangles, double min_edge) {
  const double min_angle = kRockMinAngleDegrees * kPi / 180.0;
  for (const auto &t : triangles) {
    const Eigen::Vector3d &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    if ((b - a).norm() < min_edge || (c - b).norm() < min_edge || (a - c).norm() < min_edge)
      return true;
    if (smallest_angle(a, b, c) < min_angle)
      return true;
  }
  return false;
}

// Smallest interior dihedral angle over all edges of an outward-oriented closed mesh. Small
// means a wedge: e.g. four spread points near one great circle make a flat tetrahedron
// whose faces have good angles but whose volume is almost zero.
double smallest_dihedral(const std::vector<Eigen::Vector3d> &points,
                         const std::vector<std::array<int, 3>> &triangles) {
  std::vector<Eigen::Vector3d> normals;
  std::vector<std::pair<std::pair<int, int>, int>> directed; // (a, b) -> triangle
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const auto &tr = triangles[t];
    normals.push_back(
        (points[tr[1]] - points[tr[0]]).cross(points[tr[2]] - points[tr[0]]).normalized());
    for (int k = 0; k < 3; ++k)
      directed.push_back({{tr[k], tr[(k + 1) % 3]}, t});
  }
  std::sort(directed.begin(), directed.end());
  double smallest = kPi;
  for (const auto &[edge, t] : directed) {
    const auto twin = std::lower_bound(directed.begin(), directed.end(),
                                       std::make_pair(std::make_pair(edge.second, edge.first), 0));
    if (twin == directed.end() || twin->first != std::make_pair(edge.second, edge.first))
      return 0.0; // not closed: reject
    const double cos_normals = std::clamp(normals[t].dot(normals[twin->second]), -1.0, 1.0);
    smallest = std::min(smallest, kPi - std::acos(cos_normals));
  }
  return smallest;
}

// Counter-clockwise seen from outside: the normal points away from an interior point.
void orient_outward(const std::vector<Eigen::Vector3d> &points,
                    std::vector<std::array<int, 3>> &triangles) {
  Eigen::Vector3d inside = Eigen::Vector3d::Zero(); // vertex average of a convex hull
  for (const Eigen::Vector3d &p : points)
    inside += p;
  inside /= static_cast<double>(points.size());
  for (auto &t : triangles) {
    const Eigen::Vector3d &a = points[t[0]];
    const Eigen::Vector3d normal = (points[t[1]] - a).cross(points[t[2]] - a);
    if (normal.dot(a - inside) < 0.0)
      std::swap(t[1], t[2]);
  }
}

// Each triangle rotated to start at its smallest index (winding kept), then sorted.
void canonical_order(std::vector<std::array<int, 3>> &triangles) {
  for (auto &t : triangles)
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
}

void check_parameters(const RockParameters &p) {
  std::ostringstream os;
  if (p.ntri < 4 || p.ntri % 2 != 0)
    os << "random rock: ntri must be even and at least 4 (a closed triangulated convex "
          "surface with n vertices has 2n - 4 triangles), got "
       << p.ntri;
  else if (!(std::isfinite(p.size) && p.size > 0.0))
    os << "random rock: size must be positive and finite, got " << p.size;
  else if (!(p.aspect_middle > 0.0 && p.aspect_middle <= 1.0))
    os << "random rock: aspect_middle must be in (0, 1], got " << p.aspect_middle;
  else if (!(p.aspect_short > 0.0 && p.aspect_short <= 1.0))
    os << "random rock: aspect_short must be in (0, 1], got " << p.aspect_short;
  if (!os.str().empty())
    throw ShapeError(os.str());
}

} // namespace

TriangleMesh random_rock(const RockParameters &params) {
  check_parameters(params);
  const int n = (params.ntri + 4) / 2;
  const double min_chord = kRockMinSpacing * tiling_edge(n);
  std::mt19937_64 engine(params.seed);

  for (int attempt = 0; attempt < kRockMaxAttempts; ++attempt) {
    const std::vector<Eigen::Vector3d> directions = spread_directions(engine, n, min_chord);
    if (directions.empty())
      continue;
    std::vector<std::array<int, 3>> triangles = hull_triangles(directions);
    if (static_cast<int>(triangles.size()) != params.ntri ||
        has_sliver(directions, triangles, min_chord))
      continue;
    orient_outward(directions, triangles); // the stretch below keeps the orientation
    if (smallest_dihedral(directions, triangles) < kRockMinDihedralDegrees * kPi / 180.0)
      continue;
    canonical_order(triangles);

    TriangleMesh mesh;
    const Eigen::Vector3d stretch(1.0, params.aspect_middle, params.aspect_short);
    for (const Eigen::Vector3d &d : directions)
      mesh.vertices.push_back(d.cwiseProduct(stretch));
    mesh.triangles = std::move(triangles);

    const Eigen::Vector3d centre = mass_properties(mesh).centre_of_mass;
    double radius = 0.0;
    for (Eigen::Vector3d &p : mesh.vertices) {
      p -= centre;
      radius = std::max(radius, p.norm());
    }
    const double factor = 0.5 * params.size / radius;
    for (Eigen::Vector3d &p : mesh.vertices)
      p *= factor;
    return mesh;
  }
  std::ostringstream os;
  os << "random rock: no acceptable convex hull with " << params.ntri << " triangles after "
     << kRockMaxAttempts << " draws (seed " << params.seed << ")";
  throw ShapeError(os.str());
}

} // namespace tri
