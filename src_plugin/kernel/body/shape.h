// A particle shape template: a validated closed mesh in its body frame plus the numbers the
// dynamics and the contact search need. Every particle of the shape shares one Shape.
//
// Body frame: origin at the centre of mass, axes along the principal axes of inertia in
// ascending order of moment (MassProperties::principal_axes, including its convention for
// repeated moments), right-handed. world = R q * body + x for a particle at x with
// orientation q.
//
// Input frame: the frame of the mesh given to make_shape (a mesh file's own coordinates after
// `scale`; for a random rock, the generator's frame: its centre of mass at the origin and the
// stretch axes of `aspect` along x, y, z). The Shape keeps how the two relate:
//   input = principal_axes * body + centre_of_mass,
// so a particle with orientation input_orientation (R = principal_axes) at x has the world
// triangles input - centre_of_mass + x: the input mesh translated, its centre of mass at x.
#pragma once

#include "body/mass_properties.h"
#include "body/shape_error.h"
#include "body/smooth_surface.h"
#include "geometry/triangle_mesh.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace tri {

// Relative tolerance of the convexity test: a vertex counts as "behind" a face plane when its
// signed distance is at most kConvexityTolerance x (2 x bounding_radius).
constexpr double kConvexityTolerance = 1e-9;

// Two surfaces. `mesh` is the given surface: the contact surface, and what mass, inertia, the
// bounding radius and output refer to. `soa` and the numbers after `inertia_per_density` up to
// `surface_lift` describe the surface the contact kernel measures: `mesh` offset inward by
// `layer` (inner_surface.h), the same triangles in the same order; with layer 0 (make_shape)
// it is `mesh` itself.
struct Shape {
  std::string name;
  TriangleMesh mesh;   // body frame; unreferenced vertices removed
  TriangleSoA surface; // mesh as SoA, same triangles, same order
  double layer = 0.0;  // m: how far soa lies inside mesh (the soft layer, epsilon)
  TriangleSoA soa;     // the inner surface (the kernel's), same triangles, same order
  double volume = 0.0; // m^3
  // Principal moments about the centre of mass, ascending, per unit density: m^5
  // (x density in kg/m^3 = kg m^2). The body-frame inertia tensor is their diagonal matrix.
  Eigen::Vector3d inertia_per_density = Eigen::Vector3d::Zero();
  double bounding_radius = 0.0; // max vertex distance of `mesh` from the centre of mass, m
  double inner_radius = 0.0;    // max vertex distance of soa from the centre of mass, m
  double min_edge_length = 0.0; // shortest triangle edge, m
  double max_edge_length = 0.0; // longest triangle edge, m (sets the contact-patch link length)
  double mean_edge_length = 0.0; // mean over the 3 edges of every triangle, m (the mesh's
                                 // resolution against the soft layer: fix tri/particles)
  // The smallest extent of the vertices along the principal axes, m (thinnest_extent below;
  // penetration_depth.h bounds a contact's depth by it).
  double thinnest_extent = 0.0;
  bool convex = false;          // every vertex on or behind every face plane (kConvexityTolerance)
  // The smooth surface the mesh samples, where it is one (smooth_surface.h): 3 lifts per
  // triangle (m, rotation invariant); empty for a body that is its facets.
  std::vector<double> edge_bulge;
  double surface_lift = 0.0; // m, the largest lift (smooth_surface.h max_lift); 0 without
  // Where the surface is a ball (smooth_surface.h corner_spheres): 3 spheres per triangle of
  // `soa`, whose radius plus `layer`'s epsilon is the contact surface's; empty where none is.
  std::vector<SurfaceSphere> corner_spheres;
  double ball_lift = 0.0; // m, how far those spheres rise above soa's facets (max_ball_sag)
  // The principal axes as columns, in the input frame: the rotation from the body (principal)
  // frame to the input frame (orthonormal, determinant +1; MassProperties::principal_axes).
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
  // The centre of mass in the input frame, m: the offset the body frame was moved by.
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();
  // principal_axes as a unit quaternion, w >= 0 (the orientation of `orient file`).
  Eigen::Quaterniond input_orientation = Eigen::Quaterniond::Identity();
};

// Validates the mesh (validate_mesh: throws ShapeError, message prefixed with
// "shape '<name>': "), computes its mass properties and moves it into its principal frame,
// keeping the rotation and offset back to the input frame (principal_axes, centre_of_mass,
// input_orientation).
Shape make_shape(std::string name, TriangleMesh mesh);

// The shape with its kernel surface (soa and the numbers that describe it) offset inward by
// `layer` (m, >= 0) from `mesh`, and its reach. Throws ShapeError ("shape '<name>': ...") when
// the layer does not fit the shape (inner_surface.h).
Shape with_soft_layer(Shape shape, double layer);

// How far from the centre of mass a contact can reach (m): the given surface, or the kernel's
// surface grown by the soft layer `epsilon` where that is farther (a layer outside the mesh:
// `layer outside` of fix tri/particles). LIGGGHTS's radius, so its neighbour lists see every
// contact.
double contact_reach(const Shape &shape, double epsilon);

// Uniformly scales a mesh about the origin (for the `scale` keyword). Throws ShapeError if
// factor <= 0 or is not finite.
TriangleMesh scaled(TriangleMesh mesh, double factor);

// True when every vertex is on or behind every face plane, within tolerance (same units as
// the mesh). Precondition: a valid mesh.
bool is_convex(const TriangleMesh &mesh, double tolerance);

// The smallest extent of a shape's vertices along the axes of its frame, m (for a body-frame
// shape, along its principal axes: a cube's side, a plate's thickness, a ball's diameter).
double thinnest_extent(const TriangleSoA &body_frame);

} // namespace tri
