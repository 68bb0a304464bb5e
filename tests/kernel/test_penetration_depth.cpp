// penetration_depth.h: the depth of a contact through the intersection of the real surfaces,
// against cases whose depth is known by construction (a ball's pole below a plane, two poles
// crossing, a cube face sunk flat), and the force it gives: continuous at the layer boundary,
// monotone in the depth, the gradient of one potential (an undamped bounce returns its speed),
// the same for particle-particle and particle-wall, and the resolvable limit reported.
#include "body/shape.h"
#include "contact/penetration_depth.h"
#include "interaction/body_interaction.h"
#include "interaction/interaction_tally.h"

#include "body_pair_helpers.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using Eigen::Vector3d;

namespace {

constexpr double kRadius = 0.0025; // m
constexpr double kEps = 5e-5;      // m, each body's soft layer
constexpr double kLayer = 2 * kEps;

// A body made of world-frame triangles, owned here.
struct Solid {
  tri::TriangleSoA world;
  tri::Body body;
};

// A mesh scaled by `scale` and moved to `x` (no rotation), as a particle of mass `mass`.
Solid particle(const tri::TriangleMesh &mesh, double scale, const Vector3d &x, double mass) {
  Solid s;
  const tri::TriangleSoA unit = tri::to_soa(mesh);
  tri::transform_soa(unit, scale * Eigen::Matrix3d::Identity(), x, s.world);
  tri::TriangleSoA body_frame;
  tri::transform_soa(unit, scale * Eigen::Matrix3d::Identity(), Vector3d::Zero(), body_frame);
  s.body.epsilon = kEps;
  s.body.longest_edge = 0.0;
  for (int t = 0; t < s.world.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      s.body.longest_edge = std::max(
          s.body.longest_edge, (s.world.vertex(t, k) - s.world.vertex(t, (k + 1) % 3)).norm());
  s.body.min_edge = 0.0;
  s.body.thinnest = tri::thinnest_extent(body_frame);
  s.body.state.x = x;
  s.body.state.mass = mass;
  return s;
}

// The plane z = 0 as a wall patch of two triangles, 2 cm square.
Solid floor_patch() {
  Solid s;
  s.world.resize(2);
  const Vector3d c0(-0.01, -0.01, 0), c1(0.01, -0.01, 0), c2(0.01, 0.01, 0), c3(-0.01, 0.01, 0);
  s.world.set_vertex(0, 0, c0);
  s.world.set_vertex(0, 1, c1);
  s.world.set_vertex(0, 2, c2);
  s.world.set_vertex(1, 0, c0);
  s.world.set_vertex(1, 1, c2);
  s.world.set_vertex(1, 2, c3);
  s.body.epsilon = kEps;
  s.body.longest_edge = std::numeric_limits<double>::infinity();
  s.body.state.mass = 0.0;
  return s;
}

// kn = 1 N/m, no damping, no friction: the normal force in N is the overlap in m.
tri::InteractionSettings spring_only() {
  tri::InteractionSettings s;
  s.coefficients.kn = 1.0;
  s.coefficients.tangential = tri::TangentialModel::no_history;
  s.coefficients.limit_force = true;
  return s;
}

tri::PairForceResult interact(Solid &a, Solid &b) {
  a.body.triangles = &a.world;
  b.body.triangles = &b.world;
  tri::InteractionScratch scratch;
  tri::ContactStats stats;
  return tri_test::body_interaction_alone(a.body, b.body, spring_only(), 1e-6, nullptr, scratch,
                                          stats);
}

// Octasphere (its poles on the z axis) of radius kRadius whose south pole is `depth` below
// z = 0 (negative: above).
Solid ball_at_depth(double depth, double mass = 1e-4) {
  return particle(tri_test::octasphere(3), kRadius, Vector3d(0, 0, kRadius - depth), mass);
}

} // namespace

TEST(DepthBehindSurface, ClosedBodyAndWall) {
  const tri::TriangleSoA cube = tri::to_soa(tri_test::box());
  const tri::SurfaceSide closed;
  EXPECT_NEAR(tri::depth_behind_surface({0.5, 0.4, 0.3}, {0, 0, -1}, cube, closed), 0.3, 1e-15);
  EXPECT_NEAR(tri::depth_behind_surface({0.5, 0.4, 0.3}, {0, 0, 1}, cube, closed), 0.7, 1e-15);
  EXPECT_NEAR(tri::depth_behind_surface({0.2, 0.4, 0.3}, {-1, 0, 0}, cube, closed), 0.2, 1e-15);
  // Through a vertex and along a diagonal edge: one of the triangles there takes the hit.
  EXPECT_NEAR(tri::depth_behind_surface({0.5, 0.5, 0.5}, Vector3d(1, 1, 1).normalized(), cube,
                                        closed),
              std::sqrt(0.75), 1e-12);
  // Outside: the first crossing enters.
  EXPECT_EQ(tri::depth_behind_surface({0.5, 0.5, 1.5}, {0, 0, -1}, cube, closed), 0.0);
  EXPECT_EQ(tri::depth_behind_surface({0.5, 0.5, 1.5}, {0, 0, 1}, cube, closed), 0.0);

  Solid floor = floor_patch();
  tri::SurfaceSide wall;
  wall.wall = true;
  wall.particle_centre = Vector3d(0, 0, 0.003); // the particle is above: the solid below
  EXPECT_NEAR(tri::depth_behind_surface({0.001, 0, -0.0002}, {0, 0, 1}, floor.world, wall),
              0.0002, 1e-18);
  EXPECT_EQ(tri::depth_behind_surface({0.001, 0, 0.0002}, {0, 0, 1}, floor.world, wall), 0.0);
  EXPECT_EQ(tri::depth_behind_surface({0.001, 0, 0.0002}, {0, 0, -1}, floor.world, wall), 0.0);
  wall.particle_centre = Vector3d(0, 0, -0.003); // the same patch, the particle below it
  EXPECT_NEAR(tri::depth_behind_surface({0.001, 0, 0.0002}, {0, 0, -1}, floor.world, wall),
              0.0002, 1e-18);
}

TEST(DepthBehindSurface, ThinnestExtentAndLimit) {
  EXPECT_DOUBLE_EQ(tri::thinnest_extent(tri::to_soa(tri_test::box(3, 1, 2))), 1.0);
  EXPECT_DOUBLE_EQ(tri::deep_contact_limit(0.004, 0.002), 0.25 * 0.002);
  EXPECT_DOUBLE_EQ(tri::deep_contact_limit(0.004, std::numeric_limits<double>::infinity()),
                   0.001);
}

// A ball's pole sunk h below a plane: overlap = layer + h (the analytic depth), pushed straight
// up through the pole, for h from half a layer to 8 layers.
TEST(DeepContact, BallOnPlaneOverlapIsLayerPlusDepth) {
  for (double layers : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    const double h = layers * kLayer;
    Solid ball = ball_at_depth(h), floor = floor_patch();
    const tri::PairForceResult r = interact(ball, floor);
    ASSERT_TRUE(r.intersecting) << layers;
    EXPECT_NEAR(r.force_a.z(), kLayer + h, 1e-12 * kLayer) << layers << " layers";
    // Lateral force and torque: rounding of the reduction's normal (1e-6 of the force).
    EXPECT_NEAR(r.force_a.head<2>().norm(), 0.0, 1e-6 * kLayer) << layers;
    EXPECT_NEAR(r.torque_a.norm(), 0.0, 1e-6 * kLayer * kRadius) << layers;
    EXPECT_NEAR(r.max_overlap, kLayer + h, 1e-12 * kLayer);
    EXPECT_DOUBLE_EQ(r.layer, kLayer);
    EXPECT_DOUBLE_EQ(r.depth_limit, 0.25 * 2 * kRadius);
  }
}

// A cube face sunk flat: every bottom corner is tied; the force acts at the face's centre.
TEST(DeepContact, FlatFaceIsPushedAtItsCentre) {
  const double side = 0.004, h = 3 * kLayer;
  Solid cube = particle(tri_test::box(), side, Vector3d(-0.5 * side, -0.5 * side, -h), 1e-4);
  cube.body.state.x = Vector3d(0, 0, 0.5 * side - h);
  Solid floor = floor_patch();
  const tri::PairForceResult r = interact(cube, floor);
  EXPECT_NEAR(r.force_a.z(), kLayer + h, 1e-12 * kLayer);
  EXPECT_NEAR(r.torque_a.norm(), 0.0, 1e-9 * (kLayer + h) * side);
}

// Overlap against the approach along the normal, from two layers apart to 8 layers deep: never
// decreasing, never steeper than the approach (slope 1 for a pole meeting a plane), so the force
// is continuous where the real surfaces start to intersect. (The grid is offset by a third of a
// step so that no sample puts the pole exactly on the plane: there the touching triangles have
// no direction and their two contact classes cancel, a configuration of measure zero.)
TEST(DeepContact, ContinuousAndMonotoneAcrossTheLayer) {
  const int steps = 400;
  const double dz = 10.0 * kLayer / steps, from = -2.0 * kLayer + dz / 3;
  double previous = -1.0;
  bool crossed = false;
  for (int k = 0; k <= steps; ++k) {
    const double depth = from + k * dz; // of the pole below z = 0
    Solid ball = ball_at_depth(depth), floor = floor_patch();
    const tri::PairForceResult r = interact(ball, floor);
    const double overlap = r.contacts_after > 0 ? r.force_a.z() : 0.0;
    const double expected = std::max(0.0, kLayer + depth);
    EXPECT_NEAR(overlap, expected, 1e-9 * kLayer) << "pole at depth " << depth;
    if (previous >= 0.0) {
      EXPECT_GE(overlap, previous) << depth;
      EXPECT_LE(overlap - previous, dz * (1 + 1e-6)) << depth;
    }
    crossed = crossed || (r.intersecting && depth < dz);
    previous = overlap;
  }
  EXPECT_TRUE(crossed);
}

// Two balls, poles crossing by h along z: particle-particle gives the same overlap as the wall,
// equal and opposite whichever body is a.
TEST(DeepContact, ParticlePairLikeWall) {
  for (double layers : {1.0, 4.0, 8.0}) {
    const double h = layers * kLayer;
    Solid low = particle(tri_test::octasphere(3), kRadius, Vector3d(0, 0, -kRadius), 1e-4);
    Solid high =
        particle(tri_test::octasphere(3), kRadius, Vector3d(0, 0, kRadius - h), 1e-4);
    const tri::PairForceResult up = interact(low, high), down = interact(high, low);
    EXPECT_NEAR(-up.force_a.z(), kLayer + h, 1e-12 * kLayer) << layers; // low pushed down
    EXPECT_NEAR(down.force_a.z(), kLayer + h, 1e-12 * kLayer) << layers;
    EXPECT_NEAR(up.force_a.head<2>().norm(), 0.0, 1e-6 * kLayer);
  }
}

// Undamped, frictionless drop of a ball onto the plane, so fast that a linear spring reaches 4
// layers: it leaves at the speed it came with (the force is the gradient of 1/2 kn overlap^2),
// after reaching v sqrt(m / kn) of overlap.
TEST(DeepContact, UndampedBounceReturnsTheEnergy) {
  const double mass = 1e-4, kn = 1.0; // N/m, the spring_only() settings
  const double peak = 4.0 * kLayer, v0 = peak * std::sqrt(kn / mass);
  const double contact_time = M_PI * std::sqrt(mass / kn), dt = contact_time / 1000;
  const double start = 1.1 * kLayer; // the pole's height above the plane: not yet in contact
  double z = start, v = -v0;
  double deepest = 0.0;
  auto force = [&](double height) {
    Solid ball = ball_at_depth(-height, mass), floor = floor_patch();
    const tri::PairForceResult r = interact(ball, floor);
    deepest = std::max(deepest, r.max_overlap);
    return r.force_a.z(); // N
  };
  double f = force(z);
  for (int step = 0; step < 20000 && !(v > 0 && z > start); ++step) {
    v += 0.5 * dt * f / mass;
    z += dt * v;
    f = force(z);
    v += 0.5 * dt * f / mass;
  }
  EXPECT_NEAR(v / v0, 1.0, 1e-4);
  EXPECT_NEAR(deepest / peak, 1.0, 1e-3);
}

// What compute tri/stats and the host's limit check read.
TEST(DeepContact, TallyAndLimit) {
  const double limit = 0.25 * 2 * kRadius;
  Solid ball = ball_at_depth(1.1 * limit), floor = floor_patch();
  const tri::PairForceResult deep = interact(ball, floor);
  EXPECT_NEAR(deep.depth_of_limit(), 1.1, 1e-9);
  Solid shallow_ball = ball_at_depth(2 * kLayer), floor2 = floor_patch();
  const tri::PairForceResult shallow = interact(shallow_ball, floor2);
  EXPECT_NEAR(shallow.depth_of_limit(), 2 * kLayer / limit, 1e-9);
  Solid apart = ball_at_depth(-0.5 * kLayer), floor3 = floor_patch();
  const tri::PairForceResult soft = interact(apart, floor3);
  EXPECT_EQ(soft.depth_of_limit(), 0.0);

  tri::InteractionTally t;
  t.add(soft);
  EXPECT_EQ(t.deep_contacts, 0);
  EXPECT_NEAR(t.max_overlap_layers, 0.5, 1e-9);
  t.add(shallow);
  t.add(deep);
  EXPECT_EQ(t.deep_contacts, 2);
  EXPECT_NEAR(t.max_overlap_layers, (kLayer + 1.1 * limit) / kLayer, 1e-9);
  EXPECT_NEAR(t.max_depth_of_limit, 1.1, 1e-9);
  for (const char *name : {"deep_contacts", "max_overlap_layers", "max_depth_of_limit"})
    EXPECT_GT(tri::stats_column_index(name), 0) << name;
}

// A cube's corner pressed h into the top face of a slab (two particles), the line of centres
// tilted: pushed along the face's normal by layer + h, not along the line of centres.
TEST(DeepContact, CornerIntoFaceIsPushedAlongTheFaceNormal) {
  const double side = 0.002, h = 3 * kLayer;
  // The slab: [-5, 5] mm x [-5, 5] mm x [-4, 0] mm.
  Solid slab = particle(tri_test::transformed(tri_test::box(0.01, 0.01, 0.004),
                                        Eigen::Matrix3d::Identity(), Vector3d(-0.005, -0.005, -0.004)),
                  1.0, Vector3d::Zero(), 1e-3);
  slab.body.state.x = Vector3d(0, 0, -0.002);
  // The corner at the origin of box() turned to point straight down (its diagonal along +z).
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Vector3d(1, 1, 1), Vector3d(0, 0, 1)).toRotationMatrix();
  const Vector3d corner(0.002, 0.001, -h);
  Solid cube = particle(tri_test::transformed(tri_test::box(side, side, side), turn, corner), 1.0,
                        Vector3d::Zero(), 1e-4);
  cube.body.state.x = corner + turn * Vector3d::Constant(0.5 * side);
  const tri::PairForceResult r = interact(cube, slab);
  EXPECT_NEAR(r.force_a.z(), kLayer + h, 1e-9 * kLayer);
  EXPECT_NEAR(r.force_a.head<2>().norm(), 0.0, 1e-9 * kLayer);
  // Through the corner: the torque about the cube's centre is the lever to the corner x force.
  const Vector3d expected = (corner - cube.body.state.x).cross(r.force_a);
  EXPECT_NEAR((r.torque_a - expected).norm(), 0.0, 1e-6 * r.force_a.norm() * side);
}

// contact_reduction.h step 5c, with this file's harness: a finely meshed ball pressed on a
// plane or on another ball, 0.5 layer (2 % of its radius: the cap reaches facets tilted past
// 10 degrees). Its deepest vertex sits off the centre line by up to a facet, and the deepest
// pair's force there had that lever (measured: 18-91 um at level 4, 18-42 um at level 5) and,
// ball on ball, a facet's normal (0.012-0.021 rad off the line of centres); the moments' peak
// acts within 5 % of a facet of the centre line (0.6-7 um) and along the line of centres
// within 5 % of the facet angle (0.15-2 mrad).
namespace {

// The mesh turned by a rotation drawn from `seed`.
tri::TriangleMesh turned(tri::TriangleMesh m, unsigned seed) {
  std::srand(seed);
  const Eigen::Quaterniond r(Eigen::Vector4d::Random().normalized());
  for (auto &v : m.vertices)
    v = r * v;
  return m;
}

} // namespace

TEST(CurvedContact, FineBallOnPlanePushesThroughItsCentre) {
  for (int level : {4, 5}) {
    const double edge = kRadius * (level == 4 ? 0.076 : 0.038);
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
      const tri::TriangleMesh mesh = turned(tri_test::icosphere(level), seed);
      // The sphere through the vertices hangs 0.5 layer into the plane's layer.
      Solid ball = particle(mesh, kRadius, Vector3d(0, 0, kRadius + 0.5 * kLayer), 1e-4);
      Solid floor = floor_patch();
      const tri::PairForceResult r = interact(ball, floor);
      ASSERT_GT(r.force_a.norm(), 0.0);
      const double lever = r.torque_a.norm() / r.force_a.norm();
      EXPECT_LT(lever, 0.05 * edge) << level << " " << seed;
      EXPECT_LT(r.force_a.head<2>().norm(), 1e-9 * r.force_a.norm());
    }
  }
}

TEST(CurvedContact, FineBallsPushAlongTheirLineOfCentres) {
  const Vector3d axis = Vector3d(0.3, -0.5, 0.8).normalized();
  for (int level : {4, 5}) {
    const double facet_angle = level == 4 ? 0.076 : 0.038;
    for (unsigned seed : {1u, 2u, 3u}) {
      Solid a = particle(turned(tri_test::icosphere(level), seed), kRadius, Vector3d::Zero(),
                         1e-4);
      Solid b = particle(turned(tri_test::icosphere(level), seed + 10), kRadius,
                         (2 * kRadius + 0.5 * kLayer) * axis, 1e-4);
      const tri::PairForceResult r = interact(a, b);
      ASSERT_GT(r.force_a.norm(), 0.0);
      const double angle = std::acos(std::min(1.0, -r.force_a.normalized().dot(axis)));
      EXPECT_LT(angle, 0.05 * facet_angle) << level << " " << seed;
    }
  }
}
