// Mass properties against closed forms: cube, box (translated and rotated), tetrahedron,
// icosphere against the sphere (with the second-order discretisation error).
#include "body/mass_properties.h"
#include "test_meshes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>

namespace {

constexpr double kPi = 3.14159265358979323846;

using tri_test::box;
using tri_test::icosphere;
using tri_test::transformed;

Eigen::Matrix3d some_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

void expect_right_handed_rotation(const Eigen::Matrix3d &axes) {
  EXPECT_NEAR((axes.transpose() * axes - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
}

TEST(MassProperties, UnitCube) {
  const tri::MassProperties mp = tri::mass_properties(box(1, 1, 1));
  EXPECT_NEAR(mp.volume, 1.0, 1e-14);
  EXPECT_NEAR((mp.centre_of_mass - Eigen::Vector3d(0.5, 0.5, 0.5)).norm(), 0.0, 1e-14);
  // Cube of side s, unit density: I = s^5 / 6 about every axis through the centre.
  EXPECT_NEAR((mp.inertia_per_density - Eigen::Matrix3d::Identity() / 6.0).norm(), 0.0, 1e-14);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(mp.principal_moments[i], 1.0 / 6.0, 1e-14);
  // Three equal moments: the mesh's own axes are kept, not rounding noise.
  EXPECT_TRUE(mp.principal_axes.isApprox(Eigen::Matrix3d::Identity(), 1e-14));
}

TEST(MassProperties, BoxTranslatedAndRotated) {
  const double a = 3.0, b = 1.0, c = 2.0; // long axis x, short axis y
  const Eigen::Matrix3d r = some_rotation();
  const Eigen::Vector3d shift(10.0, -20.0, 30.0);
  const tri::TriangleMesh m =
      transformed(box(a, b, c), r, shift - r * Eigen::Vector3d(a / 2, b / 2, c / 2));
  const tri::MassProperties mp = tri::mass_properties(m);

  const double volume = a * b * c;
  EXPECT_NEAR(mp.volume, volume, 1e-12);
  EXPECT_NEAR((mp.centre_of_mass - shift).norm(), 0.0, 1e-12);
  // Box about its centre: Ixx = V (b^2 + c^2) / 12, etc.
  const Eigen::Vector3d body(volume * (b * b + c * c) / 12, volume * (a * a + c * c) / 12,
                             volume * (a * a + b * b) / 12);
  const Eigen::Matrix3d expected = r * body.asDiagonal() * r.transpose();
  EXPECT_NEAR((mp.inertia_per_density - expected).norm(), 0.0, 1e-11);
  // Ascending: smallest moment about the long axis (x), then z (c = 2), then y (b = 1).
  EXPECT_NEAR(mp.principal_moments[0], body[0], 1e-11);
  EXPECT_NEAR(mp.principal_moments[1], body[2], 1e-11);
  EXPECT_NEAR(mp.principal_moments[2], body[1], 1e-11);
  // Principal axes recovered: the rotated x, z, y axes, up to sign.
  EXPECT_NEAR(std::abs(mp.principal_axes.col(0).dot(r.col(0))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(mp.principal_axes.col(1).dot(r.col(2))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(mp.principal_axes.col(2).dot(r.col(1))), 1.0, 1e-12);
  expect_right_handed_rotation(mp.principal_axes);
  // The axes diagonalise the tensor.
  const Eigen::Matrix3d diagonal =
      mp.principal_axes.transpose() * mp.inertia_per_density * mp.principal_axes;
  EXPECT_NEAR((diagonal - Eigen::Matrix3d(mp.principal_moments.asDiagonal())).norm(), 0.0, 1e-11);
}

TEST(MassProperties, SignConventionIsDeterministic) {
  // The same box rotated by 180 degrees about an axis has the same tensor, so the same axes.
  const Eigen::Matrix3d flip = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const tri::TriangleMesh m = transformed(box(3, 1, 2), some_rotation(), Eigen::Vector3d::Zero());
  const tri::MassProperties p = tri::mass_properties(m);
  const tri::MassProperties q = tri::mass_properties(transformed(
      m, some_rotation() * flip * some_rotation().transpose(), Eigen::Vector3d::Zero()));
  EXPECT_NEAR((p.principal_axes - q.principal_axes).norm(), 0.0, 1e-10);
  // The largest component of axes 0 and 1 is positive.
  for (int k = 0; k < 2; ++k) {
    Eigen::Index i;
    p.principal_axes.col(k).cwiseAbs().maxCoeff(&i);
    EXPECT_GT(p.principal_axes(i, k), 0.0);
  }
}

TEST(MassProperties, RepeatedMomentsKeepTheMeshAxes) {
  // Long square prism along z: smallest moment about z, equal moments about x and y. The
  // pair's basis is the mesh's x and y (not rounding noise), completed right-handed.
  const tri::MassProperties prism = tri::mass_properties(box(1, 1, 3));
  Eigen::Matrix3d expected;
  expected.col(0) = Eigen::Vector3d::UnitZ();
  expected.col(1) = Eigen::Vector3d::UnitX();
  expected.col(2) = Eigen::Vector3d::UnitY();
  EXPECT_TRUE(prism.principal_axes.isApprox(expected, 1e-12)) << prism.principal_axes;
  // Flat square plate: largest moment about z, the equal pair first.
  const tri::MassProperties plate = tri::mass_properties(box(2, 2, 1));
  EXPECT_TRUE(plate.principal_axes.isApprox(Eigen::Matrix3d::Identity(), 1e-12))
      << plate.principal_axes;
  expect_right_handed_rotation(prism.principal_axes);
}

// A shape with three equal moments, turned in its file by an arbitrary rotation and written
// with float32 coordinates (a binary STL): its moments agree to about 1e-7, not to rounding, and
// must still count as equal, so that `orient none` keeps the file's axes (the shape stands as
// in the file) instead of the eigen-solver's arbitrary ones.
TEST(MassProperties, TurnedIsotropicShapesInFloatKeepTheFileAxes) {
  auto as_float = [](tri::TriangleMesh m) {
    for (Eigen::Vector3d &v : m.vertices)
      v = v.cast<float>().cast<double>();
    return m;
  };
  const Eigen::Vector3d shift(0.3, -0.2, 0.1);
  for (const tri::TriangleMesh &shape : {box(1, 1, 1), tri_test::icosphere(0),
                                         tri_test::icosphere(2)}) {
    const tri::MassProperties mp =
        tri::mass_properties(as_float(transformed(shape, some_rotation(), shift)));
    EXPECT_TRUE(mp.principal_axes.isApprox(Eigen::Matrix3d::Identity(), 1e-15))
        << mp.principal_axes;
    EXPECT_EQ(mp.principal_moments[0], mp.principal_moments[2]);
    // The mean moment is the shape's, to the file's precision.
    const double exact = tri::mass_properties(shape).principal_moments[0];
    EXPECT_NEAR(mp.principal_moments[1], exact, 1e-6 * exact);
  }
  // A prism 1e-3 longer than wide is not a cube: its axes are the rotated ones.
  const tri::MassProperties prism =
      tri::mass_properties(as_float(transformed(box(1, 1, 1.001), some_rotation(), shift)));
  EXPECT_NEAR(std::abs(prism.principal_axes.col(0).dot(some_rotation().col(2))), 1.0, 1e-9);
}

TEST(MassProperties, Tetrahedron) {
  const tri::MassProperties mp = tri::mass_properties(tri_test::tetrahedron());
  EXPECT_NEAR(mp.volume, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR((mp.centre_of_mass - Eigen::Vector3d::Constant(0.25)).norm(), 0.0, 1e-15);
  // Unit right tetrahedron: int x^2 dV = 1/60, int xy dV = 1/120. About the centroid:
  // Cxx = 1/60 - V/16 = 1/160, Cxy = 1/120 - V/16 = -1/480; I = tr(C) 1 - C.
  Eigen::Matrix3d expected;
  expected << 1.0 / 80, 1.0 / 480, 1.0 / 480, 1.0 / 480, 1.0 / 80, 1.0 / 480, 1.0 / 480, 1.0 / 480,
      1.0 / 80;
  EXPECT_NEAR((mp.inertia_per_density - expected).norm(), 0.0, 1e-15);
  // Eigenvalues: 1/80 - 1/480 (twice), 1/80 + 2/480 (along (1,1,1)).
  EXPECT_NEAR(mp.principal_moments[0], 1.0 / 80 - 1.0 / 480, 1e-15);
  EXPECT_NEAR(mp.principal_moments[1], 1.0 / 80 - 1.0 / 480, 1e-15);
  EXPECT_NEAR(mp.principal_moments[2], 1.0 / 80 + 2.0 / 480, 1e-15);
  EXPECT_NEAR(std::abs(mp.principal_axes.col(2).dot(Eigen::Vector3d::Ones().normalized())), 1.0,
              1e-12);
  expect_right_handed_rotation(mp.principal_axes);
}

TEST(MassProperties, IcosphereConvergesToSphereAtSecondOrder) {
  // An inscribed polyhedron misses a layer of thickness ~ h^2 / (8 r) under each face, so
  // the relative error of volume and moments falls by about 4 per level.
  const double radius = 0.002;
  const Eigen::Vector3d centre(0.1, 0.2, -0.3);
  double volume_error[2], moment_error[2];
  for (int level : {3, 4}) {
    const tri::MassProperties mp = tri::mass_properties(
        transformed(icosphere(level), radius * Eigen::Matrix3d::Identity(), centre));
    const double volume = 4.0 / 3.0 * kPi * std::pow(radius, 3);
    const double moment = 0.4 * volume * radius * radius; // 2/5 m r^2, unit density
    EXPECT_NEAR((mp.centre_of_mass - centre).norm(), 0.0, 1e-15);
    const double ve = (volume - mp.volume) / volume,
                 me = (moment - mp.principal_moments[0]) / moment;
    EXPECT_GT(ve, 0.0); // inscribed: always smaller
    EXPECT_GT(me, 0.0);
    // Nearly isotropic: the moments spread much less than the discretisation error.
    EXPECT_LT((mp.principal_moments[2] - mp.principal_moments[0]) / moment, 0.05 * me);
    volume_error[level - 3] = ve;
    moment_error[level - 3] = me;
  }
  EXPECT_LT(volume_error[0], 0.01);   // level 3, 1280 triangles: 0.86 %
  EXPECT_LT(volume_error[1], 0.0025); // level 4, 5120 triangles: 0.22 %
  EXPECT_NEAR(volume_error[0] / volume_error[1], 4.0, 0.2);
  EXPECT_NEAR(moment_error[0] / moment_error[1], 4.0, 0.2);
}

TEST(MassProperties, FarFromOriginLosesNoDigits) {
  const tri::MassProperties near = tri::mass_properties(box(0.003, 0.002, 0.001));
  const tri::MassProperties far = tri::mass_properties(transformed(
      box(0.003, 0.002, 0.001), Eigen::Matrix3d::Identity(), Eigen::Vector3d(1e3, 0, 0)));
  EXPECT_NEAR(far.volume / near.volume, 1.0, 1e-9);
  EXPECT_NEAR((far.inertia_per_density - near.inertia_per_density).norm() /
                  near.inertia_per_density.norm(),
              0.0, 1e-6);
}

} // namespace
