// Reduction of triangle-pair contacts to contact points; the design is in the header.
#include "contact_reduction.h"

#include "contact_polygon.h"
#include "point_links.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace tri {
namespace {

using Eigen::Vector3d;
using Raw = ReductionWorkspace::Raw;

bool finite(const Vector3d &v) { return std::isfinite(v.x() + v.y() + v.z()); }

// A unit reference direction whatever the caller passed.
Vector3d safe_reference(const Vector3d &ref) {
  const double len = ref.norm();
  if (std::isfinite(len) && len > 0.0)
    return ref / len;
  return Vector3d::UnitZ();
}

// Unit normal of one raw contact: the kernel's; for a separated pair whose normal is unusable,
// the closest-point direction; else the reference direction.
Vector3d raw_normal(const TriangleContact &c, const Vector3d &ref) {
  const double len = c.normal.norm();
  if (std::isfinite(len) && len > 0.5)
    return c.normal / len;
  const Vector3d d = c.point_b - c.point_a;
  const double dl = d.norm();
  if (!c.intersecting && std::isfinite(dl) && dl > 0.0)
    return d / dl;
  return ref;
}

// Strict total order of raw contacts: deepest first, then triangle ids, then coordinates.
bool deeper(const Raw &a, const Raw &b) {
  if (a.overlap != b.overlap)
    return a.overlap > b.overlap;
  if (a.tri_a != b.tri_a)
    return a.tri_a < b.tri_a;
  if (a.tri_b != b.tri_b)
    return a.tri_b < b.tri_b;
  for (int k = 0; k < 3; ++k)
    if (a.point[k] != b.point[k])
      return a.point[k] < b.point[k];
  return false;
}

// Deep penetration: in a component with intersecting pairs, separated pairs that face against
// them are seen from behind the other surface; flip them (header, "Intersecting triangles").
void flip_sunk_members(std::vector<Raw> &raw, const std::vector<int> &members, double layer,
                       const Vector3d &ref) {
  Vector3d mean = Vector3d::Zero();
  bool any = false;
  for (int i : members)
    if (raw[i].intersecting) {
      mean += raw[i].overlap * raw[i].normal;
      any = true;
    }
  if (!any)
    return;
  const double len = mean.norm();
  mean = (std::isfinite(len) && len > 0.0) ? Vector3d(mean / len) : ref;
  for (int i : members) {
    Raw &r = raw[i];
    if (!r.intersecting && r.normal.dot(mean) < 0.0) {
      r.normal = -r.normal;
      r.overlap = layer + r.distance;
    }
  }
}

// Members of class `s`, measured along class m's normal, overlap no more than m does.
bool absorbed_by(const std::vector<Raw> &raw, const std::vector<int> &members,
                 const std::vector<int> &cls, int s, const Raw &mseed, double layer) {
  const double tol = 1e-6 * layer;
  for (int i : members) {
    if (cls[i] != s)
      continue;
    if (layer - raw[i].separation.dot(mseed.normal) > mseed.overlap + tol)
      return false;
  }
  return true;
}

// Members whose overlap is within this fraction of the layer of the deepest one define the
// normal: ties up to rounding (see the header, step 4).
constexpr double kNormalDepthBand = 1e-6;

// Members within this fraction of the layer of the deepest one share the deepest point, with
// weights falling linearly to zero across it (header, step 5).
constexpr double kDeepestTaper = 1e-3;

// The two bodies' triangles (never null).
struct Faces {
  const TriangleSoA *a, *b;
};

// The member's contact polygon (header, step 5) if its triangles are nearly parallel and their
// overlap has an area beyond rounding; false otherwise.
bool member_polygon(const Raw &r, const Faces &faces, double layer, ContactPolygon &poly) {
  const TriangleSoA &ta = *faces.a, &tb = *faces.b;
  if (!contact_polygon(ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2),
                       tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2),
                       r.normal, layer, poly))
    return false;
  return poly.weight > 0.0 && poly.area > kPatchAreaRounding * poly.min_triangle_area;
}

ContactPoint make_point(const std::vector<Raw> &raw, const std::vector<int> &members,
                        const std::vector<int> &cls, const std::vector<int> &absorbed, int c,
                        int seed, double layer, const Vector3d &ref, const Faces &faces) {
  ContactPoint p;
  const Raw &s = raw[seed];
  Vector3d sum_n = Vector3d::Zero(), sum_tied = Vector3d::Zero();
  double sum_wn = 0.0, sum_wa = 0.0, sum_wt = 0.0;
  // Area moments of the polygons (step 6), relative to the seed's midpoint (near the patch, so
  // no digits are lost far from the world origin): zeroth, first, second.
  double area0 = 0.0;
  Vector3d area1 = Vector3d::Zero();
  Eigen::Matrix3d area2 = Eigen::Matrix3d::Zero();
  p.min_distance = std::numeric_limits<double>::infinity();
  for (int i : members) {
    if (cls[i] != c)
      continue;
    const Raw &r = raw[i];
    p.min_distance = std::min(p.min_distance, r.distance);
    p.intersecting = p.intersecting || r.intersecting;
    ++p.num_merged;
    if (absorbed[i])
      continue; // rim contacts count, but neither place nor orient the contact
    ContactPolygon poly;
    if (member_polygon(r, faces, layer, poly)) {
      sum_wa += poly.weight;
      const Vector3d d = poly.area_centroid - s.point;
      area0 += poly.area;
      area1 += poly.area * d;
      area2 += poly.second_moment + poly.area * d * d.transpose();
    }
    const double tied = 1.0 - (s.overlap - r.overlap) / (kDeepestTaper * layer);
    if (tied > 0.0) {
      sum_tied += tied * r.point;
      sum_wt += tied;
    }
    if (r.overlap >= s.overlap - kNormalDepthBand * layer) {
      sum_n += r.overlap * r.normal;
      sum_wn += r.overlap;
    }
  }
  // The deepest pair's midpoint, averaged over the pairs (nearly) tied with it (step 5).
  const Vector3d deepest = sum_tied / sum_wt;
  p.point = deepest;
  p.overlap = s.overlap;
  if (area0 > 0.0) {
    // Step 5b: a face contact's force is the gradient of 1/2 kn o_s^2, o_s = deepest - u (1 - r)^2,
    // smooth across flat (see the header for the derivation of the point and the factor).
    const double mean = sum_wa / area0;
    const double uneven = std::max(0.0, s.overlap - mean);
    const double r = uneven / (kFlatPatchBand * s.overlap);
    if (r < 1.0) {
      const Vector3d area_centre = s.point + area1 / area0;
      const double to_mean = (1.0 - r) * (1.0 - 3.0 * r);
      const double band_term = 2.0 * kFlatPatchBand * r * r * (1.0 - r);
      const double o_s = s.overlap - uneven * (1.0 - r) * (1.0 - r);
      p.point = ((1.0 - to_mean - band_term) * deepest + to_mean * area_centre) / (1.0 - band_term);
      p.overlap = o_s * (1.0 - band_term);
    }
  }
  p.tri_a = s.tri_a;
  p.tri_b = s.tri_b;
  const double len = sum_n.norm();
  if (std::isfinite(len) && len > 1e-3 * sum_wn)
    p.normal = sum_n / len;
  else
    p.normal = finite(s.normal) ? s.normal : ref;
  if (sum_wa > 0.0 && area0 > 0.0) {
    // Parallel-axis theorem from s.point to p.point (q = p.point - s.point), then onto the
    // contact plane.
    const Vector3d q = p.point - s.point;
    const Eigen::Matrix3d about_point =
        area2 - area1 * q.transpose() - q * area1.transpose() + area0 * q * q.transpose();
    const Eigen::Matrix3d plane = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
    Eigen::Matrix3d j = plane * about_point * plane;
    p.patch_second_moment = 0.5 * (j + j.transpose());
    p.patch_area = area0;
  }
  return p;
}

void reduce_clusters(std::vector<Raw> &raw, double layer, const ReductionParams &params,
                     const Vector3d &ref, const Faces &faces, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out) {
  const int n = static_cast<int>(raw.size());
  work.points.resize(n);
  for (int i = 0; i < n; ++i)
    work.points[i] = raw[i].point;
  link_points(work.points, params.link_length, work.parent, work.links);
  // Members of each component, components in the order of their deepest member.
  std::vector<int> &label = work.label;
  label.resize(n);
  for (int i = 0; i < n; ++i)
    label[i] = link_root(work.parent, i);
  std::vector<int> &members = work.order; // reused: all indices grouped by component
  members.resize(n);
  std::iota(members.begin(), members.end(), 0);
  std::stable_sort(members.begin(), members.end(),
                   [&](int i, int j) { return label[i] < label[j]; });

  const double cos_split = std::cos(params.split_angle);
  std::vector<int> &cls = work.cls;
  cls.assign(n, -1);
  std::vector<int> &absorbed = work.absorbed;
  absorbed.assign(n, 0);
  std::vector<int> &seeds = work.seeds; // class c: seeds[c] = its deepest member (raw index)
  std::vector<int> &alive = work.alive; // class c not absorbed
  std::vector<int> &group = work.group; // members of the current component
  seeds.clear();
  alive.clear();
  for (int begin = 0; begin < n;) {
    int end = begin;
    while (end < n && label[members[end]] == label[members[begin]])
      ++end;
    group.assign(members.begin() + begin, members.begin() + end);
    flip_sunk_members(raw, group, layer, ref);
    // Deepest first again after the flips (ties keep the sorted order: indices).
    std::sort(group.begin(), group.end(), [&](int i, int j) {
      if (raw[i].overlap != raw[j].overlap)
        return raw[i].overlap > raw[j].overlap;
      return i < j;
    });
    const int first_class = static_cast<int>(seeds.size());
    for (int seed : group) {
      if (cls[seed] >= 0)
        continue;
      const int c = static_cast<int>(seeds.size());
      seeds.push_back(seed);
      alive.push_back(1);
      for (int i : group)
        if (cls[i] < 0 && raw[i].normal.dot(raw[seed].normal) >= cos_split)
          cls[i] = c;
    }
    // Rim absorption: a later class into the first earlier (deeper) one that explains it.
    for (int s = first_class + 1; s < static_cast<int>(seeds.size()); ++s) {
      const Raw &sseed = raw[seeds[s]];
      for (int m = first_class; m < s; ++m) {
        if (!alive[m])
          continue;
        const Raw &mseed = raw[seeds[m]];
        if (sseed.normal.dot(mseed.normal) <= 0.0 || !absorbed_by(raw, group, cls, s, mseed, layer))
          continue;
        for (int i : group)
          if (cls[i] == s) {
            cls[i] = m;
            absorbed[i] = 1;
          }
        alive[s] = 0;
        break;
      }
    }
    for (int c = first_class; c < static_cast<int>(seeds.size()); ++c)
      if (alive[c])
        out.push_back(make_point(raw, group, cls, absorbed, c, seeds[c], layer, ref, faces));
    begin = end;
  }
  // Deepest first; ties keep component/class order (deterministic).
  std::stable_sort(out.begin(), out.end(), [](const ContactPoint &a, const ContactPoint &b) {
    return a.overlap > b.overlap;
  });
}

ContactPoint single_point(const Raw &r) {
  ContactPoint p;
  p.point = r.point;
  p.normal = r.normal;
  p.overlap = r.overlap;
  p.min_distance = r.distance;
  p.num_merged = 1;
  p.intersecting = r.intersecting;
  p.tri_a = r.tri_a;
  p.tri_b = r.tri_b;
  return p;
}

} // namespace

double recommended_link_length(double longest_edge_a, double longest_edge_b, double eps_a,
                               double eps_b) {
  const double edge = std::min(longest_edge_a, longest_edge_b);
  return (2.0 * edge + eps_a + eps_b) * (1.0 + 1e-9);
}

namespace {

void reduce(const TriangleContact *contacts, int n, const Faces &faces, double eps_a, double eps_b,
            const ReductionParams &params, ReductionWorkspace &work,
            std::vector<ContactPoint> &out) {
  out.clear();
  const int na = faces.a->num_triangles(), nb = faces.b->num_triangles();
  const double layer = eps_a + eps_b;
  const Vector3d ref = safe_reference(params.reference_direction);
  std::vector<Raw> &raw = work.raw;
  raw.clear();
  for (int k = 0; k < n; ++k) {
    const TriangleContact &c = contacts[k];
    if (c.tri_a < 0 || c.tri_a >= na || c.tri_b < 0 || c.tri_b >= nb)
      throw std::out_of_range("reduce_contacts: contact " + std::to_string(k) +
                              " names triangles " + std::to_string(c.tri_a) + ", " +
                              std::to_string(c.tri_b) + " of meshes with " + std::to_string(na) +
                              ", " + std::to_string(nb));
    const double distance = c.intersecting ? 0.0 : std::max(0.0, c.distance);
    const double depth = c.intersecting && std::isfinite(c.penetration_depth)
                             ? std::max(0.0, c.penetration_depth)
                             : 0.0;
    const double overlap = layer - distance + depth;
    if (!(overlap > 0.0))
      continue;
    Raw r;
    r.point = 0.5 * (c.point_a + c.point_b);
    if (!finite(r.point))
      continue; // nothing sensible to place; the kernel never produces this
    r.normal = raw_normal(c, ref);
    r.separation = c.intersecting ? Vector3d::Zero() : Vector3d(c.point_b - c.point_a);
    r.overlap = overlap;
    r.distance = distance;
    r.tri_a = c.tri_a;
    r.tri_b = c.tri_b;
    r.intersecting = c.intersecting;
    raw.push_back(r);
  }
  std::sort(raw.begin(), raw.end(), deeper);
  if (raw.empty())
    return;

  switch (params.method) {
  case ReductionMethod::none:
    for (const Raw &r : raw)
      out.push_back(single_point(r));
    return;
  case ReductionMethod::paper_min_width: {
    const double w2 = params.min_width * params.min_width;
    for (const Raw &r : raw) {
      bool near = false;
      for (ContactPoint &p : out)
        if ((p.point - r.point).squaredNorm() < w2) {
          ++p.num_merged;
          near = true;
          break;
        }
      if (!near)
        out.push_back(single_point(r));
    }
    return;
  }
  case ReductionMethod::clusters:
    reduce_clusters(raw, layer, params, ref, faces, work, out);
    return;
  }
}

} // namespace

void reduce_contacts(const TriangleContact *contacts, int n, const TriangleSoA &tris_a,
                     double eps_a, const TriangleSoA &tris_b, double eps_b,
                     const ReductionParams &params, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out) {
  reduce(contacts, n, Faces{&tris_a, &tris_b}, eps_a, eps_b, params, work, out);
}

std::vector<ContactPoint> reduce_contacts(const std::vector<TriangleContact> &contacts,
                                          const TriangleSoA &tris_a, double eps_a,
                                          const TriangleSoA &tris_b, double eps_b,
                                          const ReductionParams &params) {
  ReductionWorkspace work;
  std::vector<ContactPoint> out;
  reduce_contacts(contacts.data(), static_cast<int>(contacts.size()), tris_a, eps_a, tris_b, eps_b,
                  params, work, out);
  return out;
}

} // namespace tri
