// What the steps of the reduction (contact_reduction.h; README.md, "The reduction, step by
// step") share: internal to contact/reduction_*.cpp and contact_reduction.cpp, no contract of
// the kernel. Step numbers are the README's.
#pragma once

#include "contact/contact_point.h"
#include "contact/contact_polygon.h"
#include "contact/contact_reduction.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tri::reduction {

using Eigen::Vector3d;
using Raw = ReductionWorkspace::Raw;

// Members whose overlap is within this fraction of the layer of the deepest one define the
// normal: ties up to rounding (step 4).
constexpr double kNormalDepthBand = 1e-6;
// Members within this fraction of the layer of the deepest one share the deepest point, with
// weights falling to zero across it (step 5).
constexpr double kDeepestTaper = 1e-3;
// Members closer than this fraction of the layer, and tied in overlap (kNormalDepthBand), are
// one closest point seen by several triangle pairs: the smooth maximum counts it once (step 5).
constexpr double kSameFeatureDistance = 1e-4;
// Step 5c: the share of a class's raw overlap on members without a polygon from which on a
// curved patch keeps its deepest corner (smoothly from 0).
constexpr double kCurvedOutsideShare = 0.05;
// Step 5c: the angle between neighbouring facets up to which a curved patch is a smooth surface
// (then smoothly to twice it, where it is its facets).
constexpr double kCurvedFineAngle = 0.08;
// Step 5c: the number of facets a patch spans from which on its moments' peak starts to count,
// and from which on it is used alone (smoothly between).
constexpr double kCurvedFacetsFrom = 2.0;
constexpr double kCurvedFacetsFull = 8.0;

// The two bodies' triangles (never null) and their smooth surfaces.
struct Faces {
  const TriangleSoA *a, *b;
  const double *bulge_a = nullptr, *bulge_b = nullptr; // smooth_surface.h, 3 per triangle
  double lift = 0.0;                                   // m, ReductionParams::surface_lift
};

// One normal class of one connected region (steps 2 and 3), as the later steps read it.
struct ContactClass {
  const std::vector<Raw> &raw;
  const std::vector<int> &members;  // the region's raw indices, deepest first
  const std::vector<int> &cls;      // per raw contact: its class
  const std::vector<int> &absorbed; // per raw contact: 1 if a rim contact (step 3)
  int id;                           // this class
  int seed;                         // its deepest member (raw index)
  double layer;                     // m, eps_a + eps_b
  // A member that places and orients the point (rim contacts only count).
  bool places(int i) const { return cls[i] == id && !absorbed[i]; }
};

inline bool finite(const Vector3d &v) { return std::isfinite(v.x() + v.y() + v.z()); }

// Smoothstep 3 x^2 - 2 x^3 on [0, 1], 0 below, 1 above.
inline double smoothstep(double x) {
  if (!(x > 0.0))
    return 0.0;
  if (!(x < 1.0))
    return 1.0;
  return x * x * (3.0 - 2.0 * x);
}

// The blend of step 5b: beta(r) = 1 - 3 r^2 + 2 r^3 for the flat-patch measure r (1 lying flat,
// 0 from r = 1 on, C1 at both ends) and its derivative.
inline double flat_blend(double r) {
  if (!(r < 1.0))
    return 0.0;
  const double q = std::max(0.0, r);
  return (1.0 - q) * (1.0 - q) * (1.0 + 2.0 * q);
}
inline double flat_blend_slope(double r) {
  if (!(r < 1.0) || !(r > 0.0))
    return 0.0;
  return -6.0 * r * (1.0 - r);
}

// How curved a patch is (step 5c): 0 while its polygons' overlap gradients agree (a face on a
// face, tilted or not: the deepest corner is the peak of the real surfaces), 1 once they spread
// by 2 kFlatGradientSpread (the facets of a ball, a vertex's or an edge's facets: the moments'
// peak). The complement of face_weight_of's spread factor.
inline double curved_weight(double spread) {
  return smoothstep((spread - kFlatGradientSpread) / kFlatGradientSpread);
}

// Face weight of a patch (step 6): 1 when its polygons are the overlap of two flat regions
// (the same overlap gradient over the whole patch: a face on a face, tilted or not, evenly or
// eccentrically pressed), 0 when the gradient turns over the patch (spread above
// 2 kFlatGradientSpread) or the faces are about to leave the polygons' range (tilt from
// kParallelFaceAngle / 2 to kParallelFaceAngle): smooth in both. spread, tilt: the
// area-weighted RMS deviation and the magnitude of the mean of the polygons' overlap gradients.
inline double face_weight_of(double spread, double tilt) {
  const double tilt_full = 2.0 * std::tan(0.25 * kParallelFaceAngle);
  const double tilt_end = 2.0 * std::tan(0.5 * kParallelFaceAngle);
  return (1.0 - curved_weight(spread)) *
         (1.0 - smoothstep((tilt - tilt_full) / (tilt_end - tilt_full)));
}

// Steps 1 to 3, then one point per class (make_point) into `out`, deepest first.
void reduce_clusters(std::vector<Raw> &raw, double layer, const ReductionParams &params,
                     const Vector3d &ref, const Faces &faces, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out);

// Steps 4 to 6 for one class: its contact point. `tolerance`: ReductionParams::
// distance_tolerance; `ref`: the unit reference direction.
ContactPoint make_point(const ContactClass &cc, const Vector3d &ref, const Faces &faces,
                        double tolerance, ReductionWorkspace &work);

// Step 5: the smooth maximum F of the overlaps of raw[cands[i]] and its gradient's point,
// normal and size (the force is kn overlap normal_scale along normal). `weights` receives
// dF/do_k, `share` each member's share of its closest point.
struct SmoothDeepest {
  double overlap = 0.0, normal_scale = 1.0;
  Vector3d point, normal;
  Eigen::AlignedBox3d placing; // the points of the members with a share of the point
};

// How far from `point` the points that place it (`placing`) may lie, m; 0 for none.
inline double farthest_from(const Eigen::AlignedBox3d &placing, const Vector3d &point) {
  if (placing.isEmpty())
    return 0.0;
  return (point - placing.min()).cwiseAbs().cwiseMax((point - placing.max()).cwiseAbs()).norm();
}

// ContactPoint::point_is_material: the deepest pair's law, placed by points within
// kMaterialPointSpread of the layer of the point.
constexpr double kMaterialPointSpread = 0.1;
inline bool point_is_material(bool deepest_law, const Eigen::AlignedBox3d &placing,
                              const Vector3d &point, double layer) {
  return deepest_law && farthest_from(placing, point) <= kMaterialPointSpread * layer;
}
struct SmoothDeepestBands {
  double taper;      // m, the band below the deepest overlap that shares it
  double tie_band;   // m, overlaps closer than this are tied
  double same_point; // m, tied members closer than this are one closest point
};
SmoothDeepest smooth_deepest(const std::vector<Raw> &raw, const std::vector<int> &cands,
                             const SmoothDeepestBands &bands, const Vector3d &fallback_point,
                             const Vector3d &fallback_normal, std::vector<double> &weights,
                             std::vector<double> &share);

} // namespace tri::reduction
