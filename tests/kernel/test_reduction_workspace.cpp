// A ReductionWorkspace reused across body pairs (one per thread, every pair of a step) keeps per
// call caches (the triangles' plane normals, stamped per call): the points of a reduction must
// be bitwise those of a fresh workspace, whatever pairs came before -- meshes of other sizes,
// the same triangle indices on other triangles, and across the stamps' wrap-around.
#include "body/random_rock.h"
#include "contact/contact_reduction.h"
#include "distance/particle_contacts.h"
#include "test_meshes.h"
#include "triangle_contact_search.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <limits>
#include <vector>

namespace {

using Eigen::Vector3d;
using tri_test::box;
using tri_test::transformed;

struct Scene {
  tri::TriangleSoA a, b;
  std::vector<tri::TriangleContact> contacts;
  tri::ReductionParams params;
};

constexpr double kEps = 1e-4; // m, each body's soft layer

// b moved towards a along `direction` until their layers overlap by about a third.
Scene touching(const tri::TriangleMesh &a, const tri::TriangleMesh &b, const Vector3d &direction,
               double longest_edge) {
  Scene s;
  s.a = tri::to_soa(a);
  s.params.link_length = tri::recommended_link_length(longest_edge, longest_edge, kEps, kEps);
  s.params.reference_direction = direction;
  tri::ContactOptions opt;
  opt.kernel = tri::DistanceKernel::BruteForce;
  tri::ContactStats stats;
  for (double shift = 0.02; shift > -0.02; shift -= kEps / 3.0) {
    s.b = tri::to_soa(transformed(b, Eigen::Matrix3d::Identity(), shift * direction));
    s.contacts.clear();
    tri_test::find_triangle_contacts(s.a, kEps, s.b, kEps, opt, s.contacts, stats);
    if (!s.contacts.empty()) {
      s.b = tri::to_soa(transformed(b, Eigen::Matrix3d::Identity(), (shift - kEps) * direction));
      s.contacts.clear();
      tri_test::find_triangle_contacts(s.a, kEps, s.b, kEps, opt, s.contacts, stats);
      return s;
    }
  }
  ADD_FAILURE() << "the bodies never met";
  return s;
}

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  const double side = 0.004;
  const tri::TriangleMesh cube = box(side, side, side);
  // A face lying on a face (contact polygons), the same cube turned (edges and corners, no
  // polygon), and rocks of 20 and 40 triangles meeting at random places.
  const Vector3d up = Vector3d::UnitZ();
  out.push_back(touching(cube, transformed(cube, Eigen::Matrix3d::Identity(), 1.001 * side * up),
                         -up, side * 1.5));
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.35, Vector3d::UnitX()) * Eigen::AngleAxisd(0.2, Vector3d::UnitY()))
          .toRotationMatrix();
  out.push_back(touching(cube, transformed(cube, turn, 1.3 * side * up), -up, side * 1.5));
  for (int k = 0; k < 6; ++k) {
    tri::RockParameters ra, rb;
    ra.ntri = k % 2 ? 40 : 20;
    rb.ntri = k % 3 ? 20 : 40;
    ra.size = rb.size = side;
    ra.seed = 11 + k;
    rb.seed = 101 + k;
    ra.aspect_middle = rb.aspect_middle = 0.8;
    ra.aspect_short = rb.aspect_short = 0.6;
    const Vector3d d = Vector3d(std::cos(1.1 * k), std::sin(1.1 * k), 0.3 * (k - 2.5)).normalized();
    out.push_back(touching(tri::random_rock(ra), transformed(tri::random_rock(rb),
                                                             Eigen::Matrix3d::Identity(), 1.2 * side * d),
                           -d, side));
  }
  return out;
}

void expect_same(const tri::ContactPoint &p, const tri::ContactPoint &q) {
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(p.point[d], q.point[d]);
    EXPECT_EQ(p.normal[d], q.normal[d]);
    EXPECT_EQ(p.damping_point[d], q.damping_point[d]);
  }
  EXPECT_EQ(p.overlap, q.overlap);
  EXPECT_EQ(p.energy_overlap, q.energy_overlap);
  EXPECT_EQ(p.min_distance, q.min_distance);
  EXPECT_EQ(p.num_merged, q.num_merged);
  EXPECT_EQ(p.patch_area, q.patch_area);
  EXPECT_EQ(p.patch_mean_radius, q.patch_mean_radius);
  EXPECT_EQ(p.face_weight, q.face_weight);
  EXPECT_TRUE(p.patch_second_moment == q.patch_second_moment);
}

TEST(ReductionWorkspace, ReusedWorkspaceGivesAFreshOnesPoints) {
  const std::vector<Scene> all = scenes();
  tri::ReductionWorkspace shared;
  shared.call = std::numeric_limits<unsigned>::max() - 5; // the stamps wrap during the test
  int with_patch = 0, without_patch = 0;
  std::vector<tri::ContactPoint> reused, fresh;
  for (int round = 0; round < 3; ++round)
    for (std::size_t k = 0; k < all.size(); ++k) {
      const Scene &s = all[round == 1 ? all.size() - 1 - k : k]; // other predecessors too
      ASSERT_FALSE(s.contacts.empty());
      tri::reduce_contacts(s.contacts.data(), static_cast<int>(s.contacts.size()), s.a, kEps, s.b,
                           kEps, s.params, shared, reused);
      tri::ReductionWorkspace own;
      tri::reduce_contacts(s.contacts.data(), static_cast<int>(s.contacts.size()), s.a, kEps, s.b,
                           kEps, s.params, own, fresh);
      ASSERT_EQ(reused.size(), fresh.size());
      ASSERT_FALSE(fresh.empty());
      for (std::size_t i = 0; i < fresh.size(); ++i) {
        expect_same(reused[i], fresh[i]);
        (fresh[i].patch_area > 0.0 ? with_patch : without_patch) += round == 0;
      }
    }
  EXPECT_GT(with_patch, 0);    // the face on a face went through the polygons
  EXPECT_GT(without_patch, 0); // corners and edges did not
  EXPECT_LT(shared.call, 100u); // wrapped
}

} // namespace
