// Triangle boxes and the box cull (triangle_boxes.h): boxes contain their triangles, and the
// cull keeps every pair closer than the margin.
#include "distance_kernels.h"
#include "test_particles.h"
#include "triangle_boxes.h"

#include <gtest/gtest.h>

using namespace tri;

TEST(TriangleBoxes, ContainTheirTriangles) {
  const TriangleSoA soa = to_soa(tri_test::test_particle(40, 4e-3, 1));
  TriangleBoxes boxes;
  compute_triangle_boxes(soa, boxes);
  ASSERT_EQ(boxes.num_triangles(), 40);
  for (int t = 0; t < 40; ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d v = soa.vertex(t, k);
      EXPECT_LE(boxes.lo_x[t], v.x());
      EXPECT_GE(boxes.hi_x[t], v.x());
      EXPECT_LE(boxes.lo_y[t], v.y());
      EXPECT_GE(boxes.hi_y[t], v.y());
      EXPECT_LE(boxes.lo_z[t], v.z());
      EXPECT_GE(boxes.hi_z[t], v.z());
    }
}

TEST(TriangleBoxes, CullNeverDropsAPairCloserThanTheMargin) {
  std::mt19937_64 rng(51);
  long long close_pairs = 0, culled = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const TriangleSoA a = to_soa(tri_test::test_particle(20, 1.0, 100 + trial));
    const TriangleSoA body = to_soa(tri_test::test_particle(20, 1.0, 200 + trial));
    TriangleSoA b;
    const Eigen::Vector3d shift(tri_test::uniform(rng, -1, 1), tri_test::uniform(rng, -1, 1),
                                tri_test::uniform(rng, -1, 1));
    transform_soa(body, tri_test::random_rotation(rng), shift, b);
    const double margin = 0.05;
    TriangleBoxes ba, bb;
    compute_triangle_boxes(a, ba);
    compute_triangle_boxes(b, bb);
    std::vector<std::uint8_t> keep(20);
    for (int i = 0; i < 20; ++i) {
      const int kept = overlapping_boxes(ba, i, bb, margin, keep.data());
      int count = 0;
      for (int j = 0; j < 20; ++j) {
        count += keep[j];
        TrianglePairIndex p{i, j};
        TrianglePairDistance d;
        brute_force_scalar_distances(a, b, &p, 1, &d);
        if (d.distance < margin) {
          ++close_pairs;
          ASSERT_TRUE(keep[j]) << "trial " << trial << " pair " << i << "," << j;
        }
        culled += !keep[j];
      }
      EXPECT_EQ(kept, count);
    }
  }
  EXPECT_GT(close_pairs, 100); // the test sees contacts ...
  EXPECT_GT(culled, 1000);     // ... and the cull does remove pairs
}
