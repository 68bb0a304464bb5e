// One contact point between two bodies: what the reduction (contact_reduction.h) makes of a
// region of close triangle pairs, and what the force law (model/contact_force.h) and the
// contact history read. The steps named below are the reduction's.
#pragma once

#include <Eigen/Core>

namespace tri {

// What carries a contact, for output (compute tri/contact/local): a flat region on a flat region
// (face: face_weight >= 0.5, step 6), else the closest points tied with the deepest one (within
// kDeepestTaper of the layer, step 5): spread along a line longer than the layer (edge: an edge
// lying along a face or along an edge) or at one place (vertex: a corner on a face, two edges
// crossing, a ball on facets); deep where the real surfaces intersect (the soft layer overrun),
// whatever the region. Set by the reduction only when ReductionParams::classify is; it changes
// no force.
enum class ContactKind : int { face = 1, edge = 2, vertex = 3, deep = 4 };

struct ContactPoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // m, world frame
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit, from a towards b
  double overlap = 0.0;       // m, > 0: eps_a + eps_b - (signed) distance of the deepest member
  double min_distance = 0.0;  // m, >= 0: smallest closest-point distance among the members
  int num_merged = 0;         // raw triangle-pair contacts represented by this point
  bool intersecting = false;  // some member's triangles intersect
  int tri_a = -1, tri_b = -1; // the deepest member's triangles (diagnostics)
  // Extent of a face contact (step 6): 0 for a point-like contact.
  double patch_area = 0.0;                                       // m^2
  Eigen::Matrix3d patch_second_moment = Eigen::Matrix3d::Zero(); // m^4, about `point`, in the
                                                                 // plane orthogonal to `normal`
  double patch_mean_radius = 0.0; // m, mean distance of the patch from `point` (step 6)
  double face_weight = 0.0;       // 1 lying flat, 0 point-like or clearly tilted (step 6)
  // Where the normal dashpot measures the approach and pushes (step 6): the patch's area
  // centre when patch_area > 0 (else unused: `point`).
  Eigen::Vector3d damping_point = Eigen::Vector3d::Zero(); // m
  // The overlap whose 1/2 kn energy_overlap^2 is the contact's elastic energy (step 5b); equal
  // to `overlap` except for faces lying flat (there `overlap` is the force's, kn overlap).
  double energy_overlap = 0.0; // m
  // Whether the force's point goes with the bodies' material at it: the deepest pair's law
  // (step 5, or 5b with beta = 0 and no curved patch) at one place, every point that places it
  // (the closest points or corners within the taper of the deepest) within a tenth of the layer
  // of it (a vertex, two edges crossing, a tilted face's corner, an edge more than 0.6 degrees
  // off flat). A motion d of the bodies changes those points' weights by 2 d / taper, so it moves
  // the point against their material by at most 200 d (2 um for a layer of 0.1 mm and
  // keep_contacts' default tolerance: a thousandth of a 4 mm particle's lever). Not so for a face
  // lying flat or a curved patch (a centre of pressure) nor an edge lying flat (the middle of the
  // closest points tied along it): their point slides across the patch or along the edge under
  // tilts of micro-radians, and that slide is their restoring torque. Set by the reduction
  // (contact_reduction.h steps 5, 5b).
  bool point_is_material = true;
  ContactKind kind = ContactKind::vertex; // with ReductionParams::classify (else vertex)
};

} // namespace tri
