// Contact points of one particle pair (or particle-wall pair) from its triangle-pair contacts,
// reduced so that the summed force does not depend on how finely a face is meshed. This is the
// contract; why each step is as it is: README.md beside it, "The reduction, step by step".
//
// In: the triangle-pair contacts of one pair, the world-frame triangles they were found on and
// the soft layers eps_a, eps_b >= 0 (m). A contact is a raw contact with point (point_a +
// point_b) / 2 (m, world), the kernel's unit normal from a towards b, and overlap eps_a + eps_b
// - distance (m; intersecting: eps_a + eps_b + penetration_depth, growing past contact).
//
// Out: one ContactPoint (contact_point.h: fields, units, frames) per contact patch and normal
// class, deepest first. Raw contacts closer than link_length form a patch (step 1); normals
// within split_angle of the patch's deepest unassigned one a class (2; with
// distinct_spot_distance, not those far from it at a clearly other normal); a class that is a
// deeper class's rim is absorbed into it (3). Per class (4-6): kn overlap along `normal` at
// `point` is the gradient of the elastic energy 1/2 kn energy_overlap^2 (5: a smooth maximum of
// the members' overlaps; 5b: faces lying flat, from their contact polygons; 5c: curved patches,
// from their overlap moments); a class with contact polygons carries its patch's extent (6),
// every other 0 for patch_area, patch_second_moment, patch_mean_radius and face_weight.
//
// Boundary cases: a contact with overlap <= 0 (touching the layer exactly included) or with a
// non-finite point is ignored (with edge lifts: down to -surface_lift, and a point whose overlap
// comes out <= 0 is dropped); none left: `out` is empty. A triangle index out of range throws
// std::out_of_range. Intersecting triangles take the kernel's normal when finite, else
// reference_direction; in a patch with intersecting pairs, separated pairs facing against them
// went through the other surface: their normal is flipped and their overlap is eps_a + eps_b +
// distance. Every output normal is finite and unit (fallbacks: the class's deepest member's,
// then reference_direction).
//
// Accuracy: a flat patch gives the overlap, point and force of the faces' overlap region for any
// meshing, to rounding: contact polygons are exact functions of the triangles, and members that
// could be the deepest are recomputed exactly (distance_tolerance). Overlaps within 1e-6 of the
// layer are ties; the smooth maximum blends members within 1e-3 of the layer of the deepest.
//
// Determinism and threads: the raw contacts are sorted first (overlap descending, tri_a, tri_b,
// the point's coordinates) and every later step and sum runs in that order, so the output is
// bit-identical for any permutation of the input. No global state: one ReductionWorkspace per
// thread. Cost: O(n log n) for n raw contacts (sort, links: point_links.h), O(n x classes) for
// the normal split, one fixed-size polygon clip per member; no allocation once the workspace
// has grown.
#pragma once

#include "contact/contact_point.h"
#include "contact/contact_polygon.h"
#include "contact/point_links.h"
#include "distance/particle_contacts.h" // TriangleContact
#include "geometry/triangle_soa.h"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <vector>

namespace tri {

// Step 5b: how uneven (deepest minus mean overlap over the contact polygons, as a fraction of
// the deepest overlap) a face contact may be before it is treated as the deepest pair alone.
constexpr double kFlatPatchBand = 0.1;
// Step 6: the spread of the polygons' overlap gradients (RMS, dimensionless slope) up to which a
// patch is a flat region on a flat region (face weight 1), falling to 0 at twice it. A ball's
// patch of facets spreads by about its radius over the ball's (0.1 for a soft contact of a
// 2 mm icosphere); two flat faces meshed by any triangles by rounding only.
constexpr double kFlatGradientSpread = 0.01;
// Step 2: normals this far apart (30 degrees), at points farther apart than
// ReductionParams::distinct_spot_distance, are two contacts of a non-convex pair or a crease.
constexpr double kDistinctSpotAngle = 0.5235987755982988;

enum class ReductionMethod {
  clusters,        // the reduction described above (default)
  paper_min_width, // the paper's baseline: drop points closer than min_width to a deeper one
  none             // one ContactPoint per raw contact (validation studies only)
};

struct ReductionParams {
  ReductionMethod method = ReductionMethod::clusters;
  double link_length = 0.0; // m, clusters: see recommended_link_length(); must be > 0
  double split_angle = 0.7853981633974483; // rad (45 deg), clusters: normal-class half-angle
  // m, clusters: > 0 keeps a member out of the seed's class when it lies farther than this
  // from the seed and its normal is more than kDistinctSpotAngle off (step 2: two spots of a
  // non-convex pair, or of a particle in a wall's crease); 0: the angle alone decides.
  double distinct_spot_distance = 0.0;
  double min_width = 0.0; // m, paper_min_width: the minimum mesh width of the two meshes
  // Unit, from a towards b; used only where a normal is otherwise undefined (see above).
  Eigen::Vector3d reference_direction = Eigen::Vector3d::UnitZ();
  // m, how far the contacts' distances may lie above the exact ones (the hybrid kernel's
  // certified tolerance; 0 for brute force): step 5b then recomputes exactly only the polygon
  // members whose overlap could still be the deepest. Infinity (unknown: the unchecked penalty
  // kernel, tests): every one. Never changes a result, only what it costs. A member whose own
  // distance the kernel certified exact (TriangleContact::exact: brute force, about a third of
  // them) is not recomputed; one certified apart (TriangleContact::apart) is recomputed
  // without the intersection test (separated_triangle_distance, triangle_distance.h).
  double distance_tolerance = std::numeric_limits<double>::infinity();
  // The bodies' smooth surfaces (smooth_surface.h: edge_bulges, 3 per triangle, indexed as
  // tris_a / tris_b); null for facets that are the body (a wall, a rock, a cube). Step 5b.
  const double *edge_bulge_a = nullptr, *edge_bulge_b = nullptr;
  // m, a.lift + b.lift (body_interaction.h): contacts whose facets are up to that much beyond
  // the layer still count where edge lifts are given (their smooth surfaces may overlap); a
  // contact point whose overlap comes out <= 0 is dropped.
  double surface_lift = 0.0;
  // Keep the points whose overlap comes out <= 0 within surface_lift: between two balls the
  // spheres decide (contact/ball_contact.h), not the facets.
  bool keep_shallow = false;
  // Set each point's kind (ContactKind, contact_point.h): one pass over the class's members,
  // asked for only by a host that records its contacts.
  bool classify = false;
};

// The link length that keeps every contact patch connected: 2 * min(longest edge of a,
// longest edge of b) + eps_a + eps_b, plus a relative 1e-9 for rounding. A wall's longest edge
// may be passed as infinity (the particle's then decides).
double recommended_link_length(double longest_edge_a, double longest_edge_b, double eps_a,
                               double eps_b);

// Scratch space; reuse one per thread to avoid allocations in the pair loop.
struct ReductionWorkspace {
  struct Raw {
    Eigen::Vector3d point, normal, separation; // separation = point_b - point_a
    double overlap, distance;
    int tri_a, tri_b;
    bool intersecting;
    bool exact, apart;   // TriangleContact's
    bool maybe_parallel; // the triangles are not clearly_not_parallel (contact_reduction.cpp)
  };
  std::vector<Raw> raw;
  struct Key {      // a triangle contact that counts: its overlap, index and triangles; sorted into
    double overlap; // raw's order (the triangles settle most ties without reading the contact)
    int index;
    int tri_a, tri_b;
  };
  std::vector<Key> keys;
  std::vector<Key> sorted_keys;        // keys in order (sort_keys: small sets by rank)
  std::vector<Eigen::Vector3d> points; // raw[i].point, for the links of step 1
  LinkScratch links;
  std::vector<int> parent, order, label, cls, absorbed, seeds, alive, group, tally;
  double split_angle = std::numeric_limits<double>::quiet_NaN(); // cos_split's angle
  double cos_split = 1.0;                                        // its cosine, kept
  std::vector<ContactPolygon> polygons;                          // one class's contact polygons
  std::vector<double> polygon_layers; // per polygon: the layer, or -1 (intersecting, sunk)
  std::vector<int> plain;             // one class's members without a polygon (steps 5 and 5c)
  std::vector<double> smooth_scratch; // step 5: the smooth maximum's weights
  std::vector<double> smooth_share;   // step 5: each member's share of its closest point
  // Per triangle of a and of b: its (unscaled) plane normal and that normal's squared length,
  // computed once per call however many members share the triangle (a vertex touching a face
  // is seen by all the triangles around it); valid where the stamp equals `call`.
  struct TriangleNormal {
    Eigen::Vector3d normal;
    double norm2;
    unsigned stamp = 0;
  };
  std::vector<TriangleNormal> normals_a, normals_b;
  unsigned call = 0;
};

// Reduces `n` triangle-pair contacts of one pair (entries with overlap <= 0 are ignored) and
// writes the contact points into `out` (cleared first), deepest first. tris_a, tris_b: the
// world-frame triangles that the contacts were found on (the distance kernel's a and b);
// contact k's tri_a indexes tris_a and tri_b indexes tris_b (std::out_of_range otherwise).
// eps_a, eps_b >= 0 (m).
void reduce_contacts(const TriangleContact *contacts, int n, const TriangleSoA &tris_a,
                     double eps_a, const TriangleSoA &tris_b, double eps_b,
                     const ReductionParams &params, ReductionWorkspace &work,
                     std::vector<ContactPoint> &out);

// The same for the distance kernel's results on a pair list, read in place (the pair loop's
// form): results[k] on triangles pairs[k].a of a and pairs[k].b of b; those closer than
// `cutoff` count, as contacts_from_results (particle_contacts.h) reports them, and the output
// is bitwise reduce_contacts' of that function's list, without building it.
void reduce_kernel_results(const TrianglePairIndex *pairs, const TrianglePairDistance *results,
                           int count, double cutoff, const TriangleSoA &tris_a, double eps_a,
                           const TriangleSoA &tris_b, double eps_b, const ReductionParams &params,
                           ReductionWorkspace &work, std::vector<ContactPoint> &out);

// Convenience form for tests and tools.
std::vector<ContactPoint> reduce_contacts(const std::vector<TriangleContact> &contacts,
                                          const TriangleSoA &tris_a, double eps_a,
                                          const TriangleSoA &tris_b, double eps_b,
                                          const ReductionParams &params);

} // namespace tri
