// The reduction's entry points (contact_reduction.h): the raw contacts that count, in their
// deterministic order, then the chosen method: the clusters (the reduction_*.cpp files; which
// step is where: README.md) or a baseline.
#include "contact/contact_reduction.h"

#include "contact/reduction_steps.h"
#include "distance/triangle_distance.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace tri {
namespace {

using Eigen::Vector3d;
using reduction::Faces;
using reduction::finite;
using Raw = ReductionWorkspace::Raw;

// A unit reference direction whatever the caller passed.
Vector3d safe_reference(const Vector3d &ref) {
  const double len = ref.norm();
  if (std::isfinite(len) && len > 0.0)
    return ref / len;
  return Vector3d::UnitZ();
}

// The contacts reduce() reads come as TriangleContacts (reduce_contacts) or as the distance
// kernel's results on a pair list, read in place (reduce_kernel_results: a KernelContact is what
// contacts_from_results would copy into a TriangleContact). The accessors below read either;
// the geometry's fields (distance, point_a, point_b, normal, intersecting, penetration_depth)
// have the same names in TriangleContact and TrianglePairDistance.
struct KernelContact {
  const TrianglePairIndex &pair;
  const TrianglePairDistance &r;
};
const TriangleContact &geometry(const TriangleContact &c) { return c; }
const TrianglePairDistance &geometry(const KernelContact &c) { return c.r; }
int tri_a_of(const TriangleContact &c) { return c.tri_a; }
int tri_a_of(const KernelContact &c) { return c.pair.a; }
int tri_b_of(const TriangleContact &c) { return c.tri_b; }
int tri_b_of(const KernelContact &c) { return c.pair.b; }
bool exact_of(const TriangleContact &c) { return c.exact; }
bool exact_of(const KernelContact &c) { return certified_exact(c.r); }
bool apart_of(const TriangleContact &c) { return c.apart; }
bool apart_of(const KernelContact &c) { return certified_apart(c.r); }

// The two sources: every TriangleContact counts; a kernel result counts when it is closer than
// the cutoff (contacts_from_results' rule).
struct TriangleContactList {
  const TriangleContact *contacts;
  const TriangleContact &at(int k) const { return contacts[k]; }
  bool counts(int) const { return true; }
};
struct KernelResultList {
  const TrianglePairIndex *pairs;
  const TrianglePairDistance *results;
  double cutoff;
  KernelContact at(int k) const { return {pairs[k], results[k]}; }
  bool counts(int k) const { return is_triangle_contact(results[k], cutoff); }
};

// Unit normal of one raw contact: the kernel's; for a separated pair whose normal is unusable,
// the closest-point direction; else the reference direction.
template <class G> Vector3d raw_normal(const G &c, const Vector3d &ref) {
  const double len = c.normal.norm();
  if (std::isfinite(len) && len > 0.5)
    return c.normal / len;
  const Vector3d d = c.point_b - c.point_a;
  const double dl = d.norm();
  if (!c.intersecting && std::isfinite(dl) && dl > 0.0)
    return d / dl;
  return ref;
}

// A triangle contact's raw values: its distance (0 when intersecting), its overlap under the
// layer, its point (midway between the closest points).
template <class G> double contact_distance(const G &c) {
  return c.intersecting ? 0.0 : std::max(0.0, c.distance);
}
template <class G> double contact_overlap(const G &c, double layer) {
  const double depth = c.intersecting && std::isfinite(c.penetration_depth)
                           ? std::max(0.0, c.penetration_depth)
                           : 0.0;
  return layer - contact_distance(c) + depth;
}
template <class G> Vector3d contact_point(const G &c) { return 0.5 * (c.point_a + c.point_b); }

// Strict total order of raw contacts of equal overlap (deepest first before it): triangle ids,
// then coordinates, then the contacts' indices ia, ib.
template <class C> bool deeper(const C &a, const C &b, int ia, int ib) {
  if (tri_a_of(a) != tri_a_of(b))
    return tri_a_of(a) < tri_a_of(b);
  if (tri_b_of(a) != tri_b_of(b))
    return tri_b_of(a) < tri_b_of(b);
  const Vector3d pa = contact_point(geometry(a)), pb = contact_point(geometry(b));
  for (int k = 0; k < 3; ++k)
    if (pa[k] != pb[k])
      return pa[k] < pb[k];
  return ia < ib;
}

// Triangle t's plane normal (unscaled) and its squared length, from the call's cache.
const ReductionWorkspace::TriangleNormal &
triangle_normal(const TriangleSoA &soa, int t,
                std::vector<ReductionWorkspace::TriangleNormal> &cache, unsigned call) {
  ReductionWorkspace::TriangleNormal &e = cache[static_cast<std::size_t>(t)];
  if (e.stamp != call) {
    const Vector3d v0 = soa.vertex(t, 0);
    e.normal = (soa.vertex(t, 1) - v0).cross(soa.vertex(t, 2) - v0);
    e.norm2 = e.normal.squaredNorm();
    e.stamp = call;
  }
  return e;
}

// Whether triangles ta of a and tb of b are so far from parallel that contact_polygon returns
// false for them (most members are): the cosine of their angle below cos(kParallelFaceAngle) by
// a margin far above rounding, without contact_polygon's roots and divisions. Overflow or
// underflow leaves it false.
bool clearly_not_parallel(const ReductionWorkspace::TriangleNormal &na,
                          const ReductionWorkspace::TriangleNormal &nb) {
  static const double limit = std::cos(kParallelFaceAngle);
  const double c = na.normal.dot(nb.normal);
  return c * c < 0.99 * (limit * limit) * (na.norm2 * nb.norm2);
}

ContactPoint single_point(const Raw &r) {
  ContactPoint p;
  p.point = r.point;
  p.normal = r.normal;
  p.overlap = r.overlap;
  p.energy_overlap = r.overlap;
  p.min_distance = r.distance;
  p.num_merged = 1;
  p.intersecting = r.intersecting;
  p.tri_a = r.tri_a;
  p.tri_b = r.tri_b;
  p.kind = r.intersecting ? ContactKind::deep : ContactKind::vertex;
  return p;
}

// A pair's few contacts (a dozen) sorted deepest first by rank: each key's place is the number
// of keys before it, counted without branches (a comparison sort's branches are random in
// outcome and mispredict about every second time). The order is the comparator's below, a strict total order: the same permutation. Keys tied in overlap
// and both triangles (one triangle pair given twice: only a caller's own list) and larger sets
// take std::sort with the full comparator (deeper()).
template <class Source>
void sort_keys(std::vector<ReductionWorkspace::Key> &keys, const Source &contacts,
               std::vector<ReductionWorkspace::Key> &sorted) {
  using Key = ReductionWorkspace::Key;
  constexpr std::size_t kRankSortMax = 24;
  const auto before = [&](const Key &x, const Key &y) {
    if (x.overlap != y.overlap)
      return x.overlap > y.overlap;
    if (x.tri_a != y.tri_a) // deeper()'s first criteria, from the keys
      return x.tri_a < y.tri_a;
    if (x.tri_b != y.tri_b)
      return x.tri_b < y.tri_b;
    return deeper(contacts.at(x.index), contacts.at(y.index), x.index, y.index);
  };
  const std::size_t n = keys.size();
  if (n <= 1)
    return;
  if (n > kRankSortMax) {
    std::sort(keys.begin(), keys.end(), before);
    return;
  }
  // Both triangle indices in one integer (both are >= 0: reduce checked them), ordered as the
  // pair (tri_a, tri_b); signed (below 2^63), so that the compares vectorise. The overlaps and
  // pairs in arrays of their own: the count below then runs over all j in SIMD registers.
  alignas(64) double overlap[kRankSortMax];
  alignas(64) std::int64_t pair[kRankSortMax];
  for (std::size_t i = 0; i < n; ++i) {
    overlap[i] = keys[i].overlap;
    pair[i] = static_cast<std::int64_t>(
        static_cast<std::uint64_t>(static_cast<std::uint32_t>(keys[i].tri_a)) << 32 |
        static_cast<std::uint32_t>(keys[i].tri_b));
  }
  int rank[kRankSortMax];
  std::int64_t ties = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double oi = overlap[i];
    const std::int64_t pi = pair[i];
    std::int64_t r = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const bool same_overlap = overlap[j] == oi;
      r += (overlap[j] > oi) | (same_overlap & (pair[j] < pi));
      ties += same_overlap & (pair[j] == pi);
    }
    rank[i] = static_cast<int>(r);
  }
  if (ties != static_cast<std::int64_t>(n)) { // a key ties with another than itself
    std::sort(keys.begin(), keys.end(), before);
    return;
  }
  sorted.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    sorted[static_cast<std::size_t>(rank[i])] = keys[i];
  keys.swap(sorted);
}

// The contacts that count, as keys (which move cheaper than raw contacts): in range, with an
// overlap (beyond the lifts' reach where smooth surfaces may reach past the facets) and a
// finite point.
template <class Source>
void collect_keys(const Source &contacts, int n, const Faces &faces, double layer,
                  const ReductionParams &params, std::vector<ReductionWorkspace::Key> &keys) {
  const int na = faces.a->num_triangles(), nb = faces.b->num_triangles();
  keys.clear();
  for (int k = 0; k < n; ++k) {
    if (!contacts.counts(k))
      continue;
    const auto &c = contacts.at(k);
    const int ta = tri_a_of(c), tb = tri_b_of(c);
    if (ta < 0 || ta >= na || tb < 0 || tb >= nb)
      throw std::out_of_range("reduce_contacts: contact " + std::to_string(k) +
                              " names triangles " + std::to_string(ta) + ", " + std::to_string(tb) +
                              " of meshes with " + std::to_string(na) + ", " + std::to_string(nb));
    const double overlap = contact_overlap(geometry(c), layer);
    if (!(overlap > -params.surface_lift)) // 0 but where smooth surfaces reach past the facets
      continue;
    if (!finite(contact_point(geometry(c))))
      continue; // nothing sensible to place; the kernel never produces this
    // Field by field: a braced key went through the stack and stalled on store forwarding.
    ReductionWorkspace::Key &key = keys.emplace_back();
    key.overlap = overlap;
    key.index = k;
    key.tri_a = ta;
    key.tri_b = tb;
  }
}

// Sizes the per-triangle normal caches and starts a new call's stamp.
void start_normal_caches(const Faces &faces, ReductionWorkspace &work) {
  const int na = faces.a->num_triangles(), nb = faces.b->num_triangles();
  if (work.normals_a.size() < static_cast<std::size_t>(na))
    work.normals_a.resize(na);
  if (work.normals_b.size() < static_cast<std::size_t>(nb))
    work.normals_b.resize(nb);
  if (++work.call == 0) { // the stamps wrapped: none may look valid
    for (auto &e : work.normals_a)
      e.stamp = 0;
    for (auto &e : work.normals_b)
      e.stamp = 0;
    work.call = 1;
  }
}

// The raw contacts in the keys' order (work.raw: every field written).
template <class Source>
void fill_raw(const Source &contacts, const Faces &faces, const ReductionParams &params,
              const Vector3d &ref, ReductionWorkspace &work) {
  const std::vector<ReductionWorkspace::Key> &keys = work.keys;
  std::vector<Raw> &raw = work.raw;
  raw.resize(keys.size()); // every field written below (only the growth is zeroed)
  start_normal_caches(faces, work);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto &c = contacts.at(keys[k].index);
    const auto &g = geometry(c);
    Raw &r = raw[k];
    r.point = contact_point(g);
    r.normal = raw_normal(g, ref);
    r.separation = g.intersecting ? Vector3d::Zero() : Vector3d(g.point_b - g.point_a);
    r.overlap = keys[k].overlap;
    r.distance = contact_distance(g);
    r.tri_a = keys[k].tri_a;
    r.tri_b = keys[k].tri_b;
    r.intersecting = g.intersecting;
    r.exact = exact_of(c);
    r.apart = apart_of(c);
    r.maybe_parallel =
        params.method == ReductionMethod::clusters &&
        !clearly_not_parallel(triangle_normal(*faces.a, r.tri_a, work.normals_a, work.call),
                              triangle_normal(*faces.b, r.tri_b, work.normals_b, work.call));
  }
}

// The paper's baseline: a point per raw contact farther than min_width from every deeper one
// kept, the others counted into the first such point.
void reduce_paper_min_width(const std::vector<Raw> &raw, double min_width,
                            std::vector<ContactPoint> &out) {
  const double w2 = min_width * min_width;
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
}

template <class Source>
void reduce(const Source &contacts, int n, const Faces &faces, double eps_a, double eps_b,
            const ReductionParams &params, ReductionWorkspace &work,
            std::vector<ContactPoint> &out) {
  out.clear();
  const double layer = eps_a + eps_b;
  const Vector3d ref = safe_reference(params.reference_direction);
  // The contacts that count, deepest first (`deeper`), sorted as keys; then the raw contacts
  // in that order.
  collect_keys(contacts, n, faces, layer, params, work.keys);
  if (work.keys.empty()) {
    work.raw.clear();
    return;
  }
  sort_keys(work.keys, contacts, work.sorted_keys);
  fill_raw(contacts, faces, params, ref, work);
  switch (params.method) {
  case ReductionMethod::none:
    for (const Raw &r : work.raw)
      out.push_back(single_point(r));
    return;
  case ReductionMethod::paper_min_width:
    reduce_paper_min_width(work.raw, params.min_width, out);
    return;
  case ReductionMethod::clusters:
    reduction::reduce_clusters(work.raw, layer, params, ref, faces, work, out);
    return;
  }
}

} // namespace

double recommended_link_length(double longest_edge_a, double longest_edge_b, double eps_a,
                               double eps_b) {
  const double edge = std::min(longest_edge_a, longest_edge_b);
  return (2.0 * edge + eps_a + eps_b) * (1.0 + 1e-9);
}

void reduce_contacts(const TriangleContact *contacts, int n, const TriangleSoA &tris_a,
                     double eps_a, const TriangleSoA &tris_b, double eps_b,
                     const ReductionParams &params, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out) {
  reduce(TriangleContactList{contacts}, n,
         Faces{&tris_a, &tris_b, params.edge_bulge_a, params.edge_bulge_b, params.surface_lift},
         eps_a, eps_b, params, work, out);
}

void reduce_kernel_results(const TrianglePairIndex *pairs, const TrianglePairDistance *results,
                           int count, double cutoff, const TriangleSoA &tris_a, double eps_a,
                           const TriangleSoA &tris_b, double eps_b, const ReductionParams &params,
                           ReductionWorkspace &work, std::vector<ContactPoint> &out) {
  reduce(KernelResultList{pairs, results, cutoff}, count,
         Faces{&tris_a, &tris_b, params.edge_bulge_a, params.edge_bulge_b, params.surface_lift},
         eps_a, eps_b, params, work, out);
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
