// Steps 4 to 6 of the reduction (README.md): one contact point per class. make_point gathers
// the class's members (step 4) and takes step 5 (no contact polygons: point_without_polygons,
// with reduction_smooth_deepest.cpp) or step 5b (deepest_blend, flat_measure, energy_point),
// with step 5c (curved_patch) and step 6 (patch_extent).
//
// Steps 5b, 5c and 6 share this translation unit on purpose: the compiler fuses a product into
// a sum (floating-point contraction, the default for C++ with FMA) depending on what it
// inlines, and these steps' results are bitwise those of the same functions compiled here;
// moved to another file, step 5c's normal changed in its last bits.
#include "contact/reduction_steps.h"
#include "contact/smooth_peak.h"
#include "distance/triangle_distance.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace tri::reduction {
namespace {

// The member's contact polygon (step 5b) if its triangles are nearly parallel and their
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

// Step 5b, smooth surfaces: what smooth_surface_peak found.
struct SmoothFound {
  bool found = false;
  double overlap = 0.0;
  Vector3d point = Vector3d::Zero(), normal = Vector3d::UnitZ();
};

// Step 5b, smooth surfaces: the deepest point of the smooth surfaces that the two bodies' facets
// sample (smooth_surface.h), over the class's nearly parallel members: each member's polygon,
// clipped where the lifts may still reach (the layer widened by the lift), with the lifts of
// its two facets (smooth_peak.h).
SmoothFound smooth_surface_peak(const ContactClass &cc, const Faces &faces) {
  SmoothFound best;
  ContactPolygon poly;
  const TriangleSoA &ta = *faces.a, &tb = *faces.b;
  for (int i : cc.members) {
    if (!cc.places(i))
      continue;
    const Raw &r = cc.raw[i];
    if (!r.maybe_parallel)
      continue;
    const Vector3d a[3] = {ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2)};
    const Vector3d b[3] = {tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2)};
    if (!contact_polygon(a[0], a[1], a[2], b[0], b[1], b[2], r.normal, cc.layer + faces.lift,
                         poly) ||
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

// The kernel's deepest point and normal (steps 4 and 5) over the class's members (plain_only:
// those not deeper than D, the members without a polygon): the members within the taper of D,
// weighted by their height in it, and the overlap-weighted normal of those tied with D.
// `placing` (if given) is extended by the points of the members that place the point.
void kernel_deepest(const ContactClass &cc, double D, bool plain_only, double taper,
                    const Vector3d &ref, Vector3d &point, Vector3d &normal,
                    Eigen::AlignedBox3d *placing = nullptr) {
  const std::vector<Raw> &raw = cc.raw;
  const Raw &s = raw[cc.seed];
  Vector3d sum_n = Vector3d::Zero(), sum_p = Vector3d::Zero();
  double sum_wn = 0.0, sum_wp = 0.0;
  for (int i : cc.members) {
    if (cc.cls[i] != cc.id || cc.absorbed[i])
      continue;
    const Raw &r = raw[i];
    if (plain_only && r.overlap > D)
      continue; // a polygon member (deeper ones are polygon members by construction)
    const double tied = 1.0 - (D - r.overlap) / taper;
    if (tied > 0.0) {
      sum_p += tied * r.point;
      sum_wp += tied;
      if (placing)
        placing->extend(r.point);
    }
    if (r.overlap >= D - kNormalDepthBand * cc.layer) {
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
}

// Step 5: a class without polygons. Its point, normal and force from the smooth maximum of its
// members' overlaps; where the smooth surfaces reach past the facets, theirs.
void point_without_polygons(const ContactClass &cc, const SmoothFound &smooth,
                            const Vector3d &fallback_normal, double taper, ReductionWorkspace &work,
                            ContactPoint &p) {
  const std::vector<Raw> &raw = cc.raw;
  const std::vector<int> &plain = work.plain;
  const double layer = cc.layer;
  const Raw &s = raw[cc.seed];
  const SmoothDeepest sd =
      smooth_deepest(raw, plain, {taper, kNormalDepthBand * layer, kSameFeatureDistance * layer},
                     s.point, fallback_normal, work.smooth_scratch, work.smooth_share);
  p.point = sd.point;
  p.normal = sd.normal;
  p.overlap = sd.overlap * sd.normal_scale;
  p.energy_overlap = sd.overlap;
  Eigen::AlignedBox3d placing = sd.placing;
  if (smooth.found && smooth.overlap > sd.overlap) {
    // No facet overlaps yet (or only at a clear angle): the smooth surfaces decide where they
    // reach past the facets, fully from a taper on.
    const double gain = smooth.overlap - sd.overlap;
    const double t = smoothstep(gain / taper);
    if (t >= 1.0)
      placing.setEmpty();
    if (t > 0.0)
      placing.extend(smooth.point);
    p.point += t * (smooth.point - p.point);
    p.normal = (p.normal + t * (smooth.normal - p.normal)).normalized();
    p.energy_overlap = smooth.overlap;
    p.overlap = smooth.overlap * ((1.0 - t) * sd.normal_scale + t);
  }
  p.point_is_material = point_is_material(true, placing, p.point, layer);
}

// Step 5b: the polygons' sums, relative to the seed's midpoint (near the patch: no digits
// lost far from the world origin): their deepest region above `level`, and their integrals
// (area m^2, weight = integral of o m^3, weight2 = integral of o^2 m^4).
struct PolygonSums {
  double excess = 0.0;
  Vector3d excess1 = Vector3d::Zero(), excess_normal = Vector3d::Zero();
  Eigen::AlignedBox3d excess_placing; // the corners above the level (they place p_D)
  double area = 0.0, weight = 0.0, weight2 = 0.0, facet_area = 0.0;
  Vector3d area1 = Vector3d::Zero(), pressure1 = Vector3d::Zero(), area_normal = Vector3d::Zero();
  Eigen::Matrix3d area2 = Eigen::Matrix3d::Zero();
  Vector3d gradient1 = Vector3d::Zero();
  double gradient2 = 0.0;
};

PolygonSums sum_polygons(const std::vector<ContactPolygon> &polygons, std::size_t num_polygons,
                         const std::vector<double> &polygon_exact, double level,
                         const Vector3d &origin) {
  PolygonSums t;
  for (std::size_t k = 0; k < num_polygons; ++k) {
    const ContactPolygon &poly = polygons[k];
    // Each polygon's deepest region, tapered (continuous in the geometry): its weight is the
    // excess of o over the level integrated over the polygon (mesh-independent), its point the
    // polygon's corners above the level weighted by their excess -- the deepest corner itself
    // when it alone is deepest (a vertex of a tilted face: exactly the point of the gradient of
    // D), the middle of a tied edge when an edge lies flat (step 5b).
    const ExcessIntegral e = excess_over(poly, level, origin);
    if (e.weight > 0.0) {
      Vector3d corner_sum = Vector3d::Zero();
      double corner_weight = 0.0;
      for (int i = 0; i < poly.num_vertices; ++i) {
        const double w = corner_overlap(poly, polygon_exact[k], i) - level;
        if (w > 0.0) {
          corner_sum += w * (poly.corner_points[i] - origin);
          corner_weight += w;
          t.excess_placing.extend(poly.corner_points[i]);
        }
      }
      if (corner_weight > 0.0) {
        t.excess += e.weight;
        t.excess1 += e.weight * (corner_sum / corner_weight);
      }
    }
    t.excess_normal += e.weight * poly.direction;
    const Vector3d d = poly.area_centroid - origin;
    t.area += poly.area;
    t.facet_area += poly.weight * poly.min_triangle_area;
    t.weight += poly.weight;
    t.weight2 += poly.weight2;
    t.area1 += poly.area * d;
    t.pressure1 += poly.weight * (poly.centroid - origin);
    t.area2 += poly.second_moment + poly.area * d * d.transpose();
    t.area_normal += poly.area * poly.direction;
    t.gradient1 += poly.area * poly.overlap_gradient;
    t.gradient2 += poly.area * poly.overlap_gradient.squaredNorm();
  }
  return t;
}

// Step 5b: how uneven a patch is (the flat-patch measure r and its blend beta), from its
// polygons' sums and deepest overlap D_poly, and its mean and mean square overlap.
struct FlatMeasure {
  double mean, mean_square; // m, m^2
  double slant;             // m, the mean overlap slope across half a layer
  double uneven_total;      // m, hypot(D_poly - mean, slant)
  double r, uneven_share, beta;
};

FlatMeasure flat_measure(const PolygonSums &t, double D_poly, double layer) {
  FlatMeasure f;
  f.mean = t.weight / t.area;
  f.mean_square = t.weight2 / t.area;
  // How uneven, over the patch or over a layer's width, whichever is wider: a polygon that
  // shrinks to a sliver at a corner is uniform by its size alone, however steep its faces, and
  // judged flat its energy (a mean over a region whose edges move) would lose the work of those
  // edges: a tilted face's unevenness across a layer, slope x layer / 2, keeps it the deepest
  // pair's. Wide patches are uneven over their own width first, so it changes nothing there.
  const double unevenness = std::max(0.0, D_poly - f.mean);
  f.slant = 0.5 * layer * (t.gradient1 / t.area).norm();
  f.uneven_total = std::hypot(unevenness, f.slant);
  f.r = f.uneven_total / (kFlatPatchBand * D_poly);
  // dr/d(D - mean): the share of the unevenness that the patch's own overlaps carry.
  f.uneven_share = f.uneven_total > 0.0 ? unevenness / f.uneven_total : 1.0;
  f.beta = flat_blend(f.r);
  return f;
}

// Step 5c: the members without a polygon whose triangles are within kCurvedFacetAngle: their
// polygons' moments into `mo` (a ball's cap reaches facets tilted past step 5b's 10 degrees);
// their overlaps come off `plain_overlap`. (A member within that angle whose polygon is empty --
// a facet over one wall triangle seen through the next one's edge -- is no part of the field.)
void add_wide_polygons(const ContactClass &cc, const Faces &faces, const Vector3d &normal,
                       const std::vector<int> &plain, OverlapMoments &mo, double &plain_overlap) {
  const double layer = cc.layer;
  const Vector3d &origin = cc.raw[cc.seed].point;
  ContactPolygon wide;
  for (int i : plain) {
    const Raw &r = cc.raw[i];
    const TriangleSoA &ta = *faces.a, &tb = *faces.b;
    if (!contact_polygon(ta.vertex(r.tri_a, 0), ta.vertex(r.tri_a, 1), ta.vertex(r.tri_a, 2),
                         tb.vertex(r.tri_b, 0), tb.vertex(r.tri_b, 1), tb.vertex(r.tri_b, 2),
                         r.normal, layer, wide, kCurvedFacetAngle))
      continue;
    plain_overlap -= r.overlap;
    if (wide.weight > 0.0 && wide.area > kPatchAreaRounding * wide.min_triangle_area)
      add_overlap_moments(wide, layer, normal, origin, mo);
  }
}

// Step 5c: the angle between neighbouring facets, phi = h / R: a body's curvature 1 / R from
// how its normal turns over the patch's radius a (a sphere's cap: RMS deviation
// a / (sqrt(2) R)), the more curved of the two bodies, h the facets' size (facet_scale: their
// area). A fine ball (a 20480-triangle icosphere: 0.04) is a smooth surface seen through
// facets; a coarse one (1280: 0.15) or a polyhedron's corner is its facets, whatever the depth.
double facet_angle_of(const OverlapMoments &mo, double facet_scale) {
  double facet_angle = 0.0;
  if (mo.area > 0.0 && facet_scale > 0.0) {
    const double turn_a = 1.0 - (mo.area_normal_a / mo.area).squaredNorm();
    const double turn_b = 1.0 - (mo.area_normal / mo.area).squaredNorm();
    const double spread_body = std::sqrt(std::max(0.0, std::max(turn_a, turn_b)));
    const double radius = std::sqrt(mo.area / M_PI);
    const double h = std::sqrt(4.0 * facet_scale / std::sqrt(3.0));
    facet_angle = std::sqrt(2.0) * spread_body * h / radius;
  }
  return facet_angle;
}

// Step 5b's deepest overlap, point and normal, with the share of the members without a polygon.
struct DeepestTerms {
  double D;
  const Vector3d &point, &normal, &poly_normal;
  double plain_share;
};
// Step 5c's curved peak, its weight w and where its gradient acts.
struct CurvedTerms {
  double w, other_weights, facets_u, facet_scale;
  const CurvedPeak &curved;
  const Vector3d &area_centre, &pressure_centre, &second_centre, &normal;
};

// Energy 1/2 kn Omega, Omega = (1 - beta) X + beta Q, X = (1 - w) D^2 + w Phi^2, Q = mean
// square overlap, Phi the curved peak: its gradient acts along the normal at the deepest point,
// the area centre, the centre of pressure and the centroid of o^2 with the weights below (steps
// 5b and 5c): p's point, overlap, energy_overlap and normal.
void energy_point(const ContactClass &cc, const PolygonSums &sums, const FlatMeasure &flat,
                  const DeepestTerms &dt, const CurvedTerms &ct, ContactPoint &p) {
  const double layer = cc.layer;
  const Raw &s = cc.raw[cc.seed];
  const double area = sums.area, weight = sums.weight;
  const Vector3d &area1 = sums.area1, &pressure1 = sums.pressure1, &gradient1 = sums.gradient1;
  const double mean = flat.mean, mean_square = flat.mean_square, slant = flat.slant,
               uneven_total = flat.uneven_total, r = flat.r, uneven_share = flat.uneven_share,
               beta = flat.beta;
  const double D = dt.D, plain_share = dt.plain_share;
  const Vector3d &deepest = dt.point, &deepest_normal = dt.normal, &poly_normal = dt.poly_normal;
  const double w = ct.w, other_weights = ct.other_weights, facets_u = ct.facets_u,
               facet_scale = ct.facet_scale;
  const CurvedPeak &curved = ct.curved;
  const Vector3d &curved_area_centre = ct.area_centre, &curved_pressure_centre = ct.pressure_centre,
                 &curved_second_centre = ct.second_centre, &curved_normal = ct.normal;
  // Energy 1/2 kn Omega, Omega = (1 - beta) X + beta Q, X = (1 - w) D^2 + w Phi^2, Q = mean
  // square overlap, Phi the curved peak: its gradient acts along the normal at the deepest
  // point, the area centre, the centre of pressure and the centroid of o^2 with the weights
  // below (steps 5b and 5c).
  const double b = beta * (1.0 - plain_share);
  const double slope = flat_blend_slope(r) * (1.0 - plain_share);
  const double phi = curved.peak;
  const double x_law = (1.0 - w) * D * D + w * phi * phi;
  const double q_minus = mean_square - x_law;
  // d w = other_weights smoothstep'(u) du, u affine in n = M1 / (D f) (f held fixed).
  double blend_area = 0.0, blend_deep = 0.0;
  if (w > 0.0 && facets_u < 1.0) {
    const double dw_dn =
        other_weights * 6.0 * facets_u * (1.0 - facets_u) / (kCurvedFacetsFull - kCurvedFacetsFrom);
    const double jump = (1.0 - b) * (phi * phi - D * D) * dw_dn;
    blend_area = jump * area / (D * facet_scale);
    blend_deep = -jump * weight / (D * D * facet_scale);
  }
  const double a_deep =
      2.0 * (1.0 - b) * (1.0 - w) * D +
      q_minus * slope * (uneven_share - kFlatPatchBand * r) / (kFlatPatchBand * D) + blend_deep;
  const double curved_scale = 2.0 * (1.0 - b) * w * phi;
  const double a_area = -q_minus * slope * uneven_share / (kFlatPatchBand * D) + blend_area;
  const double a_pressure = 2.0 * b * mean;
  const Vector3d area_centre = s.point + area1 / area;
  const Vector3d pressure_centre =
      weight > 0.0 ? Vector3d(s.point + pressure1 / weight) : area_centre;
  Vector3d moment = a_deep * deepest + a_area * area_centre + a_pressure * pressure_centre;
  double sum = a_deep + a_area + a_pressure;
  if (w > 0.0) {
    moment += curved_scale *
              (curved.a_area * curved_area_centre + curved.a_pressure * curved_pressure_centre +
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

// Step 6: the patch's extent about p.point, in the plane normal to p.normal (p.face_weight
// set), from the polygons' sums about `origin` (the seed's midpoint).
void patch_extent(const Vector3d &origin, const PolygonSums &sums,
                  const std::vector<ContactPolygon> &polygons, std::size_t num_polygons,
                  ContactPoint &p) {
  const double area = sums.area;
  const Vector3d &area1 = sums.area1;
  const Eigen::Matrix3d &area2 = sums.area2;
  // Step 6: the patch's extent about the point. Parallel-axis theorem from the origin to p.point
  // (q = p.point - origin), then onto the contact plane.
  const Vector3d q = p.point - origin;
  const Eigen::Matrix3d about_point =
      area2 - area1 * q.transpose() - q * area1.transpose() + area * q * q.transpose();
  const Eigen::Matrix3d plane = Eigen::Matrix3d::Identity() - p.normal * p.normal.transpose();
  const Eigen::Matrix3d j = plane * about_point * plane;
  p.patch_second_moment = 0.5 * (j + j.transpose());
  p.patch_area = area;
  p.damping_point = origin + area1 / area;
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
}

// Step 5c: what a curved patch contributes -- the peak of its overlap moments, the centres
// where that peak's gradient acts and its direction -- and w, how much it counts (0: the
// deepest corner alone). facet_scale: the polygons' overlap-weighted smaller triangle area;
// facets_u: how many facets the patch spans, 0 at kCurvedFacetsFrom, 1 at kCurvedFacetsFull.
struct CurvedPatch {
  double facet_scale, facets_u;
  double w, other_weights; // w = other_weights smoothstep(facets_u)
  CurvedPeak curved;
  Vector3d area_centre, pressure_centre, second_centre, normal;
};

CurvedPatch curved_patch(const ContactClass &cc, double weight, double facet_area, double D,
                         double curved_base, const Vector3d &deepest_normal,
                         std::size_t num_polygons, double plain_overlap, double member_overlap,
                         const Faces &faces, const ReductionWorkspace &work) {
  const std::vector<Raw> &raw = cc.raw;
  const std::vector<ContactPolygon> &polygons = work.polygons;
  const std::vector<int> &plain = work.plain;
  const double layer = cc.layer;
  const Raw &s = raw[cc.seed];
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
    add_wide_polygons(cc, faces, deepest_normal, plain, mo, plain_overlap);
    const double outside =
        member_overlap > 0.0 ? std::max(0.0, plain_overlap) / member_overlap : 0.0;
    const double facet_angle = facet_angle_of(mo, facet_scale);
    const double fine = 1.0 - smoothstep((facet_angle - kCurvedFineAngle) / kCurvedFineAngle);
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
  return {facet_scale,
          facets_u,
          w,
          other_weights,
          curved,
          curved_area_centre,
          curved_pressure_centre,
          curved_second_centre,
          curved_normal};
}

// Step 5b's deepest overlap D, its point and normal: the polygons' (oriented near flat by the
// polygons, from the band's end on by the kernel's closest points), moved to the smooth
// surfaces' and to the members without a polygon's where those reach deeper, with those
// shares.
struct DeepestBlend {
  double D;
  Vector3d point, normal;
  double smooth_blend, plain_share;
  Eigen::AlignedBox3d placing; // the points that place `point`
};

DeepestBlend deepest_blend(const ContactClass &cc, double D_poly, double deepest_plain,
                           const SmoothFound &smooth, const Vector3d &poly_deepest,
                           const Eigen::AlignedBox3d &poly_placing,
                           const Vector3d &poly_deepest_normal, double beta, const Vector3d &ref) {
  const Raw &s = cc.raw[cc.seed];
  const double taper = kDeepestTaper * cc.layer;
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
  Eigen::AlignedBox3d placing;
  if (plain_share < 1.0 && smooth_blend < 1.0)
    placing = poly_placing.isEmpty() ? Eigen::AlignedBox3d(poly_deepest, poly_deepest)
                                     : poly_placing;
  if (plain_share < 1.0 && smooth_blend > 0.0)
    placing.extend(smooth_point);
  {
    Vector3d kernel_point, kernel_normal;
    kernel_deepest(cc, s.overlap, false, taper, ref, kernel_point, kernel_normal);
    // Near flat the polygons orient the deepest point; from the band's end on, the kernel's
    // closest points (the direction of the gradient of a tilted face's overlap).
    deepest_normal = beta * poly_deepest_normal + (1.0 - beta) * kernel_normal;
    if (smooth_blend > 0.0)
      deepest_normal += smooth_blend * (smooth_normal - deepest_normal);
    if (plain_share > 0.0) {
      Vector3d plain_point, plain_normal;
      kernel_deepest(cc, deepest_plain, true, taper, ref, plain_point, plain_normal, &placing);
      D += plain_share * (deepest_plain - D_surface);
      deepest += plain_share * (plain_point - deepest);
      deepest_normal += plain_share * (plain_normal - deepest_normal);
    }
    deepest_normal.normalize();
  }
  return {D, deepest, deepest_normal, smooth_blend, plain_share, placing};
}

// What a class's members give before a point is chosen: their contact polygons are
// work.polygons[0, num_polygons), each with its layer in work.polygon_layers (-1: intersecting
// or sunk); the members without one are work.plain.
struct ClassMembers {
  std::size_t num_polygons = 0;
  double deepest_polygon = 0.0; // m, the polygon members' deepest overlap, exact (step 5b)
  double deepest_plain = -std::numeric_limits<double>::infinity(); // m, the others' deepest
  double plain_overlap = 0.0;  // m, the summed overlap of the members without a polygon,
  double member_overlap = 0.0; // and of all (step 5c: how much lies outside the polygons)
};

// Walks the class's members: min_distance, intersecting and num_merged into `p`; their
// polygons and the members without one into `work`.
ClassMembers gather_members(const ContactClass &cc, const Faces &faces, double tolerance,
                            ReductionWorkspace &work, ContactPoint &p) {
  const std::vector<Raw> &raw = cc.raw;
  const double layer = cc.layer;
  std::vector<ContactPolygon> &polygons = work.polygons;
  // `polygons` only grows: entries [0, num_polygons) are this class's. Reusing the slots keeps
  // emplace_back from zeroing a 3 KB ContactPolygon per member (value-initialisation).
  ClassMembers m;
  work.polygon_layers.clear();
  work.plain.clear();
  // A member's exact overlap lies at most `tolerance` above its kernel overlap (and never below
  // it beyond rounding), so one that stays below the deepest exact one found so far by more
  // than that cannot be the deepest: its triangle distance is not recomputed. The members come
  // deepest first, so mostly only the first is.
  const double exact_slack =
      tolerance + 1e-9 * layer + 1e-13 * raw[cc.seed].point.cwiseAbs().maxCoeff();
  p.min_distance = std::numeric_limits<double>::infinity();
  for (int i : cc.members) {
    if (cc.cls[i] != cc.id)
      continue;
    const Raw &r = raw[i];
    p.min_distance = std::min(p.min_distance, r.distance);
    p.intersecting = p.intersecting || r.intersecting;
    ++p.num_merged;
    if (cc.absorbed[i])
      continue; // rim contacts count, but neither place nor orient the contact
    if (m.num_polygons == polygons.size())
      polygons.emplace_back();
    if (member_polygon(r, faces, layer, polygons[m.num_polygons])) { // filled in place
      ++m.num_polygons;
      work.polygon_layers.push_back(!(r.intersecting || r.overlap > layer) ? layer : -1.0);
      if (!(r.overlap + exact_slack < m.deepest_polygon))
        m.deepest_polygon = std::max(m.deepest_polygon, exact_overlap(r, faces, layer));
    } else {
      m.deepest_plain = std::max(m.deepest_plain, r.overlap);
      m.plain_overlap += std::max(0.0, r.overlap); // (< 0: facets only within the lifts' reach)
      work.plain.push_back(i);
    }
    m.member_overlap += std::max(0.0, r.overlap);
  }
  return m;
}

} // namespace

ContactPoint make_point(const ContactClass &cc, const Vector3d &ref, const Faces &faces,
                        double tolerance, ReductionWorkspace &work) {
  const std::vector<Raw> &raw = cc.raw;
  const int seed = cc.seed;
  const double layer = cc.layer;
  ContactPoint p;
  std::vector<ContactPolygon> &polygons = work.polygons;
  std::vector<double> &polygon_exact = work.polygon_layers;
  const Raw &s = raw[seed];
  const double taper = kDeepestTaper * layer;
  const ClassMembers cm = gather_members(cc, faces, tolerance, work, p);
  const std::size_t num_polygons = cm.num_polygons;
  const double deepest_plain = cm.deepest_plain, D_poly = cm.deepest_polygon;
  const double plain_overlap = cm.plain_overlap, member_overlap = cm.member_overlap;
  p.tri_a = s.tri_a;
  p.tri_b = s.tri_b;

  // The deepest point of the smooth surfaces (smooth_surface.h): over every nearly parallel
  // member, its polygon clipped where the lifts may still reach (o >= -lift).
  SmoothFound smooth;
  if (faces.bulge_a || faces.bulge_b)
    smooth = smooth_surface_peak(cc, faces);
  const Vector3d fallback_normal = finite(s.normal) ? s.normal : ref;
  if (num_polygons == 0) {
    point_without_polygons(cc, smooth, fallback_normal, taper, work, p);
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
  const PolygonSums sums = sum_polygons(polygons, num_polygons, polygon_exact, level, s.point);
  const double excess = sums.excess;
  const Vector3d &excess1 = sums.excess1, &excess_normal = sums.excess_normal;
  const double area = sums.area, weight = sums.weight, facet_area = sums.facet_area;
  const Vector3d &area_normal = sums.area_normal;
  const Vector3d &gradient1 = sums.gradient1;
  const double gradient2 = sums.gradient2;
  // excess > 0: the deepest corner exceeds the level (its polygon has a region above it).
  const Vector3d poly_deepest = excess > 0.0 ? Vector3d(s.point + excess1 / excess) : s.point;
  const Vector3d poly_normal = area_normal.normalized(); // area > 0: never zero
  const double excess_len = excess_normal.norm();
  const Vector3d poly_deepest_normal =
      excess_len > 0.0 ? Vector3d(excess_normal / excess_len) : poly_normal;
  const FlatMeasure flat = flat_measure(sums, D_poly, layer);
  const double beta = flat.beta;

  const DeepestBlend blend = deepest_blend(cc, D_poly, deepest_plain, smooth, poly_deepest,
                                           sums.excess_placing, poly_deepest_normal, beta, ref);
  const double smooth_blend = blend.smooth_blend, plain_share = blend.plain_share, D = blend.D;
  const Vector3d &deepest = blend.point, &deepest_normal = blend.normal;
  p.point = deepest;
  p.overlap = p.energy_overlap = D;
  p.normal = deepest_normal;
  const Vector3d mean_gradient = gradient1 / area;
  const double spread = std::sqrt(std::max(0.0, gradient2 / area - mean_gradient.squaredNorm()));
  // Step 5c: a curved patch (its overlap gradient turns over it) takes the peak of its moments
  // instead of its deepest corner; w is how curved, times the estimate's validity.
  const double curved_base = curved_weight(spread) * (1.0 - plain_share) * (1.0 - smooth_blend);
  // Only a patch that spans many facets is a smooth surface seen through its facets: one or
  // two facets (a vertex, an edge, a rock's corner) are the surface itself, and their deepest
  // corner is its peak. Facets spanned by the polygons of step 5b: n = M1 / (D f), f their
  // overlap-weighted smaller triangle area (continuous as polygons enter at o = 0; a
  // paraboloid's n is half the facets under its area). n has a known gradient (dM1 =
  // A do(c_A), dD = do(p_D), exact while the patch lies within the polygons' 10 degrees, as it
  // does while n is small), so the blend's own gradient enters the force (below) and a ball
  // passing through it keeps its energy.
  const CurvedPatch cp = curved_patch(cc, weight, facet_area, D, curved_base, deepest_normal,
                                      num_polygons, plain_overlap, member_overlap, faces, work);
  const double facet_scale = cp.facet_scale, facets_u = cp.facets_u;
  const double w = cp.w, other_weights = cp.other_weights;
  const CurvedPeak &curved = cp.curved;
  const Vector3d &curved_area_centre = cp.area_centre, &curved_pressure_centre = cp.pressure_centre,
                 &curved_second_centre = cp.second_centre, &curved_normal = cp.normal;
  const bool deepest_law = !((beta > 0.0 || w > 0.0) && plain_share < 1.0);
  p.point_is_material = point_is_material(deepest_law, blend.placing, p.point, layer);
  if (!deepest_law)
    energy_point(cc, sums, flat, {D, deepest, deepest_normal, poly_normal, plain_share},
                 {w, other_weights, facets_u, facet_scale, curved, curved_area_centre,
                  curved_pressure_centre, curved_second_centre, curved_normal},
                 p);
  p.face_weight = face_weight_of(spread, mean_gradient.norm()) * (1.0 - plain_share);
  patch_extent(s.point, sums, polygons, num_polygons, p);
  return p;
}

} // namespace tri::reduction
