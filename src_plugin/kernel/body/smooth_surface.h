// The smooth surface a finely meshed curved body samples: a mesh's vertices lie on it, its facets
// are chords below it. contact/smooth_peak.h measures a ball's contact on that surface, not on
// the facets; the reduction (contact_reduction.h, step 5b) takes it from there.
//
// Why. A 20480-triangle icosphere of radius R has facets 0.57 um (R 3e-4) below its vertex
// sphere. Measured on the facets, its overlap with a plane is short of the sphere's by 0 to that
// sag, depending on where the lowest point falls on the lowest facet, and the deepest point is a
// vertex up to a facet's width off the centre line. That is a different spring (stiffness and
// contact time off by about 1 %) and a lever that turns with the ball: oblique impacts missed a
// sphere's rebound spin by up to 8 % (validation/contact/oblique), and refining the mesh
// shrinks the error only as the sag does. On the smooth surface the overlap is the sphere's to
// O(h^4 / R^3) (h the edge length) at any orientation, and its deepest point lies on the line
// of centres.
//
// The surface. Each vertex gets a normal n_v: its facets' normals weighted by their angles at
// the vertex. Over a facet with corners p_0, p_1, p_2 the surface rises above the chord plane,
// along the facet's normal, by
//   h(b) = sum over the edges (i, j) of b_i b_j k_ij,   k_ij = (p_i - p_j) . (n_i - n_j) / 2,
// b the barycentric coordinates: the lift of Phong tessellation at shape factor 1/2. On a
// sphere (n_v radial) k_ij = |p_i - p_j|^2 / (2 R) and h is exactly the sphere's height above
// the chord to second order, (r_c^2 - |x - x_c|^2) / (2 R) with x_c, r_c the facet's
// circumcentre and circumradius. k_ij is a property of the edge alone, so the lift is
// continuous across edges; it is rotation invariant (a scalar per edge, stored in the body's
// shape, never transformed); a cylinder's edges along its axis get 0.
//
// Where a mesh is not a smooth surface -- a cube's edges and corners, a rock's facets, a gear's
// teeth -- it is its facets. A vertex is smooth when every facet normal around it is within
// kSmoothVertexAngle of its normal (a 1280-triangle icosphere: 0.087 rad, 5120: 0.044, 20480:
// 0.022), not at all from twice that on (a random rock of 40 facets, a cube: 0.5 to 0.96 rad),
// smoothly between; an edge's k is scaled by both ends' smoothness. Flat regions get k = 0 by
// the formula (equal normals). A mesh with no smooth edge stores nothing, and every contact
// with it is computed exactly as on the facets.
#pragma once

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <vector>

namespace tri {

constexpr double kSmoothVertexAngle = 0.15; // rad: facets within it of a vertex normal: smooth
// A vertex's ball (corner_spheres): its facets within kBallVertexAngle of its normal (rad; none
// from kSmoothVertexAngle on: a 320-triangle icosphere, 0.19 rad, whose sphere through the
// vertices has 3.5 % more volume than its mesh, is its facets; a 1280-triangle one, 0.095 rad
// and 0.9 %, a ball), the surface turning by at least kBallMinBend over an edge (rad; fully from twice it:
// a plane is not a ball), and its ring within kBallMisfit of its sag of the sphere (fully
// within half of it: a cylinder or a flat ellipsoid is not a ball).
constexpr double kBallVertexAngle = 0.11;
constexpr double kBallMinBend = 2e-3;
constexpr double kBallMisfit = 0.05;

// Three lifts per triangle, for its edges (v0, v1), (v1, v2), (v2, v0) (m); empty when every
// edge's is 0 (no smooth surface: the facets are the body). Precondition: a valid closed mesh.
std::vector<double> edge_bulges(const TriangleMesh &mesh);

// Where a smooth surface is a ball: the sphere through a vertex and its neighbours (body frame,
// as the mesh) and how far it describes the surface there (weight 1: the vertex's smoothness,
// 0 where the facets are the body, where the surface is flat, concave or not round). Between
// two such surfaces a contact is that of their spheres (contact/ball_contact.h): two finely
// meshed balls meet as balls, at the sphere overlap R_a + R_b - |c_a - c_b| on the line of
// centres, which the facets (each ball short of its sphere by up to its sag, the deepest point
// a vertex off that line) and the lifts measured along facet pairs' bisectors both miss; the
// sphere's overlap is a potential, so an undamped collision keeps its energy.
struct SurfaceSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // m, body frame
  double radius = 0.0;                              // m
  double weight = 0.0;                              // [0, 1]
};

// Each triangle's three corners' spheres (3 per triangle, in the triangles' corner order); empty
// where no vertex is a ball. Precondition: a valid closed mesh.
std::vector<SurfaceSphere> corner_spheres(const TriangleMesh &mesh);

// How far the corners' spheres rise above their facets' planes at most (m, >= 0): the contact
// search between two balls reaches that much further (Body::ball_lift).
double max_ball_sag(const TriangleMesh &mesh, const std::vector<SurfaceSphere> &corners);

// The largest lift of any facet (m, >= 0): how far the smooth surface rises above the facets.
// The contact search reaches that much further for such a body (body_interaction.h: Body::lift),
// so that a contact starts when the smooth surface, not the first vertex, meets the layer.
double max_lift(const std::vector<double> &bulges);

} // namespace tri
