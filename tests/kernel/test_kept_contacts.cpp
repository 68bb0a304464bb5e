// Kept contact points (interaction/kept_contacts.h): carried exactly where the motion is rigid
// for the pair (a translation along the normal, a motion of both bodies together), not kept
// where they cannot be, and over many steps of two rocks resting, sliding, rolling and meeting,
// within the stated bound of a measurement at every step, on average far inside it, while most
// steps carry them.
#include "body_pair_helpers.h"
#include "interaction/body_interaction.h"
#include "interaction/kept_contacts.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace tri;
using namespace tri_test;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

// A point-like contact.
ContactPoint edge_point() {
  ContactPoint c;
  c.point = Vector3d(0.001, 0.002, 0.0005);
  c.normal = Vector3d(0.2, -0.1, 1.0).normalized();
  c.damping_point = c.point + Vector3d(1e-4, -2e-4, 0.0);
  c.overlap = 3e-5;
  c.energy_overlap = 2.5e-5;
  c.min_distance = 1.7e-4;
  c.num_merged = 12;
  c.tri_a = 17;
  c.tri_b = 4;
  c.kind = ContactKind::edge;
  return c;
}

RigidPose pose(const Vector3d &x, const Quaterniond &q) {
  RigidPose p;
  p.x = x;
  p.q = q;
  p.radius = 0.002;
  return p;
}

std::vector<double> kept_record() { return std::vector<double>(kKeptContactDoubles, 0.0); }

// Rounding of lengths: the points are kept in a's frame, coordinates up to a few cm.
constexpr double kLength = 1e-16; // m


} // namespace

// At the poses they were kept at, the points come back as they were (to rounding: they are kept
// in a's frame), labels and patch included, and the motion is zero (to rounding).
TEST(KeptContacts, CarriedAtTheSamePosesAreTheKeptPoints) {
  const RigidPose a = pose(Vector3d(0.01, 0.02, 0.03), Quaterniond(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized())));
  const RigidPose b = pose(Vector3d(0.01, 0.02, 0.034), Quaterniond(Eigen::AngleAxisd(-0.4, Vector3d(0, 1, 1).normalized())));
  std::vector<double> kept = kept_record();
  const ContactPoint c = edge_point();
  keep_contacts(a, b, {c}, kept.data());
  ASSERT_TRUE(contacts_kept(kept.data()));
  EXPECT_LT(kept_contacts_motion(kept.data(), a, b), kLength);
  std::vector<ContactPoint> out;
  carry_kept_contacts(kept.data(), a, b, out);
  ASSERT_EQ(out.size(), 1u);
  const ContactPoint &o = out[0];
  EXPECT_LT((o.point - c.point).norm(), kLength);
  EXPECT_EQ(o.damping_point, o.point); // without a patch, the dashpot acts at the point
  EXPECT_LT((o.normal - c.normal).norm(), 1e-15);
  EXPECT_NEAR(o.overlap, c.overlap, kLength);
  EXPECT_NEAR(o.energy_overlap, c.energy_overlap, kLength);
  EXPECT_NEAR(o.min_distance, c.min_distance, kLength);
  EXPECT_EQ(o.num_merged, 12);
  EXPECT_EQ(o.tri_a, 17);
  EXPECT_EQ(o.tri_b, 4);
  EXPECT_EQ(o.kind, ContactKind::edge);
  EXPECT_EQ(o.patch_area, 0.0);

  ContactPoint face = c; // a tilted face's corner: its patch comes back, turned with the bodies
  face.kind = ContactKind::face;
  face.patch_area = 3e-6;
  face.patch_mean_radius = 8e-4;
  face.face_weight = 0.7;
  face.patch_second_moment << 2e-12, 1e-13, -3e-13, 1e-13, 1e-12, 4e-13, -3e-13, 4e-13, 5e-14;
  keep_contacts(a, b, {face}, kept.data());
  carry_kept_contacts(kept.data(), a, b, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_LT((out[0].damping_point - face.damping_point).norm(), kLength);
  EXPECT_EQ(out[0].patch_area, face.patch_area);
  EXPECT_EQ(out[0].patch_mean_radius, face.patch_mean_radius);
  EXPECT_EQ(out[0].face_weight, face.face_weight);
  EXPECT_LT((out[0].patch_second_moment - face.patch_second_moment).norm(), 1e-27);
  EXPECT_EQ(out[0].kind, ContactKind::face);
}

// b moved by s along the normal: the overlap falls by s, min_distance rises by s, the point
// moves s / 2, and the motion is s. Both bodies moved and turned together: nothing changes
// (the motion is relative).
TEST(KeptContacts, RelativeTranslationAlongTheNormalAndCommonMotion) {
  const RigidPose a = pose(Vector3d(0.0, 0.0, 0.0), Quaterniond(Eigen::AngleAxisd(0.3, Vector3d::UnitX())));
  const RigidPose b = pose(Vector3d(0.0, 0.0, 0.004), Quaterniond::Identity());
  std::vector<double> kept = kept_record();
  const ContactPoint c = edge_point();
  keep_contacts(a, b, {c}, kept.data());
  const double s = 1e-8;
  RigidPose b_away = b;
  b_away.x += s * c.normal;
  EXPECT_NEAR(kept_contacts_motion(kept.data(), a, b_away), s, kLength);
  std::vector<ContactPoint> out;
  carry_kept_contacts(kept.data(), a, b_away, out);
  EXPECT_NEAR(out[0].overlap, c.overlap - s, kLength);
  EXPECT_NEAR(out[0].energy_overlap, c.energy_overlap - s, kLength);
  EXPECT_NEAR(out[0].min_distance, c.min_distance + s, kLength);
  EXPECT_LT((out[0].point - (c.point + 0.5 * s * c.normal)).norm(), kLength);

  const Eigen::Isometry3d common = Eigen::Translation3d(0.003, -0.001, 0.002) *
                                   Eigen::AngleAxisd(0.9, Vector3d(1, -1, 2).normalized());
  RigidPose a2 = a, b2 = b;
  a2.x = common * a.x;
  b2.x = common * b.x;
  a2.q = Quaterniond(common.rotation()) * Quaterniond(a.q);
  b2.q = Quaterniond(common.rotation()) * Quaterniond(b.q);
  EXPECT_LT(kept_contacts_motion(kept.data(), a2, b2), kLength);
  carry_kept_contacts(kept.data(), a2, b2, out);
  EXPECT_NEAR(out[0].overlap, c.overlap, kLength);
  EXPECT_LT((out[0].point - common * c.point).norm(), kLength);
  EXPECT_LT((out[0].normal - common.rotation() * c.normal).norm(), 1e-14);

  // A turn of b by theta about its centre counts 2 sin(theta / 2) r.
  RigidPose b_turned = b;
  const double theta = 1e-6;
  b_turned.q = Quaterniond(Eigen::AngleAxisd(theta, Vector3d::UnitY()));
  EXPECT_NEAR(kept_contacts_motion(kept.data(), a, b_turned), 2 * std::sin(theta / 2) * b.radius,
              kLength);
}

// More points than are kept, a contact through the intersection, or one whose point does not go
// with the material: the record is cleared, and so is an old one; no record: the motion is
// unbounded. A face contact whose point does is kept.
TEST(KeptContacts, WhatIsNotKept) {
  const RigidPose a = pose(Vector3d::Zero(), Quaterniond::Identity());
  const RigidPose b = pose(Vector3d(0, 0, 0.004), Quaterniond::Identity());
  std::vector<double> kept = kept_record();
  EXPECT_EQ(kept_contacts_motion(kept.data(), a, b), std::numeric_limits<double>::infinity());
  const ContactPoint c = edge_point();
  keep_contacts(a, b, {c, c}, kept.data());
  EXPECT_TRUE(contacts_kept(kept.data()));
  keep_contacts(a, b, std::vector<ContactPoint>(kKeptContactPoints + 1, c), kept.data());
  EXPECT_FALSE(contacts_kept(kept.data()));
  ContactPoint deep = c;
  deep.intersecting = true;
  keep_contacts(a, b, {c}, kept.data());
  keep_contacts(a, b, {deep}, kept.data());
  EXPECT_FALSE(contacts_kept(kept.data()));
  keep_contacts(a, b, {}, kept.data());
  EXPECT_FALSE(contacts_kept(kept.data()));
  ContactPoint face = c; // a face lying flat: its point follows micro-tilts the carry cannot
  face.kind = ContactKind::face;
  face.patch_area = 2e-6;
  face.point_is_material = false;
  keep_contacts(a, b, {c}, kept.data());
  keep_contacts(a, b, {c, face}, kept.data());
  EXPECT_FALSE(contacts_kept(kept.data()));
  ContactPoint edge = c; // an edge lying flat: its point slides along it
  edge.point_is_material = false;
  keep_contacts(a, b, {c}, kept.data());
  keep_contacts(a, b, {edge}, kept.data());
  EXPECT_FALSE(contacts_kept(kept.data()));
  face.point_is_material = true; // a tilted face pushing at its one deepest corner
  keep_contacts(a, b, {face}, kept.data());
  EXPECT_TRUE(contacts_kept(kept.data()));
}

// A wall patch's points name its triangle by id: carried to a patch that lists the triangles
// differently, the point names the same triangle; a patch without it does not hold them. The
// wall (radius 0, the world's frame) bounds the motion by the particle's own.
TEST(KeptContacts, WallTrianglesByIdAndTheParticlesMotion) {
  const RigidPose particle = pose(Vector3d(0.001, 0.0, 0.002), Quaterniond::Identity());
  RigidPose wall; // Body's default for a wall: the world's frame, radius 0
  std::vector<double> kept = kept_record();
  ContactPoint c = edge_point();
  c.tri_b = 1;
  const int then_ids[3] = {10, 20, 30};
  keep_contacts(particle, wall, {c}, kept.data(), then_ids);
  const int now_ids[2] = {5, 20}, gone[2] = {5, 30};
  EXPECT_TRUE(kept_triangles_present(kept.data(), now_ids, 2));
  EXPECT_FALSE(kept_triangles_present(kept.data(), gone, 2));
  std::vector<ContactPoint> out;
  carry_kept_contacts(kept.data(), particle, wall, out, now_ids, 2);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].tri_b, 1); // id 20 is second now too
  const int reordered[3] = {20, 5, 7};
  carry_kept_contacts(kept.data(), particle, wall, out, reordered, 3);
  EXPECT_EQ(out[0].tri_b, 0);
  RigidPose moved = particle;
  moved.x.x() += 3e-9;
  EXPECT_NEAR(kept_contacts_motion(kept.data(), moved, wall), 3e-9, kLength);
  moved.q = Quaterniond(Eigen::AngleAxisd(1e-6, Vector3d::UnitZ()));
  EXPECT_NEAR(kept_contacts_motion(kept.data(), moved, wall),
              3e-9 + 2 * std::sin(0.5e-6) * particle.radius, kLength);
}

namespace {

// Two rocks on a path of small steps, evaluated with kept contact points and measured afresh
// at every step: the largest overlaps agree within twice the motion allowed plus the kernel's
// tolerance twice, and so do the contact counts but where a contact begins or ends within
// that margin. Returns the share of steps in contact that were carried.
using Path = std::function<void(int step, double &d, double &sweep, double &angle_a,
                                double &angle_b)>;

double carried_share(int pair, const Path &path, int steps, const std::string &what) {
  const double eps = 1e-4, dt = 1e-5, layer = 2 * eps;
  RockPairPath rocks(rock(pair % 2 ? 40 : 20, 31 + pair), rock(40, 41 + pair), 900 + pair);
  TriangleSoA wa, wb;
  InteractionScratch scratch_ref, scratch_got;
  double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {};
  std::vector<double> kept = kept_record();
  InteractionSettings measured = settings(true);
  measured.kept_tolerance = 0.0;
  const InteractionSettings carrying = settings(true);
  const double margin = 2 * carrying.kept_tolerance * layer +
                        2 * certified_tolerance(carrying.distance, eps, eps) + 1e-12 * layer;
  long long in_contact = 0, carried = 0;
  double error_sum = 0.0, motion_sum = 0.0; // over the carried steps
  double torque_error_max = 0.0;            // of |force| x a's radius
  for (int step = 0; step < steps; ++step) {
    double d, sweep, angle_a, angle_b;
    path(step, d, sweep, angle_a, angle_b);
    Body a, b;
    rocks.at(Vector3d(0.01, -0.02, 0.03), d, sweep, angle_a, angle_b, 0.0, 0.0, eps, wa, wb, a, b);
    const double motion = kept_contacts_motion(kept.data(), a.pose, b.pose);
    ContactStats st_ref, st_got;
    const PairForceResult ref =
        body_interaction_alone(a, b, measured, dt, h_ref, scratch_ref, st_ref);
    const PairForceResult got = body_interaction_alone(
        a, b, carrying, dt, h_got, scratch_got, st_got,
        SeparationCache{nullptr, true, nullptr, {}, kept.data()});
    const std::string at = what + " step " + std::to_string(step);
    EXPECT_NEAR(got.max_overlap, ref.max_overlap, margin) << at;
    if (got.contacts_after != ref.contacts_after) {
      EXPECT_LT(std::min(got.max_overlap, ref.max_overlap), margin) << at;
    }
    in_contact += ref.contacts_after > 0;
    carried += st_got.contacts_carried;
    if (st_got.contacts_carried > 0) {
      error_sum += std::abs(got.max_overlap - ref.max_overlap);
      motion_sum += motion;
      const double lever = ref.force_a.norm() * a.pose.radius;
      if (lever > 0.0)
        torque_error_max =
            std::max(torque_error_max, (got.torque_a - ref.torque_a).norm() / lever);
    }
  }
  EXPECT_GT(in_contact, steps / 2) << what;
  // The first-order update makes the typical error far below the bound (here at most 0.5 % of
  // the motion; with the overlap held instead of moved, 4 % to 94 %).
  const double relative = error_sum / std::max(motion_sum, 1e-300);
  std::printf("%s: mean |carried - measured| %.3g of the motion, torque within %.3g of force x "
              "radius\n",
              what.c_str(), relative, torque_error_max);
  EXPECT_LT(relative, 0.015) << what;
  // The point goes with the material to within 200 motions (ContactPoint::point_is_material):
  // 4 um here, 2e-3 of the radius, plus the overlap's share of the force.
  EXPECT_LT(torque_error_max, 5e-3) << what;
  return in_contact ? double(carried) / double(in_contact) : 0.0;
}

// The centre distance at which the rocks of `pair` first touch along their path (d from 5 mm
// down in 1 um steps), then pressed in by `press`.
double touching_distance(int pair, double press) {
  const double eps = 1e-4;
  RockPairPath rocks(rock(pair % 2 ? 40 : 20, 31 + pair), rock(40, 41 + pair), 900 + pair);
  TriangleSoA wa, wb;
  InteractionScratch scratch;
  InteractionSettings s = settings(true);
  s.kept_tolerance = 0.0;
  for (double d = 0.005; d > 0.001; d -= 1e-6) {
    Body a, b;
    rocks.at(Vector3d(0.01, -0.02, 0.03), d, 0.0, 0.0, 0.0, 0.0, 0.0, eps, wa, wb, a, b);
    ContactStats st;
    if (body_interaction_alone(a, b, s, 1e-5, nullptr, scratch, st).contacts_after > 0)
      return d - press;
  }
  return 0.0;
}

} // namespace

TEST(KeptContacts, RestingSlidingRollingAndMeetingPairsStayWithinTheBound) {
  const int steps = 600;
  for (int pair = 0; pair < 2; ++pair) {
    const double d0 = touching_distance(pair, 2e-5);
    ASSERT_GT(d0, 0.0);
    const std::string name = "pair " + std::to_string(pair);
    // resting: nanometre jitter of position and orientation
    const double resting = carried_share(
        pair,
        [&](int k, double &d, double &sweep, double &aa, double &ab) {
          d = d0 + 2e-9 * std::sin(0.37 * k);
          sweep = 1e-9 * std::cos(0.23 * k);
          aa = 1e-7 * std::sin(0.11 * k);
          ab = 1e-7 * std::cos(0.17 * k);
        },
        steps, name + " resting");
    // sliding: 2 nm a step sideways
    const double sliding = carried_share(
        pair,
        [&](int k, double &d, double &sweep, double &aa, double &ab) {
          d = d0;
          sweep = 2e-9 * k;
          aa = ab = 0.0;
        },
        steps, name + " sliding");
    // rolling: b turns 1e-6 rad a step while its centre follows
    const double rolling = carried_share(
        pair,
        [&](int k, double &d, double &sweep, double &aa, double &ab) {
          d = d0;
          ab = 1e-6 * k;
          sweep = 1e-6 * k * 0.002;
          aa = 0.0;
        },
        steps, name + " rolling");
    // meeting: approaching at 1 nm a step from just apart (0.2 um) to pressed in
    const double meeting = carried_share(
        pair,
        [&](int k, double &d, double &sweep, double &aa, double &ab) {
          d = d0 + 2e-5 + 2e-7 - 1e-9 * k;
          sweep = aa = ab = 0.0;
        },
        steps, name + " meeting");
    std::printf("%s: carried in %.2f resting, %.2f sliding, %.2f rolling, %.2f meeting\n",
                name.c_str(), resting, sliding, rolling, meeting);
    EXPECT_GT(resting, 0.9) << name;
    EXPECT_GT(sliding, 0.3) << name;
  }
}
