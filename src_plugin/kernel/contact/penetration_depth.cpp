// Depth of a contact through the intersection of the real surfaces; the design is in the header.
#include "contact/penetration_depth.h"

#include <algorithm>
#include <cmath>

namespace tri {

using Eigen::Vector3d;

namespace {

struct Box {
  Vector3d lo, hi;
};

Box bounding_box(const TriangleSoA &s) {
  Box b{Vector3d::Constant(std::numeric_limits<double>::infinity()),
        Vector3d::Constant(-std::numeric_limits<double>::infinity())};
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const Vector3d p(s.x[i], s.y[i], s.z[i]);
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

// Grown by a relative 1e-12 of its size, so a flat wall patch has a thickness to test against.
Box padded(Box b) {
  const double pad = 1e-12 * (b.hi - b.lo).norm();
  b.lo.array() -= pad;
  b.hi.array() += pad;
  return b;
}

bool inside(const Box &b, const Vector3d &p) {
  return (p.array() >= b.lo.array()).all() && (p.array() <= b.hi.array()).all();
}

// The ray p + t d, t >= 0, meets the box (slab test; a zero direction component needs p inside
// that slab).
bool ray_meets(const Box &b, const Vector3d &p, const Vector3d &d) {
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (p[k] < b.lo[k] || p[k] > b.hi[k])
        return false;
      continue;
    }
    double ta = (b.lo[k] - p[k]) / d[k], tb = (b.hi[k] - p[k]) / d[k];
    if (ta > tb)
      std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1)
      return false;
  }
  return true;
}

// Every vertex of the SoA once (sorted, exact duplicates removed).
void unique_vertices(const TriangleSoA &s, std::vector<Vector3d> &out) {
  out.clear();
  for (std::size_t i = 0; i < s.x.size(); ++i)
    out.emplace_back(s.x[i], s.y[i], s.z[i]);
  auto less = [](const Vector3d &p, const Vector3d &q) {
    for (int k = 0; k < 3; ++k)
      if (p[k] != q[k])
        return p[k] < q[k];
    return false;
  };
  std::sort(out.begin(), out.end(), less);
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

// The first crossing of the ray p + t d (t > 0) with the surface: its distance and the crossed
// triangle's outward normal (unit); `leaves`: the ray leaves the body there.
struct Crossing {
  double t = std::numeric_limits<double>::infinity();
  Vector3d outward = Vector3d::Zero();
  bool leaves = false;
};

Crossing first_crossing(const Vector3d &p, const Vector3d &d, const TriangleSoA &surface,
                        const SurfaceSide &side) {
  Crossing c;
  for (int t = 0; t < surface.num_triangles(); ++t) {
    const Vector3d v0 = surface.vertex(t, 0);
    const Vector3d e1 = surface.vertex(t, 1) - v0, e2 = surface.vertex(t, 2) - v0;
    Vector3d normal = e1.cross(e2); // outward for a closed, outward mesh
    const double area2 = normal.norm();
    if (!(std::abs(d.dot(normal)) > kRayParallelTol * area2))
      continue; // parallel (or degenerate): no crossing
    // Moller-Trumbore: p + s d = v0 + u e1 + w e2.
    const Vector3d pvec = d.cross(e2);
    const double inv = 1.0 / e1.dot(pvec);
    const Vector3d tvec = p - v0;
    const double u = tvec.dot(pvec) * inv;
    if (u < -kRayBarycentricTol || u > 1.0 + kRayBarycentricTol)
      continue;
    const Vector3d qvec = tvec.cross(e1);
    const double w = d.dot(qvec) * inv;
    if (w < -kRayBarycentricTol || u + w > 1.0 + kRayBarycentricTol)
      continue;
    const double s = e2.dot(qvec) * inv;
    if (!(s > 0.0))
      continue;
    // Crossings at one distance (through an edge or a vertex: every triangle around it) share
    // the outward normal: the mean of their unit normals (by symmetry, the axis of a pole).
    const double tie = kRayTieTol * std::max(s, std::sqrt(area2));
    if (s > c.t + tie)
      continue;
    if (side.wall && (side.particle_centre - v0).dot(normal) < 0.0)
      normal = -normal; // the wall's solid is away from the particle
    if (s < c.t - tie) {
      c.t = s;
      c.outward = Vector3d::Zero();
      c.leaves = d.dot(normal) > 0.0;
    }
    c.outward += normal / area2;
  }
  const double len = c.outward.norm();
  if (len > 0.0)
    c.outward /= len;
  return c;
}

// Vertices of one body sunk behind the other's surface along d, appended to `sunk`; `push`:
// +1 when d = -n (a's vertices: the exit face's outward normal is -n), -1 when d = +n.
void collect_sunk(const std::vector<Vector3d> &vertices, const TriangleSoA &surface,
                  const SurfaceSide &side, const Vector3d &d, double push,
                  std::vector<DepthScratch::Sunk> &sunk) {
  const Box box = padded(bounding_box(surface));
  for (const Vector3d &v : vertices) {
    // A point inside a closed body is inside its box; a wall's solid lies behind the patch.
    if (side.wall ? !ray_meets(box, v, d) : !inside(box, v))
      continue;
    const Crossing c = first_crossing(v, d, surface, side);
    if (c.leaves)
      sunk.push_back({v, v + c.t * d, -push * c.outward, c.t});
  }
}

} // namespace

double deep_contact_limit(double thinnest_a, double thinnest_b) {
  return kDeepContactLimitFraction * std::min(thinnest_a, thinnest_b);
}

double depth_behind_surface(const Vector3d &p, const Vector3d &d, const TriangleSoA &surface,
                            const SurfaceSide &side) {
  const Crossing c = first_crossing(p, d, surface, side);
  return c.leaves ? c.t : 0.0;
}

namespace {

// The sunk vertices of both bodies along normal n (a's behind b along -n, b's behind a along
// +n): the deepest depth, the tie-weighted midpoint of the deepest ones and their exits
// (header), the push direction of the deepest one's exit face, and how far the sunk vertices
// reach from that point.
struct Measured {
  double depth = 0.0;
  Vector3d point = Vector3d::Zero();
  Vector3d face_normal = Vector3d::Zero();
  double reach = 0.0;
};

Measured measure(const TriangleSoA &a, const SurfaceSide &side_a, const TriangleSoA &b,
                 const SurfaceSide &side_b, double layer, const Vector3d &n,
                 DepthScratch &scratch) {
  std::vector<DepthScratch::Sunk> &sunk = scratch.sunk;
  sunk.clear();
  collect_sunk(scratch.vertices_a, b, side_b, -n, 1.0, sunk);
  collect_sunk(scratch.vertices_b, a, side_a, n, -1.0, sunk);
  Measured m;
  for (const DepthScratch::Sunk &s : sunk)
    if (s.depth > m.depth) {
      m.depth = s.depth;
      m.face_normal = s.face_normal;
    }
  if (!(m.depth > 0.0))
    return m;
  const double band = kDepthTaper * layer;
  Vector3d sum = Vector3d::Zero();
  double weights = 0.0;
  for (const DepthScratch::Sunk &s : sunk) {
    const double w = band > 0.0 ? 1.0 - (m.depth - s.depth) / band : (s.depth == m.depth);
    if (w > 0.0) {
      sum += w * 0.5 * (s.vertex + s.exit);
      weights += w;
    }
  }
  m.point = sum / weights;
  for (const DepthScratch::Sunk &s : sunk)
    m.reach = std::max(m.reach, (s.vertex - m.point).norm());
  return m;
}

Vector3d unit_or_zero(const Vector3d &v) {
  const double len = v.norm();
  return std::isfinite(len) && len > 0.0 ? Vector3d(v / len) : Vector3d::Zero();
}

// A direction along which vertices are sunk, and what is sunk along it.
struct DeepDirection {
  Measured measured;
  Vector3d n = Vector3d::Zero();
};

DeepDirection deep_direction(const TriangleSoA &a, const SurfaceSide &side_a, const TriangleSoA &b,
                             const SurfaceSide &side_b, double layer, const Vector3d &reference,
                             const std::vector<ContactPoint> &points, DepthScratch &scratch) {
  // 1. The direction: the reference (line of centres, or towards the wall) if vertices are sunk
  // along it, else the intersecting points' normals either way, the one of least depth (the
  // least translation that separates the bodies).
  Vector3d n = unit_or_zero(reference);
  Measured m;
  if (n.squaredNorm() > 0.0)
    m = measure(a, side_a, b, side_b, layer, n, scratch);
  if (!(m.depth > 0.0)) {
    for (const ContactPoint &c : points) {
      if (!c.intersecting)
        continue;
      for (double sign : {1.0, -1.0}) {
        const Vector3d candidate = sign * c.normal;
        const Measured mc = measure(a, side_a, b, side_b, layer, candidate, scratch);
        if (mc.depth > 0.0 && (!(m.depth > 0.0) || mc.depth < m.depth)) {
          m = mc;
          n = candidate;
        }
      }
    }
  }
  if (!(m.depth > 0.0))
    return {m, n}; // no vertex inside (edges crossing): the reduction's points stand
  // 2. Refined to the face the deepest vertex is behind (a corner pressed into a face is pushed
  // along the face's normal, whatever the line of centres), while that face agrees.
  for (int iteration = 0; iteration < kDepthNormalIterations; ++iteration) {
    const Vector3d face = unit_or_zero(m.face_normal);
    if (!(face.dot(n) > 0.0) || face.dot(n) >= 1.0 - 1e-15)
      break;
    const Measured mf = measure(a, side_a, b, side_b, layer, face, scratch);
    if (!(mf.depth > 0.0))
      break;
    m = mf;
    n = face;
  }
  return {m, n};
}

// Every point of the intersection region merged into one, at the measured depth along n.
void merge_intersection(const TriangleSoA &a, const SurfaceSide &side_a, const TriangleSoA &b,
                        const SurfaceSide &side_b, double layer, double link_length,
                        const Measured &m, const Vector3d &n, std::vector<ContactPoint> &points,
                        DepthScratch &scratch) {
  // 3. One contact for the intersection region: every intersecting point within reach of the
  // sunk vertices (plus a link length) merges into it, the nearest one in any case.
  const double reach = m.reach + link_length;
  std::vector<int> &drop = scratch.drop;
  drop.assign(points.size(), 0);
  int nearest = -1;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(points.size()); ++k) {
    const double dist = (points[k].point - m.point).norm();
    if (!points[k].intersecting) {
      // Part of the same intersection (header): a pair the reduction flipped (overlap beyond the
      // layer), one inside the other body, or one at the level of the intersection along n.
      const Vector3d &p = points[k].point;
      const bool level = std::abs((p - m.point).dot(n)) <= 0.5 * m.depth + layer;
      drop[k] = dist <= reach &&
                (points[k].overlap > layer || level ||
                 depth_behind_surface(p, -n, b, side_b) > 0.0 ||
                 depth_behind_surface(p, n, a, side_a) > 0.0);
      continue;
    }
    if (dist < nearest_distance) {
      nearest_distance = dist;
      nearest = k;
    }
    drop[k] = dist <= reach;
  }
  drop[nearest] = 1;
  ContactPoint merged = points[nearest];
  merged.num_merged = 0;
  merged.overlap = layer + m.depth;
  merged.point = m.point;
  merged.normal = n;
  // A point contact: the rocking damper and the twist of a patch are for faces in the layers.
  merged.patch_area = 0.0;
  merged.patch_second_moment.setZero();
  merged.patch_mean_radius = 0.0;
  merged.face_weight = 0.0;
  for (int k = 0; k < static_cast<int>(points.size()); ++k)
    if (drop[k]) {
      merged.num_merged += points[k].num_merged;
      merged.min_distance = std::min(merged.min_distance, points[k].min_distance);
      // An edge crossing deeper than every vertex (and pushing the same way) keeps its overlap.
      if (points[k].normal.dot(n) >= std::cos(kDeepGroupAngle))
        merged.overlap = std::max(merged.overlap, points[k].overlap);
    }
  merged.energy_overlap = merged.overlap; // the force is kn overlap along n: its energy's
  std::size_t w = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!drop[k])
      points[w++] = points[k];
  points.resize(w);
  points.push_back(merged);
  std::stable_sort(points.begin(), points.end(), [](const ContactPoint &p, const ContactPoint &q) {
    return p.overlap > q.overlap;
  });
}

} // namespace

double deepen_contacts(const TriangleSoA &a, const SurfaceSide &side_a, const TriangleSoA &b,
                       const SurfaceSide &side_b, double layer, const Vector3d &reference,
                       double link_length, std::vector<ContactPoint> &points,
                       DepthScratch &scratch) {
  int first = -1;
  for (int k = 0; k < static_cast<int>(points.size()) && first < 0; ++k)
    if (points[k].intersecting)
      first = k;
  if (first < 0)
    return 0.0;
  unique_vertices(a, scratch.vertices_a);
  unique_vertices(b, scratch.vertices_b);
  const DeepDirection deep =
      deep_direction(a, side_a, b, side_b, layer, reference, points, scratch);
  if (!(deep.measured.depth > 0.0))
    return 0.0;
  merge_intersection(a, side_a, b, side_b, layer, link_length, deep.measured, deep.n, points,
                     scratch);
  return deep.measured.depth;
}

} // namespace tri
