// Reduction of triangle-pair contacts to contact points; the design is in the header.
#include "contact/contact_reduction.h"

#include "contact/contact_polygon.h"
#include "contact/point_links.h"
#include "contact/smooth_peak.h"
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
using Raw = ReductionWorkspace::Raw;

bool finite(const Vector3d &v) { return std::isfinite(v.x() + v.y() + v.z()); }

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

// Deep penetration: in a component with intersecting pairs, separated pairs that face against
// them are seen from behind the other surface; flip them (header, "Intersecting triangles").
// True if it flipped any.
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

// Step 5c: the share of a class's raw overlap on members without a polygon from which on a
// curved patch keeps its deepest corner (smoothly from 0).
constexpr double kCurvedOutsideShare = 0.05;
// Step 5c: the number of facets a patch spans from which on its moments' peak starts to count,
// and from which on it is used alone (smoothly between).
// Step 5c: the angle between neighbouring facets up to which a curved patch is a smooth surface
// (then smoothly to twice it, where it is its facets).
constexpr double kCurvedFineAngle = 0.08;
constexpr double kCurvedFacetsFrom = 2.0;
constexpr double kCurvedFacetsFull = 8.0;

// Members within this fraction of the layer of the deepest one share the deepest point, with
// weights falling linearly to zero across it (header, step 5).
constexpr double kDeepestTaper = 1e-3;
// Members closer than this fraction of the layer, and tied in overlap (kNormalDepthBand), are
// one closest point seen by several triangle pairs: the smooth maximum counts it once (step 5).
constexpr double kSameFeatureDistance = 1e-4;

// The two bodies' triangles (never null).
struct Faces {
  const TriangleSoA *a, *b;
  const double *bulge_a = nullptr, *bulge_b = nullptr; // smooth_surface.h, 3 per triangle
  double lift = 0.0; // m, ReductionParams::surface_lift
};

// Triangle t's plane normal (unscaled) and its squared length, from the call's cache.
const ReductionWorkspace::TriangleNormal &
triangle_normal(const TriangleSoA &soa, int t, std::vector<ReductionWorkspace::TriangleNormal> &cache,
                unsigned call) {
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

// The member's contact polygon (header, step 5) if its triangles are nearly parallel and their
// overlap has an area beyond rounding; false otherwise.
bool member_polygon(const Raw &r, const Faces &faces, double layer, ContactPolygon &poly) {
  const TriangleSoA &ta = *faces.a, &tb = *faces.b;
  if (!r.maybe_parallel)
    return false; // as contact_polygon would
  if (!contact_polygon(ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2),
                       tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2),
                       r.normal, layer, poly))
    return false;
  return poly.weight > 0.0 && poly.area > kPatchAreaRounding * poly.min_triangle_area;
}

// A polygon member's overlap, exact: layer minus the brute-force distance of its two triangles
// (triangle_distance.h, exact to rounding, where the hybrid kernel is exact to its tolerance);
// the raw overlap of an intersecting or flipped (sunk) member, or of one whose distance the
// kernel certified exact already (about a third of them, mostly brute-force fallbacks).
double exact_overlap(const Raw &r, const Faces &faces, double layer) {
  if (r.intersecting || r.overlap > layer || r.exact)
    return r.overlap;
  const TriangleSoA &ta = *faces.a, &tb = *faces.b;
  const Vector3d a[3] = {ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2)};
  const Vector3d b[3] = {tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2)};
  if (r.apart) { // the same value (to rounding) without the intersection test
    const double distance = separated_triangle_distance(a, b);
    return distance < 0.0 ? r.overlap : layer - distance;
  }
  const TrianglePairDistance d = triangle_distance(a, b);
  return d.intersecting ? r.overlap : layer - d.distance;
}

// The blend of step 5b: beta(r) = 1 - 3 r^2 + 2 r^3 for the flat-patch measure r (1 lying flat,
// 0 from r = 1 on, C1 at both ends) and its derivative. Also the contact's face weight (step 6).
double flat_blend(double r) {
  if (!(r < 1.0))
    return 0.0;
  const double q = std::max(0.0, r);
  return (1.0 - q) * (1.0 - q) * (1.0 + 2.0 * q);
}
double flat_blend_slope(double r) {
  if (!(r < 1.0) || !(r > 0.0))
    return 0.0;
  return -6.0 * r * (1.0 - r);
}

// Corner i's overlap for the deepest point (step 5b): the larger of the affine one and layer
// minus its exact closest-point distance (contact_polygon.h) for a member that is separated
// (`layer` > 0); the affine one for an intersecting or sunk member (`layer` < 0) and on the
// layer's cut. Never below the affine one, so a polygon whose region reaches above the level
// has a corner above it.
double corner_overlap(const ContactPolygon &poly, double layer, int i) {
  if (layer > 0.0 && poly.corner_distances[i] >= 0.0)
    return std::max(poly.corner_overlaps[i], layer - poly.corner_distances[i]);
  return poly.corner_overlaps[i];
}

// Smoothstep 3 x^2 - 2 x^3 on [0, 1], 0 below, 1 above.
double smoothstep(double x) {
  if (!(x > 0.0))
    return 0.0;
  if (!(x < 1.0))
    return 1.0;
  return x * x * (3.0 - 2.0 * x);
}

// The class's deepest overlap as the energy sees it (header, step 5), a smooth maximum F of the
// overlaps o_i of its members raw[cands[i]]. With a_i = 1 - (D - o_i) / taper (D the largest o_i; only a_i > 0
// count), w_i the member's share of its closest point (below), weights m_i = w_i a_i^2 / sum w_j a_j^2
// and u <= 0 solving sum m_i (a_i - u)^2 = 1:
//   u = A - sqrt(A^2 + 1 - B),  A = sum w a^3 / sum w a^2,  B = sum w a^4 / sum w a^2,
//   F = D + g taper u,  g = smoothstep(D / taper) (F is 0 when a contact starts or ends).
// F = D for a lone deepest candidate and for any number tied with it (so the overlap of a face
// or an edge does not depend on how many triangle pairs see it), dips by at most a fraction of
// the taper in between, and is C1 in every o_i (a candidate enters with weight and slope 0).
// Its gradient gives the point, normal and force: c_k = dF/do_k = g du/da_k, plus, shared by
// the candidates tied with the deepest (tie_band) in proportion to w_k,
// 1 + taper u g' - g sum_i du/da_i.
// normal_scale = |sum c_k n_k|: the force is kn F normal_scale along `normal`. `weights`
// receives the c_k, `share` the w_k (same_point: the distance within which tied members are one
// point).
struct SmoothDeepest {
  double overlap = 0.0, normal_scale = 1.0;
  Vector3d point, normal;
};
SmoothDeepest smooth_deepest(const std::vector<Raw> &raw, const std::vector<int> &cands,
                             double taper, double tie_band, double same_point,
                             const Vector3d &fallback_point, const Vector3d &fallback_normal,
                             std::vector<double> &weights, std::vector<double> &share) {
  double D = -std::numeric_limits<double>::infinity();
  for (int i : cands)
    D = std::max(D, raw[i].overlap);
  int num_active = 0, last_active = 0;
  weights.resize(cands.size()); // a_k for now
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const double a = 1.0 - (D - raw[cands[k]].overlap) / taper;
    weights[k] = a;
    if (a > 0.0) {
      ++num_active;
      last_active = static_cast<int>(k);
    }
  }
  if (num_active == 1) { // the usual case: one deepest member, F = D, all of its gradient
    const Raw &d = raw[cands[last_active]];
    weights.assign(cands.size(), 0.0);
    weights[last_active] = 1.0;
    SmoothDeepest out;
    out.overlap = D;
    out.point = d.point;
    out.normal = finite(d.normal) ? d.normal : fallback_normal; // unit (raw_normal)
    return out;
  }
  // Each closest point counts once, however many triangle pairs see it: an edge crossing a
  // face's edge is seen by up to four, and when a pair's closest point jumps from one end of a
  // parallel edge to the other (two crossings tied in depth), the counts of the two points
  // swap. Counted per member, the smooth maximum's weights (and with them the point of the
  // force) would jump there by a third of the distance between the points, so a member's share
  // is 1 / (the active members at its point with its overlap). Ties within tie_band only: a
  // merge or split then moves F by at most half of it.
  double s2 = 0.0, s3 = 0.0, s4 = 0.0;
  share.assign(cands.size(), 0.0);
  // Deepest first (the reduction's order, mostly): ties with a member are then a window
  // around it, since |o_j - o_k| only grows (rounding included) with the distance in order.
  bool sorted = true;
  for (std::size_t k = 1; k < cands.size(); ++k)
    sorted = sorted && raw[cands[k - 1]].overlap >= raw[cands[k]].overlap;
  const double same2 = same_point * same_point;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const double a = weights[k];
    if (!(a > 0.0))
      continue;
    const Raw &rk = raw[cands[k]];
    int count = 0;
    if (sorted) { // the members tied with k's overlap are the ones next to it
      std::size_t lo = k, hi = k + 1;
      while (lo > 0 && std::abs(raw[cands[lo - 1]].overlap - rk.overlap) <= tie_band)
        --lo;
      while (hi < cands.size() && std::abs(raw[cands[hi]].overlap - rk.overlap) <= tie_band)
        ++hi;
      for (std::size_t j = lo; j < hi; ++j)
        count += weights[j] > 0.0 && (raw[cands[j]].point - rk.point).squaredNorm() <= same2;
    } else {
      for (std::size_t j = 0; j < cands.size(); ++j) {
        const Raw &rj = raw[cands[j]];
        count += weights[j] > 0.0 && std::abs(rj.overlap - rk.overlap) <= tie_band &&
                 (rj.point - rk.point).squaredNorm() <= same2;
      }
    }
    const double w = 1.0 / std::max(1, count);
    share[k] = w;
    s2 += w * a * a;
    s3 += w * a * a * a;
    s4 += w * a * a * a * a;
  }
  const double A = s3 / s2, B = s4 / s2; // s2 >= 1 to rounding: the deepest point has a = 1
  const double R = std::sqrt(std::max(0.0, A * A + 1.0 - B));
  const double u = A - R;
  const double x = D / taper;
  const double g = smoothstep(x);
  const double g_slope = x > 0.0 && x < 1.0 ? 6.0 * x * (1.0 - x) / taper : 0.0;
  // du/da_k = dA - (A dA - dB / 2) / R, dA = (3 a^2 s2 - 2 a s3) / s2^2, dB likewise.
  std::vector<double> &slope = weights; // a_k, then du/da_k, then c_k in place
  double sum_slope = 0.0;
  const double inv_s2s2 = 1.0 / (s2 * s2);
  for (std::size_t k = 0; k < slope.size(); ++k) {
    const double a = slope[k];
    double du = 0.0;
    if (a > 0.0 && R > 0.0) {
      const double dA = share[k] * (3.0 * a * s2 - 2.0 * s3) * a * inv_s2s2;
      const double dB = share[k] * (4.0 * a * a * s2 - 2.0 * s4) * a * inv_s2s2;
      du = dA - (A * dA - 0.5 * dB) / R;
    }
    slope[k] = du;
    sum_slope += du;
  }
  // The deepest's own part of the gradient, split over the members tied with it by their
  // shares: each tied point gets an equal part, however many pairs see it.
  double top_weight = 0.0;
  for (std::size_t k = 0; k < cands.size(); ++k)
    if (raw[cands[k]].overlap >= D - tie_band)
      top_weight += share[k];
  const double top_part = (1.0 + taper * u * g_slope - g * sum_slope) / top_weight;
  Vector3d sum_p = Vector3d::Zero(), sum_n = Vector3d::Zero();
  double sum_c = 0.0;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const Raw &d = raw[cands[k]];
    double c_k = g * slope[k];
    if (d.overlap >= D - tie_band)
      c_k += top_part * share[k];
    weights[k] = c_k;
    if (c_k == 0.0)
      continue;
    sum_p += c_k * d.point;
    sum_c += c_k;
    if (finite(d.normal))
      sum_n += c_k * d.normal;
  }
  SmoothDeepest out;
  out.overlap = D + taper * u * g;
  out.point = sum_c > 0.0 ? Vector3d(sum_p / sum_c) : fallback_point;
  const double len = sum_n.norm();
  if (std::isfinite(len) && len > 1e-3 * std::abs(sum_c)) {
    out.normal = sum_n / len;
    out.normal_scale = len;
    // F's gradient under rotation is the moment sum_k c_k x_k x n_k; one force N = sum c n
    // has it exactly, but for its part along N (a twist), when it acts at p + N x M / |N|^2
    // (M the moment about p, the weighted centroid): members with different normals at
    // different points (a gear's teeth) would otherwise turn the bodies the wrong amount.
    Vector3d moment = Vector3d::Zero();
    for (std::size_t k = 0; k < cands.size(); ++k)
      if (weights[k] != 0.0 && finite(raw[cands[k]].normal))
        moment += weights[k] * (raw[cands[k]].point - out.point).cross(raw[cands[k]].normal);
    const Vector3d shift = sum_n.cross(moment) / (len * len);
    if (finite(shift))
      out.point += shift;
  } else {
    out.normal = fallback_normal;
    out.normal_scale = sum_c;
  }
  return out;
}

// How curved a patch is (step 5c): 0 while its polygons' overlap gradients agree (a face on a
// face, tilted or not: the deepest corner is the peak of the real surfaces), 1 once they spread
// by 2 kFlatGradientSpread (the facets of a ball, a vertex's or an edge's facets: the moments'
// peak). The complement of face_weight_of's spread factor.
double curved_weight(double spread) {
  return smoothstep((spread - kFlatGradientSpread) / kFlatGradientSpread);
}

// Face weight of a patch (step 6): 1 when its polygons are the overlap of two flat regions
// (the same overlap gradient over the whole patch: a face on a face, tilted or not, evenly or
// eccentrically pressed), 0 when the gradient turns over the patch (the facets of a ball, a
// curved surface: spread above 2 kFlatGradientSpread) or the faces are about to leave the
// polygons' range (tilt from kParallelFaceAngle / 2 to kParallelFaceAngle): smooth in both.
// spread, tilt: the area-weighted RMS deviation and the magnitude of the mean of the
// polygons' overlap gradients (1: the slope of the local overlap).
double face_weight_of(double spread, double tilt) {
  const double tilt_full = 2.0 * std::tan(0.25 * kParallelFaceAngle);
  const double tilt_end = 2.0 * std::tan(0.5 * kParallelFaceAngle);
  return (1.0 - curved_weight(spread)) *
         (1.0 - smoothstep((tilt - tilt_full) / (tilt_end - tilt_full)));
}

// The deepest point of the smooth surfaces that two bodies' facets sample (smooth_surface.h)
// over one class's members: each nearly parallel member's polygon, clipped where the lifts may
// still reach (the layer widened by faces.lift), with the lifts of its two facets.
struct SmoothFound {
  bool found = false;
  double overlap = 0.0;
  Vector3d point = Vector3d::Zero(), normal = Vector3d::UnitZ();
};
SmoothFound smooth_surface_peak(const std::vector<Raw> &raw, const std::vector<int> &members,
                                const std::vector<int> &cls, const std::vector<int> &absorbed,
                                int c, double layer, const Faces &faces) {
  SmoothFound best;
  ContactPolygon poly;
  const TriangleSoA &ta = *faces.a, &tb = *faces.b;
  for (int i : members) {
    if (cls[i] != c || absorbed[i])
      continue;
    const Raw &r = raw[i];
    if (!r.maybe_parallel)
      continue;
    const Vector3d a[3] = {ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2)};
    const Vector3d b[3] = {tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2)};
    if (!contact_polygon(a[0], a[1], a[2], b[0], b[1], b[2], r.normal, layer + faces.lift, poly) ||
        !(poly.area > kPatchAreaRounding * poly.min_triangle_area))
      continue;
    const SmoothPeak peak =
        smooth_peak(poly, a, faces.bulge_a ? faces.bulge_a + 3 * r.tri_a : nullptr, b,
                    faces.bulge_b ? faces.bulge_b + 3 * r.tri_b : nullptr, faces.lift);
    if (!best.found || peak.overlap > best.overlap) {
      best.found = true;
      best.overlap = peak.overlap;
      best.point = peak.point;
      best.normal = peak.normal;
    }
  }
  return best;
}

// Class c's ContactKind but deep (ContactKind, header): face from its face weight, else edge or
// vertex from how far the members tied with the deepest lie from it.
ContactKind class_kind(const ContactPoint &p, const std::vector<Raw> &raw,
                       const std::vector<int> &members, const std::vector<int> &cls,
                       const std::vector<int> &absorbed, int c, double layer) {
  if (p.intersecting)
    return ContactKind::deep;
  if (p.face_weight >= 0.5)
    return ContactKind::face;
  const Raw *deepest = nullptr;
  for (int i : members)
    if (cls[i] == c && !absorbed[i] && (!deepest || raw[i].overlap > deepest->overlap))
      deepest = &raw[i];
  if (!deepest)
    return ContactKind::vertex;
  const double tied = deepest->overlap - kDeepestTaper * layer;
  double spread2 = 0.0;
  for (int i : members)
    if (cls[i] == c && !absorbed[i] && raw[i].overlap >= tied)
      spread2 = std::max(spread2, (raw[i].point - deepest->point).squaredNorm());
  return spread2 > layer * layer ? ContactKind::edge : ContactKind::vertex;
}

ContactPoint make_point(const std::vector<Raw> &raw, const std::vector<int> &members,
                        const std::vector<int> &cls, const std::vector<int> &absorbed, int c,
                        int seed, double layer, const Vector3d &ref, const Faces &faces,
                        double tolerance, ReductionWorkspace &work) {
  ContactPoint p;
  std::vector<ContactPolygon> &polygons = work.polygons;
  std::vector<double> &polygon_exact = work.polygon_layers;
  std::vector<int> &plain = work.plain;
  // `polygons` only grows: entries [0, num_polygons) are this class's. Reusing the slots keeps
  // emplace_back from zeroing a 3 KB ContactPolygon per member (value-initialisation).
  std::size_t num_polygons = 0;
  polygon_exact.clear();
  plain.clear();
  const Raw &s = raw[seed];
  double deepest_plain = -std::numeric_limits<double>::infinity(); // members without a polygon
  double D_poly = 0.0; // the polygon members' deepest overlap, exact (step 5b)
  double plain_overlap = 0.0, member_overlap = 0.0; // step 5c: how much lies outside polygons
  // A member's exact overlap lies at most `tolerance` above its kernel overlap (and never below
  // it beyond rounding), so one that stays below the deepest exact one found so far by more
  // than that cannot be the deepest: its triangle distance is not recomputed. The members come
  // deepest first, so mostly only the first is.
  const double exact_slack =
      tolerance + 1e-9 * layer + 1e-13 * raw[seed].point.cwiseAbs().maxCoeff();
  const double taper = kDeepestTaper * layer;
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
    if (num_polygons == polygons.size())
      polygons.emplace_back();
    if (member_polygon(r, faces, layer, polygons[num_polygons])) { // filled in place
      ++num_polygons;
      polygon_exact.push_back(!(r.intersecting || r.overlap > layer) ? layer : -1.0);
      if (!(r.overlap + exact_slack < D_poly))
        D_poly = std::max(D_poly, exact_overlap(r, faces, layer));
    } else {
      deepest_plain = std::max(deepest_plain, r.overlap);
      plain_overlap += std::max(0.0, r.overlap); // (< 0: facets only within the lifts' reach)
      plain.push_back(i);
    }
    member_overlap += std::max(0.0, r.overlap);
  }
  p.tri_a = s.tri_a;
  p.tri_b = s.tri_b;

  // The kernel's deepest overlap, point and normal over the members without a polygon (all of
  // them when there are no polygons): step 4 and 5.
  auto kernel_deepest = [&](double D, bool plain_only, Vector3d &point, Vector3d &normal) {
    Vector3d sum_n = Vector3d::Zero(), sum_p = Vector3d::Zero();
    double sum_wn = 0.0, sum_wp = 0.0;
    for (int i : members) {
      if (cls[i] != c || absorbed[i])
        continue;
      const Raw &r = raw[i];
      if (plain_only && r.overlap > D)
        continue; // a polygon member (deeper ones are polygon members by construction)
      const double tied = 1.0 - (D - r.overlap) / taper;
      if (tied > 0.0) {
        sum_p += tied * r.point;
        sum_wp += tied;
      }
      if (r.overlap >= D - kNormalDepthBand * layer) {
        sum_n += r.overlap * r.normal;
        sum_wn += r.overlap;
      }
    }
    point = sum_wp > 0.0 ? Vector3d(sum_p / sum_wp) : s.point;
    const double len = sum_n.norm();
    if (std::isfinite(len) && len > 1e-3 * sum_wn)
      normal = sum_n / len;
    else
      normal = finite(s.normal) ? s.normal : ref;
  };

  // The deepest point of the smooth surfaces (smooth_surface.h): over every nearly parallel
  // member, its polygon clipped where the lifts may still reach (o >= -lift).
  SmoothFound smooth;
  if (faces.bulge_a || faces.bulge_b)
    smooth = smooth_surface_peak(raw, members, cls, absorbed, c, layer, faces);
  const Vector3d fallback_normal = finite(s.normal) ? s.normal : ref;
  if (num_polygons == 0) {
    const SmoothDeepest sd =
        smooth_deepest(raw, plain, taper, kNormalDepthBand * layer, kSameFeatureDistance * layer,
                       s.point, fallback_normal, work.smooth_scratch, work.smooth_share);
    p.point = sd.point;
    p.normal = sd.normal;
    p.overlap = sd.overlap * sd.normal_scale;
    p.energy_overlap = sd.overlap;
    if (smooth.found && smooth.overlap > sd.overlap) {
      // No facet overlaps yet (or only at a clear angle): the smooth surfaces decide where they
      // reach past the facets, fully from a taper on.
      const double gain = smooth.overlap - sd.overlap;
      const double t = smoothstep(gain / taper);
      p.point += t * (smooth.point - p.point);
      p.normal = (p.normal + t * (smooth.normal - p.normal)).normalized();
      p.energy_overlap = smooth.overlap;
      p.overlap = smooth.overlap * ((1.0 - t) * sd.normal_scale + t);
    }
    return p;
  }

  // Step 5b with polygons. Their deepest overlap and its region, exact functions of the two
  // triangles (no kernel tolerance), moments relative to the seed's midpoint (near the patch:
  // no digits lost far from the world origin).
  // The level of the deepest region: the taper below the deepest corner (a corner is the
  // deepest point of its polygon; where the closest points are an edge-edge pair inside the
  // polygons the corners may lie below the exact D).
  double deepest_corner = 0.0;
  for (std::size_t k = 0; k < num_polygons; ++k)
    deepest_corner = std::max(deepest_corner, polygons[k].max_overlap);
  const double level = std::min(D_poly, deepest_corner) - taper;
  double excess = 0.0;
  Vector3d excess1 = Vector3d::Zero(), excess_normal = Vector3d::Zero();
  double area = 0.0, weight = 0.0, weight2 = 0.0, facet_area = 0.0;
  Vector3d area1 = Vector3d::Zero(), pressure1 = Vector3d::Zero(), area_normal = Vector3d::Zero();
  Eigen::Matrix3d area2 = Eigen::Matrix3d::Zero();
  Vector3d gradient1 = Vector3d::Zero();
  double gradient2 = 0.0;
  for (std::size_t k = 0; k < num_polygons; ++k) {
    const ContactPolygon &poly = polygons[k];
    // Each polygon's deepest region, tapered (continuous in the geometry): its weight is the
    // excess of o over the level integrated over the polygon (mesh-independent), its point the
    // polygon's corners above the level weighted by their excess -- the deepest corner itself
    // when it alone is deepest (a vertex of a tilted face: exactly the point of the gradient of
    // D), the middle of a tied edge when an edge lies flat (header, step 5b).
    const ExcessIntegral e = excess_over(poly, level, s.point);
    if (e.weight > 0.0) {
      Vector3d corner_sum = Vector3d::Zero();
      double corner_weight = 0.0;
      for (int i = 0; i < poly.num_vertices; ++i) {
        const double w = corner_overlap(poly, polygon_exact[k], i) - level;
        if (w > 0.0) {
          corner_sum += w * (poly.corner_points[i] - s.point);
          corner_weight += w;
        }
      }
      if (corner_weight > 0.0) {
        excess += e.weight;
        excess1 += e.weight * (corner_sum / corner_weight);
      }
    }
    excess_normal += e.weight * poly.direction;
    const Vector3d d = poly.area_centroid - s.point;
    area += poly.area;
    facet_area += poly.weight * poly.min_triangle_area;
    weight += poly.weight;
    weight2 += poly.weight2;
    area1 += poly.area * d;
    pressure1 += poly.weight * (poly.centroid - s.point);
    area2 += poly.second_moment + poly.area * d * d.transpose();
    area_normal += poly.area * poly.direction;
    gradient1 += poly.area * poly.overlap_gradient;
    gradient2 += poly.area * poly.overlap_gradient.squaredNorm();
  }
  // excess > 0: the deepest corner exceeds the level (its polygon has a region above it).
  const Vector3d poly_deepest = excess > 0.0 ? Vector3d(s.point + excess1 / excess) : s.point;
  const Vector3d poly_normal = area_normal.normalized(); // area > 0: never zero
  const double excess_len = excess_normal.norm();
  const Vector3d poly_deepest_normal =
      excess_len > 0.0 ? Vector3d(excess_normal / excess_len) : poly_normal;
  const double mean = weight / area, mean_square = weight2 / area;
  // How uneven, over the patch or over a layer's width, whichever is wider: a polygon that
  // shrinks to a sliver at a corner is uniform by its size alone, however steep its faces, and
  // judged flat its energy (a mean over a region whose edges move) would lose the work of those
  // edges: a tilted face's unevenness across a layer, slope x layer / 2, keeps it the deepest
  // pair's. Wide patches are uneven over their own width first, so it changes nothing there.
  const double unevenness = std::max(0.0, D_poly - mean);
  const double slant = 0.5 * layer * (gradient1 / area).norm();
  const double uneven_total = std::hypot(unevenness, slant);
  const double r = uneven_total / (kFlatPatchBand * D_poly);
  // dr/d(D - mean): the share of the unevenness that the patch's own overlaps carry.
  const double uneven_share = uneven_total > 0.0 ? unevenness / uneven_total : 1.0;
  const double beta = flat_blend(r);

  // A body that samples a smooth surface (smooth_surface.h) is measured on it: the polygons'
  // deepest point with the facets' lifts, which is D_poly where no lift reaches (flat facets,
  // no smooth edge: nothing changes), and takes over the point and normal once it lies a taper
  // above the facets' deepest corner.
  const double smooth_gain = smooth.found ? std::max(0.0, smooth.overlap - D_poly) : 0.0;
  const Vector3d smooth_point = smooth.found ? smooth.point : poly_deepest;
  const Vector3d smooth_normal = smooth.found ? smooth.normal : poly_deepest_normal;
  const double smooth_blend = smoothstep(smooth_gain / taper);
  // Members without a polygon (a face's own rim seen edge-on, an edge at a clear angle) take
  // over only where they are deeper than the polygons by more than the taper: within it they
  // are the same closest points seen through the kernel's tolerance (step 5b).
  const double D_surface = D_poly + smooth_gain;
  const double plain_share = smoothstep((deepest_plain - D_surface - taper) / taper);
  double D = D_surface;
  Vector3d deepest = poly_deepest, deepest_normal;
  if (smooth_blend > 0.0)
    deepest += smooth_blend * (smooth_point - poly_deepest);
  {
    Vector3d kernel_point, kernel_normal;
    kernel_deepest(s.overlap, false, kernel_point, kernel_normal);
    // Near flat the polygons orient the deepest point; from the band's end on, the kernel's
    // closest points (the direction of the gradient of a tilted face's overlap).
    deepest_normal = beta * poly_deepest_normal + (1.0 - beta) * kernel_normal;
    if (smooth_blend > 0.0)
      deepest_normal += smooth_blend * (smooth_normal - deepest_normal);
    if (plain_share > 0.0) {
      Vector3d plain_point, plain_normal;
      kernel_deepest(deepest_plain, true, plain_point, plain_normal);
      D += plain_share * (deepest_plain - D_surface);
      deepest += plain_share * (plain_point - deepest);
      deepest_normal += plain_share * (plain_normal - deepest_normal);
    }
    deepest_normal.normalize();
  }
  p.point = deepest;
  p.overlap = p.energy_overlap = D;
  p.normal = deepest_normal;
  const Vector3d mean_gradient = gradient1 / area;
  const double spread = std::sqrt(std::max(0.0, gradient2 / area - mean_gradient.squaredNorm()));
  // Step 5c: a curved patch (its overlap gradient turns over it) takes the peak of its moments
  // instead of its deepest corner; w is how curved, times the estimate's validity.
  const double curved_base =
      curved_weight(spread) * (1.0 - plain_share) * (1.0 - smooth_blend);
  // Only a patch that spans many facets is a smooth surface seen through its facets: one or
  // two facets (a vertex, an edge, a rock's corner) are the surface itself, and their deepest
  // corner is its peak. Facets spanned by the polygons of step 5b: n = M1 / (D f), f their
  // overlap-weighted smaller triangle area (continuous as polygons enter at o = 0; a
  // paraboloid's n is half the facets under its area). n has a known gradient (dM1 =
  // A do(c_A), dD = do(p_D), exact while the patch lies within the polygons' 10 degrees, as it
  // does while n is small), so the blend's own gradient enters the force (below) and a ball
  // passing through it keeps its energy.
  const double facet_scale = weight > 0.0 ? facet_area / weight : 0.0;
  const double facets = facet_scale > 0.0 && D > 0.0 ? weight / (D * facet_scale) : 0.0;
  const double facets_u = (facets - kCurvedFacetsFrom) / (kCurvedFacetsFull - kCurvedFacetsFrom);
  double w = 0.0, other_weights = 0.0;
  CurvedPeak curved;
  OverlapMoments mo;
  Vector3d curved_area_centre = Vector3d::Zero(), curved_pressure_centre = Vector3d::Zero(),
           curved_second_centre = Vector3d::Zero(), curved_normal = Vector3d::Zero();
  if (curved_base > 0.0 && facets_u > 0.0) {
    for (std::size_t k = 0; k < num_polygons; ++k)
      add_overlap_moments(polygons[k], layer, deepest_normal, s.point, mo);
    // A ball's cap reaches facets tilted past the 10 degrees of step 5b (at an overlap of
    // 1.5 % of its radius): their polygons up to kCurvedFacetAngle enter the moments only.
    // What is left without a polygon (a steep side, an edge's other face) cuts the patch off,
    // and its moments' peak is not its own: it keeps the deepest corner.
    ContactPolygon wide;
    // (A member whose triangles are within that angle but whose polygon is empty -- a facet
    // over one wall triangle seen through the next one's edge -- is no part of the field.)
    for (int i : plain) {
      const Raw &r = raw[i];
      const TriangleSoA &ta = *faces.a, &tb = *faces.b;
      if (!contact_polygon(ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2),
                           tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2),
                           r.normal, layer, wide, kCurvedFacetAngle))
        continue;
      plain_overlap -= r.overlap;
      if (wide.weight > 0.0 && wide.area > kPatchAreaRounding * wide.min_triangle_area)
        add_overlap_moments(wide, layer, deepest_normal, s.point, mo);
    }
    const double outside = member_overlap > 0.0 ? std::max(0.0, plain_overlap) / member_overlap
                                                : 0.0;
    // The angle between neighbouring facets, phi = h / R: a body's curvature 1 / R from how
    // its normal turns over the patch's radius a (a sphere's cap: RMS deviation a /
    // (sqrt(2) R)), the more curved of the two bodies, h the facets' size. A fine ball (a
    // 20480-triangle icosphere: 0.04) is a smooth surface seen through facets; a coarse one
    // (1280: 0.15) or a polyhedron's corner is its facets, whatever the depth (a coarse ball
    // sunk deep spans many facets).
    double facet_angle = 0.0;
    if (mo.area > 0.0 && facet_scale > 0.0) {
      const double turn_a = 1.0 - (mo.area_normal_a / mo.area).squaredNorm();
      const double turn_b = 1.0 - (mo.area_normal / mo.area).squaredNorm();
      const double spread_body = std::sqrt(std::max(0.0, std::max(turn_a, turn_b)));
      const double radius = std::sqrt(mo.area / M_PI);
      const double h = std::sqrt(4.0 * facet_scale / std::sqrt(3.0));
      facet_angle = std::sqrt(2.0) * spread_body * h / radius;
    }
    const double fine =
        1.0 - smoothstep((facet_angle - kCurvedFineAngle) / kCurvedFineAngle);
    curved = curved_peak(mo.area, mo.m1, mo.m2, mo.m3);
    other_weights =
        curved_base * (1.0 - smoothstep(outside / kCurvedOutsideShare)) * curved.validity * fine;
    w = other_weights * smoothstep(facets_u);
    if (w > 0.0) {
      curved_area_centre = s.point + mo.area1 / mo.area;
      curved_pressure_centre = s.point + mo.first1 / mo.m1;
      curved_second_centre = s.point + mo.second1 / mo.m2;
      // The direction of the peak's gradient under translation (OverlapMoments).
      const Vector3d n = curved.a_area * mo.area_normal / mo.area +
                         curved.a_pressure * mo.m1_normal / mo.m1 +
                         curved.a_second * mo.m2_normal / mo.m2;
      const double len = n.norm();
      curved_normal = std::isfinite(len) && len > 0.5 ? Vector3d(n / len) : deepest_normal;
    }
  }
  if ((beta > 0.0 || w > 0.0) && plain_share < 1.0) {
    // Energy 1/2 kn Omega, Omega = (1 - beta) X + beta Q, X = (1 - w) D^2 + w Phi^2, Q = mean
    // square overlap, Phi the curved peak: its gradient acts along the normal at the deepest
    // point, the area centre, the centre of pressure and the centroid of o^2 with the weights
    // below (header, steps 5b and 5c).
    const double b = beta * (1.0 - plain_share);
    const double slope = flat_blend_slope(r) * (1.0 - plain_share);
    const double phi = curved.peak;
    const double x_law = (1.0 - w) * D * D + w * phi * phi;
    const double q_minus = mean_square - x_law;
    // d w = other_weights smoothstep'(u) du, u affine in n = M1 / (D f) (f held fixed).
    double blend_area = 0.0, blend_deep = 0.0;
    if (w > 0.0 && facets_u < 1.0) {
      const double dw_dn = other_weights * 6.0 * facets_u * (1.0 - facets_u) /
                           (kCurvedFacetsFull - kCurvedFacetsFrom);
      const double jump = (1.0 - b) * (phi * phi - D * D) * dw_dn;
      blend_area = jump * area / (D * facet_scale);
      blend_deep = -jump * weight / (D * D * facet_scale);
    }
    const double a_deep = 2.0 * (1.0 - b) * (1.0 - w) * D +
                          q_minus * slope * (uneven_share - kFlatPatchBand * r) /
                              (kFlatPatchBand * D) +
                          blend_deep;
    const double curved_scale = 2.0 * (1.0 - b) * w * phi;
    const double a_area = -q_minus * slope * uneven_share / (kFlatPatchBand * D) + blend_area;
    const double a_pressure = 2.0 * b * mean;
    const Vector3d area_centre = s.point + area1 / area;
    const Vector3d pressure_centre =
        weight > 0.0 ? Vector3d(s.point + pressure1 / weight) : area_centre;
    Vector3d moment = a_deep * deepest + a_area * area_centre + a_pressure * pressure_centre;
    double sum = a_deep + a_area + a_pressure;
    if (w > 0.0) {
      moment += curved_scale * (curved.a_area * curved_area_centre +
                                curved.a_pressure * curved_pressure_centre +
                                curved.a_second * curved_second_centre);
      sum += curved_scale * (curved.a_area + curved.a_pressure + curved.a_second);
    }
    if (sum > 0.0) {
      p.point = moment / sum;
      // The slant's share of r changes with the faces' relative tilt, not with the overlap at
      // any point: its part of Omega's gradient is a couple about n x g (g the mean overlap
      // slope; a turn d(theta) of a against b changes |g| by -d(theta) . (m x g^)), carried by
      // moving the force's point along g by (dOmega/d|g|) / sum (energy kn Omega / 2, force
      // kn sum / 2).
      const double slope_norm = (gradient1 / area).norm();
      if (slant > 0.0 && slope_norm > 0.0) {
        const double d_omega_d_slope =
            q_minus * slope * (slant / uneven_total) / (kFlatPatchBand * D) * 0.5 * layer;
        p.point += d_omega_d_slope / sum * (gradient1 / area) / slope_norm;
      }
      p.overlap = 0.5 * sum;
      p.energy_overlap = std::sqrt(std::max(0.0, (1.0 - b) * x_law + b * mean_square));
      const Vector3d point_normal =
          w > 0.0 ? Vector3d((1.0 - w) * deepest_normal + w * curved_normal) : deepest_normal;
      const Vector3d blended = (1.0 - b) * point_normal + b * poly_normal;
      p.normal = blended.normalized();
    }
  }
  p.face_weight = face_weight_of(spread, mean_gradient.norm()) * (1.0 - plain_share);
  // Step 6: the patch's extent about the point. Parallel-axis theorem from s.point to p.point
  // (q = p.point - s.point), then onto the contact plane.
  const Vector3d q = p.point - s.point;
  const Eigen::Matrix3d about_point =
      area2 - area1 * q.transpose() - q * area1.transpose() + area * q * q.transpose();
  const Eigen::Matrix3d plane = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
  const Eigen::Matrix3d j = plane * about_point * plane;
  p.patch_second_moment = 0.5 * (j + j.transpose());
  p.patch_area = area;
  p.damping_point = s.point + area1 / area;
  // The mean distance of the patch from the point, over the same polygons, projected onto the
  // contact plane (numerator and denominator alike). Only a face-like contact twists against
  // its patch (contact_force.h), so a point-like one skips the integral (its asinh per edge).
  DistanceIntegral dist;
  for (std::size_t k = 0; p.face_weight > 0.0 && k < num_polygons; ++k) {
    const ContactPolygon &poly = polygons[k];
    const DistanceIntegral one =
        polygon_distance_integral(poly.vertices, poly.num_vertices, p.point, p.normal);
    dist.area += one.area;
    dist.distance += one.distance;
  }
  p.patch_mean_radius = dist.area > 0.0 ? dist.distance / dist.area : 0.0;
  return p;
}

void reduce_clusters(std::vector<Raw> &raw, double layer, const ReductionParams &params,
                     const Vector3d &ref, const Faces &faces, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out) {
  const int n = static_cast<int>(raw.size());
  // Members of each component, components in the order of their deepest member.
  std::vector<int> &label = work.label;
  label.resize(n);
  // Points whose bounding box has a diagonal within the link length are all linked (every
  // pair's distance is at most the diagonal, and rounding keeps that order: a contact at one
  // place, most of them): one component, labels 0, as link_points would find.
  Vector3d lo = raw[0].point, hi = raw[0].point;
  for (int i = 1; i < n; ++i) {
    lo = lo.cwiseMin(raw[i].point);
    hi = hi.cwiseMax(raw[i].point);
  }
  bool one_component = (hi - lo).squaredNorm() <= params.link_length * params.link_length;
  if (one_component) {
    std::fill(label.begin(), label.end(), 0);
  } else {
    work.points.resize(n);
    for (int i = 0; i < n; ++i)
      work.points[i] = raw[i].point;
    link_points(work.points, params.link_length, work.parent, work.links);
    for (int i = 0; i < n; ++i)
      label[i] = link_root(work.parent, i);
    one_component = true;
    for (int i = 0; i < n; ++i)
      one_component = one_component && label[i] == 0;
  }
  // All indices grouped by component, in index order within each (the order of a stable sort
  // by label): one component (most pairs) as they are, else a counting sort (labels are
  // indices).
  std::vector<int> &members = work.order;
  members.resize(n);
  if (one_component) {
    std::iota(members.begin(), members.end(), 0);
  } else {
    std::vector<int> &tally = work.tally;
    tally.assign(n + 1, 0);
    for (int i = 0; i < n; ++i)
      ++tally[label[i] + 1];
    for (int i = 0; i < n; ++i)
      tally[i + 1] += tally[i];
    for (int i = 0; i < n; ++i)
      members[tally[label[i]]++] = i;
  }

  if (!(params.split_angle == work.split_angle)) { // the same angle pair after pair
    work.split_angle = params.split_angle;
    work.cos_split = std::cos(params.split_angle);
  }
  const double cos_split = work.cos_split;
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
    // Deepest first again after the flips (ties keep the sorted order: indices). Without a
    // flip the group, in index order, is in that order already (raw is sorted deepest first).
    if (flip_sunk_members(raw, group, layer, ref))
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
      if (alive[c]) {
        const ContactPoint p = make_point(raw, group, cls, absorbed, c, seeds[c], layer, ref,
                                          faces, params.distance_tolerance, work);
        // Facets within reach of the lifts whose smooth surfaces do not overlap yet.
        if (params.surface_lift > 0.0 && !(p.overlap > 0.0))
          continue;
        out.push_back(p);
        if (params.classify)
          out.back().kind = class_kind(p, raw, group, cls, absorbed, c, layer);
      }
    begin = end;
  }
  // Deepest first; ties keep component/class order (deterministic). (One point, mostly: no
  // sort, whose buffer would be allocated.)
  if (out.size() > 1)
    std::stable_sort(out.begin(), out.end(), [](const ContactPoint &a, const ContactPoint &b) {
      return a.overlap > b.overlap;
    });
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

} // namespace

double recommended_link_length(double longest_edge_a, double longest_edge_b, double eps_a,
                               double eps_b) {
  const double edge = std::min(longest_edge_a, longest_edge_b);
  return (2.0 * edge + eps_a + eps_b) * (1.0 + 1e-9);
}

namespace {

// A pair's few contacts (a dozen) sorted deepest first by rank: each key's place is the number
// of keys before it, counted without branches. An insertion sort's comparisons, random in
// outcome, mispredicted about every second branch (2 % of a formed hopper's step). The order
// is the comparator's below, a strict total order: the same permutation. Keys tied in overlap
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
    pair[i] = static_cast<std::int64_t>(static_cast<std::uint64_t>(
                  static_cast<std::uint32_t>(keys[i].tri_a)) << 32 |
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

template <class Source>
void reduce(const Source &contacts, int n, const Faces &faces, double eps_a, double eps_b,
            const ReductionParams &params, ReductionWorkspace &work,
            std::vector<ContactPoint> &out) {
  out.clear();
  const int na = faces.a->num_triangles(), nb = faces.b->num_triangles();
  const double layer = eps_a + eps_b;
  const Vector3d ref = safe_reference(params.reference_direction);
  // The contacts that count, deepest first (`deeper`), sorted as keys, which move cheaper than
  // raw contacts; then the raw contacts in that order.
  std::vector<ReductionWorkspace::Key> &keys = work.keys;
  keys.clear();
  for (int k = 0; k < n; ++k) {
    if (!contacts.counts(k))
      continue;
    const auto &c = contacts.at(k);
    const int ta = tri_a_of(c), tb = tri_b_of(c);
    if (ta < 0 || ta >= na || tb < 0 || tb >= nb)
      throw std::out_of_range("reduce_contacts: contact " + std::to_string(k) +
                              " names triangles " + std::to_string(ta) + ", " +
                              std::to_string(tb) + " of meshes with " + std::to_string(na) +
                              ", " + std::to_string(nb));
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
  std::vector<Raw> &raw = work.raw;
  if (keys.empty()) {
    raw.clear();
    return;
  }
  sort_keys(keys, contacts, work.sorted_keys);
  raw.resize(keys.size()); // every field written below (only the growth is zeroed)
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
