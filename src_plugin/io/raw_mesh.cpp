// The steps every format shares after parsing: faces into triangles, triangles into an indexed
// mesh (mesh_formats.h).
#include "mesh_formats.h"

#include <Eigen/Geometry>
#include <climits>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <utility>

namespace tri::mesh_io {

namespace {

using Vec3 = Eigen::Vector3d;

// Ear clipping is quadratic in the corners for ordinary polygons and cubic at worst; this many
// point-in-ear tests (a fraction of a second) bound one polygon, so no file can make it hang.
constexpr std::int64_t kEarClippingBudget = 100'000'000;

// Splits the simple polygon `corners` (at least 4, with an area) by ear clipping in the
// plane normal to `area`: going round from the second corner, the first corner whose triangle
// with its two neighbours turns the polygon's way and holds no other corner (not even on its
// border, which would leave a corner in the middle of a new edge) is cut off, then the search
// goes on from the corner after it. For a convex polygon every corner is such an ear and the
// result is the fan from the first corner. Returns why not when no corner is an ear, or when the
// ears' areas do not add up to the polygon's (it crosses itself), or past the work budget.
std::string clip_ears(const RawMesh &raw, const std::vector<int> &corners, const Vec3 &area,
                      std::vector<std::array<int, 3>> &triangles) {
  const int n = static_cast<int>(corners.size());
  // Plane coordinates (u, v) chosen so that the polygon turns counter-clockwise in them.
  int axis = 0;
  area.cwiseAbs().maxCoeff(&axis);
  int u = (axis + 1) % 3, v = (axis + 2) % 3;
  if (area[axis] < 0)
    std::swap(u, v);
  std::vector<double> x(n), y(n);
  std::vector<int> next(n), prev(n);
  for (int i = 0; i < n; ++i) {
    x[i] = raw.points[corners[i]][u];
    y[i] = raw.points[corners[i]][v];
    next[i] = (i + 1) % n;
    prev[i] = (i + n - 1) % n;
  }
  auto turn = [&](int a, int b, int c) {
    return (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]);
  };
  std::int64_t work = 0;
  double clipped_area = 0; // twice the area of the triangles cut off, in the plane
  auto is_ear = [&](int i) {
    const int a = prev[i], b = next[i];
    if (!(turn(a, i, b) > 0))
      return false;
    for (int j = next[b]; j != a; j = next[j]) {
      ++work;
      if (turn(a, i, j) >= 0 && turn(i, b, j) >= 0 && turn(b, a, j) >= 0)
        return false;
    }
    return true;
  };
  int corner = 1, remaining = n, misses = 0;
  while (remaining > 3) {
    if (work > kEarClippingBudget)
      return "it is not convex and too large to split into triangles here (" + std::to_string(n) +
             " corners); write it as triangles";
    if (is_ear(corner)) {
      clipped_area += turn(prev[corner], corner, next[corner]);
      triangles.push_back({corners[prev[corner]], corners[corner], corners[next[corner]]});
      next[prev[corner]] = next[corner];
      prev[next[corner]] = prev[corner];
      corner = next[corner];
      --remaining;
      misses = 0;
    } else {
      corner = next[corner];
      if (++misses > remaining)
        return "its corners do not form a simple polygon (it crosses or touches itself), so it "
               "cannot be split into triangles";
    }
  }
  // The triangles of a simple polygon cover it once, so their areas add up to its area; a
  // polygon that crosses itself can still lose all its corners as ears, but its lobes then
  // count with both signs in its area and never add up.
  const double last = turn(prev[corner], corner, next[corner]);
  clipped_area += last;
  const double polygon_area = area[axis] < 0 ? -area[axis] : area[axis];
  if (!(last > 0) || !(std::abs(clipped_area - polygon_area) <= 1e-9 * polygon_area))
    return "its corners do not form a simple polygon (it crosses or touches itself), so it cannot "
           "be split into triangles";
  triangles.push_back({corners[prev[corner]], corners[corner], corners[next[corner]]});
  return "";
}

} // namespace

std::string append_face(RawMesh &raw, const std::vector<int> &corners) {
  if (corners.size() == 3) {
    raw.triangles.push_back({corners[0], corners[1], corners[2]});
    return "";
  }
  std::vector<int> distinct;
  distinct.reserve(corners.size());
  for (int c : corners)
    if (distinct.empty() || raw.points[c] != raw.points[distinct.back()])
      distinct.push_back(c);
  while (distinct.size() > 1 && raw.points[distinct.back()] == raw.points[distinct.front()])
    distinct.pop_back();
  if (distinct.size() < 3)
    return "it has fewer than 3 distinct corners";
  if (distinct.size() == 3) {
    raw.triangles.push_back({distinct[0], distinct[1], distinct[2]});
    return "";
  }

  const std::size_t n = distinct.size();
  const Vec3 &p0 = raw.points[distinct[0]];
  auto fan_normal = [&](std::size_t k) {
    const Vec3 a = raw.points[distinct[k]] - p0, b = raw.points[distinct[k + 1]] - p0;
    return Vec3(a.cross(b));
  };
  Vec3 area = Vec3::Zero(); // twice the vector area: the same from any starting corner
  for (std::size_t k = 1; k + 1 < n; ++k)
    area += fan_normal(k);
  bool fan_turns_one_way = true;
  for (std::size_t k = 1; k + 1 < n && fan_turns_one_way; ++k)
    fan_turns_one_way = fan_normal(k).dot(area) > 0;
  // A corner that is not finite makes index_triangles refuse the mesh, naming the coordinate;
  // any split will do until then.
  bool finite = true;
  for (int c : distinct)
    finite = finite && raw.points[c].allFinite();
  if (fan_turns_one_way || !finite) {
    for (std::size_t k = 1; k + 1 < n; ++k)
      raw.triangles.push_back({distinct[0], distinct[k], distinct[k + 1]});
    return "";
  }
  if (!(area.squaredNorm() > 0))
    return "it has no area (its corners lie on a line)";
  std::vector<std::array<int, 3>> triangles;
  const std::string why = clip_ears(raw, distinct, area, triangles);
  if (why.empty())
    raw.triangles.insert(raw.triangles.end(), triangles.begin(), triangles.end());
  return why;
}

TriangleMesh index_triangles(const RawMesh &raw) {
  if (raw.triangles.empty())
    throw FormatError("mesh file contains no triangles");
  if (raw.triangles.size() > static_cast<std::size_t>(INT_MAX))
    throw FormatError("mesh file has more triangles than an int can count");
  TriangleMesh mesh;
  mesh.triangles.reserve(raw.triangles.size());
  // An ordered map, so that the result does not depend on a hash; it compares coordinates as
  // numbers (so -0 and 0 are one vertex, the first one met).
  std::map<std::array<double, 3>, int> vertex_at;
  std::vector<int> vertex_of_point(raw.points.size(), -1);
  auto vertex = [&](int point) {
    int &v = vertex_of_point[static_cast<std::size_t>(point)];
    if (v < 0) {
      const Vec3 &p = raw.points[static_cast<std::size_t>(point)];
      // Before the map: NaN compares false with everything and would merge with any point.
      if (!p.allFinite()) {
        std::ostringstream os;
        os << "a triangle corner has a coordinate that is not a finite number (" << p.x() << ", "
           << p.y() << ", " << p.z() << ")";
        throw FormatError(os.str());
      }
      const auto [it, inserted] =
          vertex_at.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, mesh.num_vertices());
      if (inserted)
        mesh.vertices.push_back(p);
      v = it->second;
    }
    return v;
  };
  for (const auto &t : raw.triangles)
    mesh.triangles.push_back({vertex(t[0]), vertex(t[1]), vertex(t[2])});
  return mesh;
}

} // namespace tri::mesh_io
