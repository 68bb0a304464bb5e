// Triangle boxes and the box cull (triangle_boxes.h): boxes contain their triangles, and the
// cull keeps every pair closer than the margin; the two-stage cull keeps exactly the full
// cull's pairs.
#include "distance/distance_kernels.h"
#include "distance/triangle_boxes.h"
#include "test_particles.h"

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

// The two-stage cull (whole box first, then pairs among survivors) keeps exactly the pairs
// of the full cull, in row-major order, and so every pair within the layer; random
// particles of different sizes and triangle counts, shifts from deep overlap to apart.
TEST(TriangleBoxes, TwoStageCullKeepsExactlyTheFullCullsPairs) {
  long long close_pairs = 0, kept_pairs = 0, all_pairs = 0;
  CullScratch scratch;
  for (int seed = 0; seed < 300; ++seed) {
    std::mt19937_64 rng(7000 + seed);
    const TriangleSoA a = to_soa(tri_test::test_particle(6 + 2 * (seed % 18), 1.0, 300 + seed));
    const TriangleSoA body = to_soa(tri_test::test_particle(
        6 + 2 * ((seed * 7) % 20), tri_test::uniform(rng, 0.3, 2.0), 900 + seed));
    const int na = a.num_triangles(), nb = body.num_triangles();
    TriangleSoA b;
    const double reach = tri_test::uniform(rng, 0.2, 2.5);
    const Eigen::Vector3d shift(tri_test::uniform(rng, -reach, reach),
                                tri_test::uniform(rng, -reach, reach),
                                tri_test::uniform(rng, -reach, reach));
    transform_soa(body, tri_test::random_rotation(rng), shift, b);
    const double margin = tri_test::uniform(rng, 0.0, 0.2);
    TriangleBoxes ba, bb;
    compute_triangle_boxes(a, ba);
    compute_triangle_boxes(b, bb);
    std::vector<TrianglePairIndex> full, two;
    std::vector<std::uint8_t> keep(nb);
    for (int i = 0; i < na; ++i) {
      overlapping_boxes(ba, i, bb, margin, keep.data());
      for (int j = 0; j < nb; ++j)
        if (keep[j])
          full.push_back({i, j});
    }
    const int count = cull_triangle_pairs(ba, bb, margin, scratch, two);
    ASSERT_EQ(count, static_cast<int>(full.size())) << "seed " << seed;
    for (int k = 0; k < count; ++k) {
      ASSERT_EQ(two[k].a, full[k].a) << "seed " << seed << " entry " << k;
      ASSERT_EQ(two[k].b, full[k].b) << "seed " << seed << " entry " << k;
    }
    // Every pair within the layer is among them.
    std::vector<std::uint8_t> in_two(static_cast<std::size_t>(na) * nb, 0);
    for (int k = 0; k < count; ++k)
      in_two[static_cast<std::size_t>(two[k].a) * nb + two[k].b] = 1;
    for (int i = 0; i < na; ++i)
      for (int j = 0; j < nb; ++j) {
        TrianglePairIndex p{i, j};
        TrianglePairDistance d;
        brute_force_scalar_distances(a, b, &p, 1, &d);
        if (d.distance < margin) {
          ++close_pairs;
          ASSERT_TRUE(in_two[static_cast<std::size_t>(i) * nb + j])
              << "seed " << seed << " pair " << i << "," << j;
        }
      }
    kept_pairs += count;
    all_pairs += static_cast<long long>(na) * nb;
  }
  EXPECT_GT(close_pairs, 1000);          // the test sees contacts ...
  EXPECT_LT(kept_pairs, all_pairs / 2);  // ... and the cull removes most pairs
}

TEST(TriangleBoxes, WholeBoxContainsTriangleBoxesAndEmptySetCullsAll) {
  const TriangleSoA soa = to_soa(tri_test::test_particle(40, 4e-3, 2));
  TriangleBoxes boxes;
  compute_triangle_boxes(soa, boxes);
  for (int t = 0; t < 40; ++t) {
    EXPECT_LE(boxes.all_lo[0], boxes.lo_x[t]);
    EXPECT_LE(boxes.all_lo[1], boxes.lo_y[t]);
    EXPECT_LE(boxes.all_lo[2], boxes.lo_z[t]);
    EXPECT_GE(boxes.all_hi[0], boxes.hi_x[t]);
    EXPECT_GE(boxes.all_hi[1], boxes.hi_y[t]);
    EXPECT_GE(boxes.all_hi[2], boxes.hi_z[t]);
  }
  TriangleBoxes none;
  compute_triangle_boxes(TriangleSoA{}, none);
  CullScratch scratch;
  std::vector<TrianglePairIndex> pairs(1);
  EXPECT_EQ(cull_triangle_pairs(boxes, none, 1.0, scratch, pairs), 0);
  EXPECT_EQ(cull_triangle_pairs(none, boxes, 1.0, scratch, pairs), 0);
}

// The two-frame cull (world boxes and boxes in a rotated frame) and the separating-axis filter
// keep every pair closer than the margin, keep only pairs the world cull keeps, in its order,
// and remove more than it does.
TEST(TriangleBoxes, TwoFrameCullAndSeparatingAxesKeepEveryPairWithinTheMargin) {
  long long close_pairs = 0, world_kept = 0, tight_kept = 0;
  CullScratch scratch, scratch2;
  for (int seed = 0; seed < 200; ++seed) {
    std::mt19937_64 rng(9100 + seed);
    const TriangleSoA a = to_soa(tri_test::test_particle(6 + 2 * (seed % 18), 1.0, 500 + seed));
    const TriangleSoA body = to_soa(tri_test::test_particle(
        6 + 2 * ((seed * 5) % 20), tri_test::uniform(rng, 0.3, 2.0), 1500 + seed));
    const int na = a.num_triangles(), nb = body.num_triangles();
    TriangleSoA b;
    const double reach = tri_test::uniform(rng, 0.3, 1.5);
    const Eigen::Vector3d shift(tri_test::uniform(rng, -reach, reach),
                                tri_test::uniform(rng, -reach, reach),
                                tri_test::uniform(rng, -reach, reach));
    transform_soa(body, tri_test::random_rotation(rng), shift, b);
    const double margin = tri_test::uniform(rng, 0.0, 0.2);
    const Eigen::Matrix3d frame = tri_test::random_rotation(rng);
    TriangleSoA fa, fb;
    transform_soa(a, frame, Eigen::Vector3d::Zero(), fa);
    transform_soa(b, frame, Eigen::Vector3d::Zero(), fb);
    TriangleBoxes ba, bb, bfa, bfb;
    compute_triangle_boxes(a, ba);
    compute_triangle_boxes(b, bb);
    compute_triangle_boxes(fa, bfa);
    compute_triangle_boxes(fb, bfb);
    std::vector<TrianglePairIndex> world, tight;
    const int nw = cull_triangle_pairs(ba, bb, margin, scratch, world);
    const double frame_margin = margin * (1 + 1e-9) + 1e-12;
    int nt =
        cull_triangle_pairs_two_frames(ba, bb, bfa, bfb, margin, frame_margin, scratch2, tight);
    nt = separating_axis_filter(a, b, frame_margin, tight.data(), nt);
    // A subsequence of the world cull's list.
    int w = 0;
    for (int k = 0; k < nt; ++k) {
      while (w < nw && !(world[w].a == tight[k].a && world[w].b == tight[k].b))
        ++w;
      ASSERT_LT(w, nw) << "seed " << seed << ": pair " << tight[k].a << "," << tight[k].b
                       << " is not kept by the world cull, or out of order";
    }
    std::vector<std::uint8_t> kept(static_cast<std::size_t>(na) * nb, 0);
    for (int k = 0; k < nt; ++k)
      kept[static_cast<std::size_t>(tight[k].a) * nb + tight[k].b] = 1;
    for (int i = 0; i < na; ++i)
      for (int j = 0; j < nb; ++j) {
        TrianglePairIndex p{i, j};
        TrianglePairDistance d;
        brute_force_scalar_distances(a, b, &p, 1, &d);
        if (d.distance < margin) {
          ++close_pairs;
          ASSERT_TRUE(kept[static_cast<std::size_t>(i) * nb + j])
              << "seed " << seed << " pair " << i << "," << j << " at " << d.distance;
        }
      }
    world_kept += nw;
    tight_kept += nt;
  }
  EXPECT_GT(close_pairs, 1000);
  EXPECT_LT(tight_kept, world_kept * 0.8);
}

// The separating-axis filter on hand-made pairs: parallel faces a little more or less than
// the margin apart, crossed edges apart along their common normal only, a degenerate triangle
// (a segment), and a pair that intersects.
TEST(TriangleBoxes, SeparatingAxesOnHandMadePairs) {
  auto tri = [](Eigen::Vector3d p, Eigen::Vector3d q, Eigen::Vector3d r) {
    TriangleSoA t;
    t.resize(1);
    t.set_vertex(0, 0, p);
    t.set_vertex(0, 1, q);
    t.set_vertex(0, 2, r);
    return t;
  };
  using V = Eigen::Vector3d;
  const TriangleSoA floor = tri(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0));
  auto kept = [](const TriangleSoA &a, const TriangleSoA &b, double margin) {
    TrianglePairIndex p{0, 0};
    return separating_axis_filter(a, b, margin, &p, 1);
  };
  for (double h : {0.099, 0.101}) // parallel, h above: apart beyond 0.1 only
    EXPECT_EQ(kept(floor, tri(V(0, 0, h), V(1, 0, h), V(0, 1, h)), 0.1), h < 0.1 ? 1 : 0);
  // Two edges crossing at right angles, 0.2 apart along z: only the edge-edge axis sees it
  // (each triangle is vertical, so neither face normal is z).
  const TriangleSoA xs = tri(V(-1, 0, 0), V(1, 0, 0), V(0, 0, -1));
  const TriangleSoA ys = tri(V(0, -1, 0.2), V(0, 1, 0.2), V(0, 0, 1.2));
  EXPECT_EQ(kept(xs, ys, 0.19), 0);
  EXPECT_EQ(kept(xs, ys, 0.21), 1);
  const TriangleSoA segment = tri(V(0, 0, -5), V(0, 0, 0), V(0, 0, 5)); // no normal
  EXPECT_EQ(kept(segment, floor, 0.1), 1);                              // it crosses the floor
  EXPECT_EQ(kept(tri(V(0.2, 0.2, -1), V(0.3, 0.2, 1), V(0.2, 0.3, 1)), floor, 0.0), 1);
}
