// Contact points of one particle pair (or particle-wall pair) from its triangle-pair
// contacts, reduced so that the summed force does not depend on how finely a face is meshed.
//
// Contact geometry (paper, section 2): every particle carries a soft layer, eps_a and eps_b
// (m). A triangle pair closer than eps_a + eps_b is a raw contact with
//   point   = (point_a + point_b) / 2          midway between the closest points (m, world)
//   normal  = the kernel's normal, unit, from a towards b
//   overlap = eps_a + eps_b - distance          (m, > 0; intersecting pairs:
//             eps_a + eps_b + penetration_depth, so the overlap keeps growing past contact)
//
// Why a reduction, and why this one. Two flat faces in contact produce one raw contact per
// triangle pair whose closest points lie in the soft layers: their number grows with the
// square of the mesh resolution, and a force per raw contact makes the stiffness of a
// resting cube grow with it. The paper's rule (drop points closer than the minimum mesh
// width) removes near-duplicates only: the surviving count still grows with resolution
// (test ReductionPaperBaseline.CountGrowsWithResolution). Here one contact patch -- a
// connected piece of the overlap of the two soft layers -- gives ONE contact point:
//  1. Spatial connectivity (union-find): two raw points are linked when they are closer than
//     `link_length`. Closest points of a triangle pair lie on both triangles, so the raw
//     points of two edge-adjacent triangles of the finer mesh are at most
//     2 * longest edge + (eps_a + eps_b) apart (the midpoint moves by half the gap):
//     recommended_link_length() returns that bound, so a patch is never torn apart by the
//     mesh, at any resolution, while regions farther apart stay separate (a non-convex
//     particle touching in two places).
//  2. Normal classes inside a connected region: the deepest unassigned raw contact seeds a
//     class that takes every unassigned member whose normal is within `split_angle` of the
//     seed's. A particle wedged in a corner (two faces at 90 degrees whose patches meet at an
//     edge) thus keeps one contact per face.
//  3. Rim absorption: near the border of a flat patch, triangles of the other mesh that lie
//     just outside the footprint see the patch's EDGE at a slant (normal tilted up to ~90
//     degrees, small overlap). Their number depends on the mesh, so they must not become
//     contacts of their own. A class S is absorbed into an earlier (deeper) class M of the
//     same region when n_S . n_M > 0 and every member j of S, measured along M's normal,
//     overlaps no more than M does: (eps_a + eps_b) - s_j . n_M <= overlap_M (+ 1e-6 of the
//     layer), s_j = point_b - point_a being j's separation vector. Rim contacts satisfy this
//     exactly (their separation along n_M is the patch's own gap); a second face at 90
//     degrees or more never does.
//  4. One ContactPoint per class: overlap = the largest member overlap (so a flat patch at
//     uniform gap gives exactly eps_a + eps_b - gap, whatever the mesh; with contact polygons,
//     step 5b); point: see steps 5 and 5b;
//     normal = the deepest member's normal, averaged (overlap-weighted) over the members tied
//     with it to 1e-6 (eps_a + eps_b) (a flat face). The deepest pair is the pair of closest
//     points of the two surfaces, whose direction is the contact normal of two convex bodies;
//     averaging over the whole class instead lets the slanted contacts near a corner or border
//     tilt a flat contact (measured: up to 5% lateral force for a tilted cube on a finely
//     meshed plane); min_distance = the smallest member distance (for the paper's time-step
//     rule); num_merged counts every member, absorbed ones included.
//  5. The point: the gradient of the contact's energy. The force is kn x the deepest overlap,
//     the gradient of 1/2 kn overlap^2 when it acts through the deepest pair of closest points
//     (the overlap changes with the bodies' motion exactly as that pair's distance does). Any
//     other point -- an overlap-weighted centroid of the members, a centre of pressure -- gives
//     a torque that is not the gradient of the energy and a tumbling rock gains or loses energy
//     at every impact (measured, validation/contact/energy: a box of 32 rocks drifted 2.5 % in
//     1e5 steps with the weighted centroid, 16-18 % in one bounce with a centre of pressure).
//     But the plain maximum's gradient jumps where two closest points trade places: an edge
//     lying flat on a face (every point of it is a closest point) had its point jump from the
//     middle to one end at the slightest roll, a bang-bang torque that made a cube resting on
//     an incline chatter in roll at the time-step scale and walk (6 um/s). So the overlap of a
//     class without contact polygons (5b) is a smooth maximum F of the members' overlaps
//     (smooth_deepest in the .cpp): members within kDeepestTaper = 1e-3 of the layer of the
//     deepest share it, with weights rising smoothly from 0 at the taper's edge, and the point,
//     the normal and the force's size are F's gradient: force kn F |sum_i (dF/do_i) n_i| along
//     that sum, at the members' midpoints weighted by dF/do_i, moved across the normal so that
//     the force's moment is F's gradient under rotation (but for its twist about the normal,
//     which one force cannot carry). The weights are m_i = w_i a_i^2 / sum w_j a_j^2 on
//     a_i = 1 - (D - o_i) / taper, so any number of members tied with the deepest (the
//     triangle pairs that all see one edge, the two ends of an edge lying flat) give F = D
//     exactly, whatever the meshing; between ties F dips below D by at most a fraction of the
//     taper. w_i = 1 / (the members at i's point, within kSameFeatureDistance = 1e-4 of the
//     layer, tied with its overlap): each closest point counts once however many triangle pairs
//     see it. Counted per member, near a tie F leans to the point more pairs see, and when one
//     pair's closest point jumps from one end of a parallel edge to the other (both ends tied
//     at that moment), the counts swap and the force's point jumped by a third of the distance
//     between the two points: voxel jacks gained 1.3e-4 of their energy in one such step
//     (validation/contact/energy_nonconvex; test ClosestPointsSeenByManyPairsCountOnce). F is
//     faded in over the first
//     taper of depth, so a contact starts and ends at F = 0. With a taper whose point was not
//     F's gradient, a member crossing the band in a few steps
//     gained or lost energy: non-convex gears, voxel jacks and U shapes colliding without
//     damping or friction ended 0.3-4e-4 off and did not converge as dt fell
//     (validation/contact/energy_nonconvex).
//  5b. Faces lying flat on each other. There the deepest pair is arbitrary (any point of the
//     faces' overlap is a closest point; the kernel returns one, often a vertex, and its
//     distance to within its tolerance): a resting cube would be pushed at a corner, tip, and
//     rest on a point that depends on the meshing; and the energy 1/2 kn max_overlap^2 has a
//     kink at flat (tilting either way deepens one side). So each member whose two triangles
//     are nearly parallel (within kParallelFaceAngle = 10 degrees, contact_polygon.h) gets its
//     contact polygon: the overlap of the two triangles projected along their bisector m, cut
//     to where the soft layers overlap, on which the local overlap o is affine, with its
//     integrals (area, of o, of o^2, first and second moments) and o at its corners. The
//     triangles of a face partition it, so the polygons of all pairs of two faces tile the
//     faces' overlap region for ANY meshing: its area A, area centre c_A, mean overlap
//     m = integral of o / A, mean square Q = integral of o^2 / A and centre of pressure c_P are
//     the faces', to rounding, and they are exact functions of the triangles: no distance-kernel
//     tolerance enters. That matters: the hybrid kernel is exact to 1e-4 epsilon (1e-8 m here),
//     which is 1 % of the overlap of a light cube at rest (kn 2000, 4 mm, 0.8 um), and its
//     closest points of parallel triangles jump: measured with the previous rule (deepest pair
//     from the kernel), a 12-triangle cube at rest on a 2-triangle plane rocked at 1e-4 rad/s
//     (1e-13 with the brute-force kernel), on 5 to 15 degree inclines at 1e-3 to 1e-2 rad/s.
//     With polygons:
//       D   = the largest corner overlap over the polygons (exact; the deepest overlap);
//       p_D = the deepest region: each polygon's part within kDeepestTaper of the layer of D,
//             weighted by o - (D - taper) (continuous in the geometry, smoothing the tie of an
//             edge lying flat, step 5), its centroid moved along the polygon's overlap gradient
//             onto the polygon's own deepest level (a tilted face's deepest point is then ON its
//             low edge, not a taper's width inside it: 1e-4 instead of 1.5e-3 work error in
//             FaceContactForceIsTheGradientOfItsEnergy);
//       r   = hypot(D - m, g layer / 2) / (kFlatPatchBand D), g the polygons' mean overlap
//             slope (how uneven, over the patch or across a layer's width, whichever is wider:
//             0 lying flat; a vertex's cone or an edge's wedge has m = D/3 or D/2 at any depth,
//             r >= 5; a sliver of a steep face at a corner is uniform by its size alone, and
//             taken for flat its energy, a mean over a region whose edges sweep through it,
//             would miss their work: test SliverOfATiltedFaceKeepsTheEnergy);
//       beta = 1 - 3 r^2 + 2 r^3 for r < 1, 0 beyond (C1 at both ends).
//     The contact's energy is 1/2 kn Omega,  Omega = (1 - beta) D^2 + beta Q:
//     the deepest pair's law from r = 1 on (a clearly uneven face, an impacting edge), and lying
//     flat the energy of the same stiffness spread uniformly over the patch, kn / A per area (a
//     Winkler foundation): force kn m at the centre of pressure, tilt stiffness kn J / A, a
//     resting face's pressure shifting towards its low side as a real one does. Since A is fixed
//     while a face lies flat (its whole face overlaps), dm = do(c_A), dQ = 2 m do(c_P) and
//     dD = do(p_D) for a motion that changes the local overlap by do(x); with
//     dr = ((k - b r) dD - k dm + (1 - k^2)^(1/2) dS) / (b D)  (b = kFlatPatchBand,
//     k = (D - m) / (r b D), 1 unless the slope term counts, S = g layer / 2; S changes with
//     the faces' relative tilt alone, so its part is a couple, carried by moving the point
//     along g: test TiltingNarrowPatchKeepsTheEnergy):
//       d Omega = a_D do(p_D) + a_A do(c_A) + a_P do(c_P),
//       a_D = 2 (1 - beta) D + (Q - D^2) beta' (k - b r) / (b D),
//       a_A = -(Q - D^2) beta' k / (b D),     a_P = 2 beta m,
//     so the force is kn (a_D + a_A + a_P) / 2 (reported as `overlap`, `energy_overlap` =
//     sqrt(Omega)) along the normal at the point (a_D p_D + a_A c_A + a_P c_P) / (a_D + a_A + a_P)
//     (the sum is at least 1.67 D: Q <= D^2, beta' <= 0). Lying flat: kn m at c_P, whatever the
//     meshing; a tilt moves c_P towards the low side (a restoring torque, flat is a stable rest
//     with no chatter); an impacting, clearly tilted face gets the deepest pair; every force and
//     torque is the gradient of one energy (test FaceContactForceIsTheGradientOfItsEnergy). The
//     normal: (1 - beta) n_D + beta n_A, normalised, n_A the polygons' area-weighted bisector
//     (exact; the gradient direction of Q for faces lying flat), n_D = beta x the deepest
//     region's bisector + (1 - beta) x the kernel's deepest normal (step 4: the closest-point
//     direction, the gradient direction of a tilted face's D). Members without a polygon in the
//     same class (the side faces of a cube seen edge-on along its bottom edge, within the
//     kernel's tolerance of the face's own deepest overlap) take over only where they are
//     deeper than the polygons by more than the taper: their share rises from 0 to 1 (smooth
//     step) as they exceed D by 1 to 2 tapers, moving D, p_D and the normal to theirs and
//     beta to 0; within it they are the same closest points seen through the kernel's
//     tolerance. D here is the plain maximum and p_D its tapered region (not step 5's smooth
//     maximum): a contact whose last polygon member tilts past 10 degrees moves to
//     step 5's smooth maximum, which equals D where the members are tied with the deepest (a
//     rock's face leaving a face, seen by several triangle pairs at once). Not the smooth
//     maximum here too, with the members without a polygon lowered by 2 beta
//     tapers so that a face's rim stays out -- its energy couples F to beta, whose gradient
//     scales as 1 / D, and a cube landing on a plane was kicked to 5 rad/s at D ~ taper.
//     Members that are not nearly parallel (vertex-face, edge-edge, edge-face,
//     faces at a clear angle) carry no area; absorbed rim contacts neither place nor orient the
//     point. The switch at 10 degrees: a face tilted that far is uneven by at least
//     sin(10 deg) / 2 of its width over the overlap (or the overlap is a wedge, r >= 5), so both
//     sides of the switch give the deepest pair and its overlap (the polygons' measured along
//     the bisector, short of the perpendicular one by gap (1 / cos 5 deg - 1) = 0.4 % of the
//     gap there) unless the face is narrower than about 1.2 layers. The baselines
//     (paper_min_width, none) keep the kernel's midpoints: they are the paper's.
//     Smooth surfaces (smooth_surface.h). A body whose mesh samples a smooth surface (a finely
//     meshed ball: its vertices on the sphere, its facets chords up to the sag below it) is
//     measured on that surface against a wall: each member's polygon (clipped where the lifts
//     may still reach, o >= -lift) gets its facets' lifts, and D becomes the largest o + h_a +
//     h_b over them, its point and normal the smooth surfaces' there (taking over from the
//     polygons' deepest point over the first taper of the gain). Where nothing is lifted (flat
//     facets, a cube, a rock, a wall) the gain is 0 and the result bitwise the facets'. The
//     search reaches epsilon + the body's largest lift (body_interaction.h, Body::lift), so a
//     contact starts when the smooth surface, not the first vertex, enters the layer: starting
//     at the vertex was a force switched on at up to the sag (0.3 um of a 6.5 um impact of a
//     20480-triangle icosphere), and with kt = kn at small vt / vn it alone put the rebound spin
//     4-6 % off a sphere's (validation/contact/oblique). With it, oblique impacts of levels 3 to
//     5 agree with the ideal ball to 0.5 % (level 5: 0.04 %) and a frictionless head-on impact
//     leaves no spin (0.002 % of vn). Particle pairs keep their facets for now: the smooth
//     peak over step 5b's 10-degree polygons has holes between two coarse balls (their facets at
//     the peak tilt independently by up to half the facet angle), and widening the polygons to
//     45 degrees measured spurious peaks on steep facet pairs (deep wall impacts: 3.6 layers
//     for 2), so both were dropped (validation/contact/deep, pairs: e 0.976 undamped).
//  5c. Curved patches: a finely meshed ball. Its deepest corner is a vertex that turns with the
//     ball, so the deepest pair's force has a lever about the centre (kn D R sin(turn)) that
//     refining the mesh does not remove (an impact turns the ball by far less than a facet):
//     a frictionless head-on impact of a 20480-triangle icosphere left it spinning at 6 % of
//     the impact speed over R (validation/contact/oblique), and two balls pressed together
//     pushed along a facet's normal, 0.012-0.021 rad off their line of centres. Where
//       - the polygons' overlap gradients turn over the patch (curved_weight(spread), the
//         complement of step 6's flat test),
//       - the patch is whole: its members' polygons up to kCurvedFacetAngle (45 degrees; a
//         ball's cap passes step 5b's 10 degrees at an overlap of 1.5 % of R) cover all but
//         kCurvedOutsideShare of the class's raw overlap (a steep side or an edge's other face
//         cuts it off),
//       - its bodies are finely faceted: the angle between neighbouring facets, estimated as
//         sqrt(2) x the RMS turn of the more curved body's normal over the patch x the facet
//         size / the patch radius, is below kCurvedFineAngle (0.08; to 0 at twice it: a
//         1280-triangle icosphere, 0.15, or a polyhedron's corner is its facets at any depth),
//       - and the patch spans several facets (n = M1 / (D f) from kCurvedFacetsFrom to
//         kCurvedFacetsFull, f the polygons' overlap-weighted smaller triangle area),
//     the deepest overlap D is replaced by the peak of the patch's overlap moments,
//       Phi = M2 M3 / (3 M2^2 - 2 M1 M3),  M_p = integral of o^p over those polygons
//     (contact_polygon.h curved_peak: exactly D for any profile homogeneous about its peak --
//     a vertex's cone, an edge's wedge, a paraboloid -- and, being an integral, blind to which
//     vertex is deepest). The moments are taken along one direction (the deepest normal) with
//     every corner on a's surface, so the polygons of neighbouring facets add up to one field.
//     With w the product of those weights, X = (1 - w) D^2 + w Phi^2 replaces D^2 in step 5b's
//     Omega; its gradient acts at the moments' area centre, centre of pressure and centroid of
//     o^2 (dM_p = p M_(p-1) do(c_(p-1)): curved_peak's weights), plus the gradient of w through
//     n (dn from dM1 and dD; f and the other weights held fixed: they are 1 or 0 on a ball), so
//     a ball passing through the blend keeps its energy (oblique head-on impacts return vn to
//     2e-5). Its direction is the peak's gradient under translation: a translation d of b
//     changes o by -n_b . d, so the normal is (sum over the moments' weights of the integrals
//     of o^(p-1) n_b) normalised -- a wall's normal exactly, and for two balls the line of
//     centres to 0.2-2 mrad (tests CurvedContact.*). A vertex, an edge or a coarse ball keeps
//     the deepest pair exactly; a face on a face (gradients agree) keeps step 5b.
//     What it does not fix: Phi of a faceted cap sits below the circumscribed sphere's overlap
//     by about the mean facet sag (the deepest vertex by 0 to the full sag), and its gradient
//     point is an extrapolation (weights about 6, -21 and 16 for a paraboloid) that carries the
//     facets' discretisation to the lever amplified: a level-5 ball's head-on spin is 0.6 %,
//     not 0, and with kt = kn in the sticking regime its rebound spin is still 8 % off
//     (validation/contact/oblique). Against a wall a smooth body's patch is measured on its
//     smooth surface instead (step 5b), which leaves the moments to particle pairs and to
//     curved meshes that are not smooth surfaces.
//  6. The patch's extent, for the rocking damper and the twisting friction of contact_model.h.
//     The force of a contact acts at one point, so a rotation of the two bodies about that
//     point (about an axis in the contact plane: one face rocking on the other) gives no normal
//     velocity there and the normal dashpot does not resist it, and a rotation about the normal
//     moves nothing at the point, so point friction does not resist it either, while a real
//     (or a pressure-like, distributed) contact of two faces is squeezed on one side and
//     released on the other, and rubs over its whole region when it twists: the rocking of a
//     face contact would be undamped (measured: a cube sliding down an incline with friction
//     rocked at several rad/s, validation/contact/friction), a spinning cube would never stop
//     and a resting one would turn under any off-centre friction (validation/contact/twist). So
//     a class with polygons also carries
//       patch_area          = A (m^2);
//       patch_second_moment = the polygons' second moments of area, each moved from its own
//                             area centroid to the contact point (parallel-axis theorem:
//                             J_i + A_i d_i d_i^T, d_i = area_centroid_i - point), projected onto
//                             the contact plane (P J P, P = I - n n^T): m^4, symmetric 3x3,
//                             world frame, J n = 0;
//       patch_mean_radius   = the region's mean distance from the point, integral of |x - p| dA
//                             / A over the polygons projected onto the contact plane (closed
//                             form per polygon edge, contact_polygon.h polygon_distance_integral):
//                             the lever of Coulomb friction spread over a uniformly pressed
//                             region turning about the point (mu F_n r_mean); 0 when
//                             face_weight is 0 (a point-like contact does not twist against
//                             its patch, so the integral is skipped);
//       face_weight         = how much the contact is a flat region on a flat region (times
//                             one minus the share of members without a polygon): 1 when the
//                             polygons' overlap gradients (the relative slope of the two
//                             surfaces) are the same over the whole patch, 0 when they turn
//                             over it (area-weighted RMS deviation above 2 kFlatGradientSpread:
//                             the facets of a ball, whose slope turns by patch radius / R) and,
//                             smoothly, as the faces tilt from 5 to 10 degrees (the polygons'
//                             range). The rocking damper and the twist spring act in proportion
//                             to it: a vertex, an edge, a face about to leave the polygons'
//                             range, or a ball on near-flat facets is a point, free to roll and
//                             to twist as LIGGGHTS's spheres are; a face pressed on a face, evenly
//                             or not (a cube resting on an incline, sliding, or stacked off
//                             centre), rocks damped and twists against friction. Not beta: a
//                             face loaded off centre is uneven (its centre of pressure moves
//                             towards the low side, r >= 1 for an eccentricity of a sixth of its
//                             width) and is still a face (measured with beta: a cube stacked
//                             1 mm off centre on another kept turning at 1.3 rad/s, a cube
//                             sliding down an incline rocked at 1.7 rad/s).
//       damping_point       = the patch's area centre c_A: where the normal dashpot measures
//                             the approach and acts (contact_force.h). The deepest point of a
//                             ball rolling over facets is a vertex off its lowest point, whose
//                             material velocity has a normal part +-omega x offset as the vertex
//                             passes under (measured: a 1280-triangle icosphere rolling down
//                             20 degrees, gamman 200, accelerated 1.5 % below the rigid-body value
//                             with the dashpot there); the region's centre sees the approach of
//                             the two bodies, not the passing of facets, and a dashpot force at
//                             the point where its velocity is measured only dissipates.
//     Like the point, all are those of the faces' overlap region for any meshing (the polygons
//     tile it). A class without polygons gets 0 for all: no couple, no twist, the dashpot at
//     the point.
//
// Intersecting triangles (real surfaces crossing: the soft layer was overrun). The kernel's
// normal for such a pair (minimum-overlap separating axis) is used when finite; otherwise
// `reference_direction` (a unit vector from a towards b that the caller supplies: the line of
// centres for two particles, the wall's normal towards the wall for a wall). In a connected
// region that contains intersecting pairs, non-intersecting pairs whose normal points against
// the intersecting pairs' mean normal are triangles that went THROUGH the other surface (a
// face sunk below a plane sees the plane from behind): their normal is flipped and their
// overlap is eps_a + eps_b + distance, so the force keeps growing with penetration instead of
// changing sign. A class whose weighted mean normal degenerates (opposite normals cancel)
// takes the seed's normal, and if that is not finite the reference direction: every output
// normal is finite and unit.
//
// Determinism: the raw contacts are sorted first (overlap descending, then tri_a, tri_b, then
// the point's coordinates) and every later step and every sum runs in that order, so the
// output is bit-identical for any permutation of the input (e.g. any thread count upstream).
// Output order: deepest contact first.
//
// Cost: O(n log n) for n raw contacts (sort + sweep or grid for the links, point_links.h), plus
// O(n * classes) for the normal split, plus one polygon clip (fixed-size, on the stack) per
// member; no allocation when the workspace is reused.
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

enum class ReductionMethod {
  clusters,        // the reduction described above (default)
  paper_min_width, // the paper's baseline: drop points closer than min_width to a deeper one
  none             // one ContactPoint per raw contact (validation studies only)
};

struct ReductionParams {
  ReductionMethod method = ReductionMethod::clusters;
  double link_length = 0.0; // m, clusters: see recommended_link_length(); must be > 0
  double split_angle = 0.7853981633974483; // rad (45 deg), clusters: normal-class half-angle
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
  // Set each point's kind (ContactKind above): one pass over the class's members, asked for
  // only by a host that records its contacts.
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
    bool exact, apart; // TriangleContact's
    bool maybe_parallel; // the triangles are not clearly_not_parallel (contact_reduction.cpp)
  };
  std::vector<Raw> raw;
  struct Key { // a triangle contact that counts: its overlap, index and triangles; sorted into
    double overlap; // raw's order (the triangles settle most ties without reading the contact)
    int index;
    int tri_a, tri_b;
  };
  std::vector<Key> keys;
  std::vector<Key> sorted_keys; // keys in order (sort_keys: small sets by rank)
  std::vector<Eigen::Vector3d> points; // raw[i].point, for the links of step 1
  LinkScratch links;
  std::vector<int> parent, order, label, cls, absorbed, seeds, alive, group, tally;
  double split_angle = std::numeric_limits<double>::quiet_NaN(); // cos_split's angle
  double cos_split = 1.0;                                         // its cosine, kept
  std::vector<ContactPolygon> polygons; // one class's contact polygons
  std::vector<double> polygon_layers;   // per polygon: the layer, or -1 (intersecting, sunk)
  std::vector<int> plain; // one class's members without a polygon (steps 5 and 5c)
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
// world-frame triangles that the contacts were found on (find_triangle_contacts' a and b);
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
