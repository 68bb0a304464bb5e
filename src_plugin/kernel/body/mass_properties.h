// Mass properties of the solid bounded by a closed, outward-oriented triangle mesh, per unit
// density, by the divergence theorem: the solid is the signed sum of the tetrahedra
// (reference point, a, b, c) over the triangles (a, b, c), and each tetrahedron's volume,
// first and second moments have closed forms. Exact for the polyhedron (up to rounding).
//
// Units: with vertices in metres, volume is m^3, centre of mass m, inertia m^5 (multiply by
// a density in kg/m^3 to get kg m^2).
// Precondition: a valid mesh (validate_mesh). An open or inverted mesh gives meaningless
// (e.g. negative) values rather than an error.
#pragma once

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>

namespace tri {

struct MassProperties {
  double volume = 0.0;                                      // m^3
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero(); // m, in the mesh's frame
  // Inertia tensor about the centre of mass in the mesh's axes, per unit density (m^5):
  // I = integral (|r|^2 1 - r r^T) dV, r measured from the centre of mass.
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero();
  // Its eigenvalues, ascending (m^5).
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();
  // Its eigenvectors as columns, in the order of principal_moments: a rotation (orthonormal,
  // determinant +1). body = principal_axes^T (x - centre_of_mass) puts a point in the
  // principal frame. See principal_frame() for the sign and degeneracy convention.
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
};

MassProperties mass_properties(const TriangleMesh &mesh);

// Eigen-decomposition of a symmetric inertia tensor with a deterministic convention:
//  - moments ascending;
//  - moments that agree within kDegenerateMomentTolerance x the largest are one repeated
//    eigenvalue, reported as their mean; its eigenspace has no preferred basis, so the basis is
//    taken as close to the mesh's own axes as possible (a cube, a regular polyhedron or an
//    icosphere keeps its file's axes, turned however it is in the file; a square prism keeps
//    its two side axes) instead of whatever rounding noise picks. The tolerance, 1e-5, lies
//    above what a mesh file's coordinates carry (an STL's float32 ones, 6e-8, or six printed
//    digits, put a turned cube's moments up to about 3e-6 apart) and far below a shape meant to
//    differ; averaging changes the inertia by at most that share;
//  - each axis points so that its component of largest magnitude is positive (ties: the
//    lowest coordinate index), except the third, which is axis0 x axis1 (right-handed).
constexpr double kDegenerateMomentTolerance = 1e-5;
void principal_frame(const Eigen::Matrix3d &inertia, Eigen::Vector3d &moments,
                     Eigen::Matrix3d &axes);

} // namespace tri
