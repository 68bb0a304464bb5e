// Steps 1 to 3 of the reduction (README.md): connected regions of the raw contacts, normal
// classes inside each region, and rim classes absorbed into the deeper class they belong to;
// then one contact point per remaining class (make_point), deepest first.
#include "contact/point_links.h"
#include "contact/reduction_steps.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tri::reduction {
namespace {

// Step 1: label[i] = the connected region of raw contact i (labels are indices). True if all
// are one region.
bool label_regions(const std::vector<Raw> &raw, double link_length, ReductionWorkspace &work) {
  const int n = static_cast<int>(raw.size());
  std::vector<int> &label = work.label;
  label.resize(n);
  // Points whose bounding box has a diagonal within the link length are all linked (every
  // pair's distance is at most the diagonal, and rounding keeps that order: a contact at one
  // place, most of them): one region, labels 0, as link_points would find.
  Vector3d lo = raw[0].point, hi = raw[0].point;
  for (int i = 1; i < n; ++i) {
    lo = lo.cwiseMin(raw[i].point);
    hi = hi.cwiseMax(raw[i].point);
  }
  if ((hi - lo).squaredNorm() <= link_length * link_length) {
    std::fill(label.begin(), label.end(), 0);
    return true;
  }
  work.points.resize(n);
  for (int i = 0; i < n; ++i)
    work.points[i] = raw[i].point;
  link_points(work.points, link_length, work.parent, work.links);
  for (int i = 0; i < n; ++i)
    label[i] = link_root(work.parent, i);
  bool one_region = true;
  for (int i = 0; i < n; ++i)
    one_region = one_region && label[i] == 0;
  return one_region;
}

// All indices grouped by region into work.order, in index order within each (the order of a
// stable sort by label): one region (most pairs) as they are, else a counting sort.
void group_by_region(int n, bool one_region, ReductionWorkspace &work) {
  const std::vector<int> &label = work.label;
  std::vector<int> &members = work.order;
  members.resize(n);
  if (one_region) {
    std::iota(members.begin(), members.end(), 0);
    return;
  }
  std::vector<int> &tally = work.tally;
  tally.assign(n + 1, 0);
  for (int i = 0; i < n; ++i)
    ++tally[label[i] + 1];
  for (int i = 0; i < n; ++i)
    tally[i + 1] += tally[i];
  for (int i = 0; i < n; ++i)
    members[tally[label[i]]++] = i;
}

// Deep penetration: in a region with intersecting pairs, separated pairs that face against
// them are seen from behind the other surface; flip them (contact_reduction.h, "Intersecting
// triangles"). True if it flipped any.
bool flip_sunk_members(std::vector<Raw> &raw, const std::vector<int> &members, double layer,
                       const Vector3d &ref) {
  Vector3d mean = Vector3d::Zero();
  bool any = false;
  for (int i : members)
    if (raw[i].intersecting) {
      mean += raw[i].overlap * raw[i].normal;
      any = true;
    }
  if (!any)
    return false;
  const double len = mean.norm();
  mean = (std::isfinite(len) && len > 0.0) ? Vector3d(mean / len) : ref;
  bool flipped = false;
  for (int i : members) {
    Raw &r = raw[i];
    if (!r.intersecting && r.normal.dot(mean) < 0.0) {
      r.normal = -r.normal;
      r.overlap = layer + r.distance;
      flipped = true;
    }
  }
  return flipped;
}

// Step 2: the deepest unassigned member of the region seeds a class of every unassigned member
// within the split angle of its normal; appends the seeds and marks the classes alive. With a
// distinct-spot distance, a member farther than it from the seed whose normal is more than
// kDistinctSpotAngle off is another contact: a non-convex pair touching in two spots (a jack's
// arm on two faces of another) or a particle in a wall's crease keeps one contact each,
// whichever spot is deeper. In one class the smooth maximum would hold the deeper spot's
// energy alone, and the contact's point would jump between the spots when their overlaps
// cross.
void split_normal_classes(const std::vector<Raw> &raw, const std::vector<int> &group,
                          double cos_split, double distinct_distance, ReductionWorkspace &work) {
  static const double cos_distinct = std::cos(kDistinctSpotAngle);
  const double distinct2 = distinct_distance * distinct_distance;
  std::vector<int> &cls = work.cls;
  for (int seed : group) {
    if (cls[seed] >= 0)
      continue;
    const int c = static_cast<int>(work.seeds.size());
    work.seeds.push_back(seed);
    work.alive.push_back(1);
    const Raw &s = raw[seed];
    for (int i : group) {
      if (cls[i] >= 0)
        continue;
      const double cos_angle = raw[i].normal.dot(s.normal);
      if (cos_angle < cos_split)
        continue;
      if (distinct2 > 0.0 && cos_angle < cos_distinct &&
          (raw[i].point - s.point).squaredNorm() > distinct2)
        continue;
      cls[i] = c;
    }
  }
}

// Step 3: members of class `s`, measured along class m's normal, overlap no more than m does.
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

// Step 3: each class after the region's first into the first earlier (deeper) one that
// explains it as its rim.
void absorb_rims(const std::vector<Raw> &raw, const std::vector<int> &group, int first_class,
                 double layer, ReductionWorkspace &work) {
  const std::vector<int> &seeds = work.seeds;
  std::vector<int> &cls = work.cls;
  for (int s = first_class + 1; s < static_cast<int>(seeds.size()); ++s) {
    const Raw &sseed = raw[seeds[s]];
    for (int m = first_class; m < s; ++m) {
      if (!work.alive[m])
        continue;
      const Raw &mseed = raw[seeds[m]];
      if (sseed.normal.dot(mseed.normal) <= 0.0 || !absorbed_by(raw, group, cls, s, mseed, layer))
        continue;
      for (int i : group)
        if (cls[i] == s) {
          cls[i] = m;
          work.absorbed[i] = 1;
        }
      work.alive[s] = 0;
      break;
    }
  }
}

// The cosine of the split angle, kept while the angle stays the same pair after pair.
double cos_split_of(double split_angle, ReductionWorkspace &work) {
  if (!(split_angle == work.split_angle)) {
    work.split_angle = split_angle;
    work.cos_split = std::cos(split_angle);
  }
  return work.cos_split;
}

// For `classify`: the class's ContactKind but deep (contact_point.h): face from its face
// weight, else edge or vertex from how far the members tied with the deepest lie from it.
ContactKind class_kind(const ContactPoint &p, const ContactClass &cc) {
  if (p.intersecting)
    return ContactKind::deep;
  if (p.face_weight >= 0.5)
    return ContactKind::face;
  const Raw *deepest = nullptr;
  for (int i : cc.members)
    if (cc.places(i) && (!deepest || cc.raw[i].overlap > deepest->overlap))
      deepest = &cc.raw[i];
  if (!deepest)
    return ContactKind::vertex;
  // Edge or vertex: how far the members tied with the deepest lie from it.
  const double tied = deepest->overlap - kDeepestTaper * cc.layer;
  double spread2 = 0.0;
  for (int i : cc.members)
    if (cc.places(i) && cc.raw[i].overlap >= tied)
      spread2 = std::max(spread2, (cc.raw[i].point - deepest->point).squaredNorm());
  return spread2 > cc.layer * cc.layer ? ContactKind::edge : ContactKind::vertex;
}

// Steps 2 to 6 for the region group = members[begin, end): its classes' points into `out`.
void reduce_region(std::vector<Raw> &raw, int begin, int end, double layer,
                   const ReductionParams &params, const Vector3d &ref, const Faces &faces,
                   ReductionWorkspace &work, std::vector<ContactPoint> &out) {
  std::vector<int> &group = work.group;
  group.assign(work.order.begin() + begin, work.order.begin() + end);
  // Deepest first again after the flips (ties keep the sorted order: indices). Without a
  // flip the group, in index order, is in that order already (raw is sorted deepest first).
  if (flip_sunk_members(raw, group, layer, ref))
    std::sort(group.begin(), group.end(), [&](int i, int j) {
      if (raw[i].overlap != raw[j].overlap)
        return raw[i].overlap > raw[j].overlap;
      return i < j;
    });
  const int first_class = static_cast<int>(work.seeds.size());
  split_normal_classes(raw, group, work.cos_split, params.distinct_spot_distance, work);
  absorb_rims(raw, group, first_class, layer, work);
  for (int c = first_class; c < static_cast<int>(work.seeds.size()); ++c) {
    if (!work.alive[c])
      continue;
    const ContactClass cc{raw, group, work.cls, work.absorbed, c, work.seeds[c], layer};
    const ContactPoint p = make_point(cc, ref, faces, params.distance_tolerance, work);
    // Facets within reach of the lifts whose smooth surfaces do not overlap yet.
    if (params.surface_lift > 0.0 && !params.keep_shallow && !(p.overlap > 0.0))
      continue;
    out.push_back(p);
    if (params.classify)
      out.back().kind = class_kind(p, cc);
  }
}

} // namespace

void reduce_clusters(std::vector<Raw> &raw, double layer, const ReductionParams &params,
                     const Vector3d &ref, const Faces &faces, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out) {
  const int n = static_cast<int>(raw.size());
  group_by_region(n, label_regions(raw, params.link_length, work), work);
  cos_split_of(params.split_angle, work);
  work.cls.assign(n, -1);
  work.absorbed.assign(n, 0);
  work.seeds.clear(); // class c: seeds[c] = its deepest member (raw index)
  work.alive.clear(); // class c not absorbed
  const std::vector<int> &label = work.label, &members = work.order;
  for (int begin = 0; begin < n;) {
    int end = begin;
    while (end < n && label[members[end]] == label[members[begin]])
      ++end;
    reduce_region(raw, begin, end, layer, params, ref, faces, work, out);
    begin = end;
  }
  // Deepest first; ties keep region/class order (deterministic). (One point, mostly: no
  // sort, whose buffer would be allocated.)
  if (out.size() > 1)
    std::stable_sort(out.begin(), out.end(), [](const ContactPoint &a, const ContactPoint &b) {
      return a.overlap > b.overlap;
    });
}

} // namespace tri::reduction
