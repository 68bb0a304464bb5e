// Brute-force distance (triangle_distance.h) on sliver triangles -- height 1e-7 (and 2e-8,
// just above the sliver cut) of their length -- against regular and sliver triangles, at
// scales 1e-6 .. 1e3: scalar path, block path (brute_force_distances) and scalar pair list.
//
// The reference is known by construction: triangle A lies in z <= 0 and B in z >= d, and a
// point of A at z = 0 lies below a point of B at z = d (a face, edge or vertex of each, in
// every combination), so the distance is exactly d. The pair is then rotated (seeded),
// moved and scaled, which rounds every corner by ~1e-16 of its coordinates and so moves the
// true distance by ~1e-15 of the pair's size, far below the tolerance tested (1e-12).
#include "distance/distance_kernels.h"
#include "distance/triangle_distance.h"
#include "test_triangle_cases.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <sstream>

using namespace tri;
using namespace tri_test;

namespace {

using Tri = std::array<V, 3>;

// A triangle in z >= 0 with a point `touch` at z = 0 (put at the origin below).
struct Upper {
  Tri t;
  std::string what;
};

// Shapes in the xy plane: slivers of unit length and height eta with the apex over
// x = apex (at an end: a right angle and a short edge), and one regular triangle.
Tri sliver_shape(double apex, double eta) { return {V(0, 0, 0), V(1, 0, 0), V(apex, eta, 0)}; }
Tri regular_shape() { return {V(0, 0, 0), V(0.9, 0.1, 0), V(0.3, 0.8, 0)}; }

V rotate_z(const V &p, double angle) {
  return V(std::cos(angle) * p.x() - std::sin(angle) * p.y(),
           std::sin(angle) * p.x() + std::cos(angle) * p.y(), p.z());
}

// Face down: the whole triangle at z = 0, an interior point at the origin.
Upper face_down(const Tri &s, std::mt19937_64 &rng) {
  const double w0 = uniform(rng, 0.1, 0.8), w1 = uniform(rng, 0.05, 0.9 - w0);
  const V q = w0 * s[0] + w1 * s[1] + (1 - w0 - w1) * s[2];
  const double angle = uniform(rng, 0, 2 * M_PI);
  Upper u{{}, "face"};
  for (int k = 0; k < 3; ++k)
    u.t[k] = rotate_z(s[k] - q, angle);
  return u;
}

// Edge down: edge k on a line through the origin at angle `angle` in the xy plane, the
// triangle tilted up about it by phi (0 < phi < pi).
Upper edge_down(const Tri &s, int k, double phi, double angle, std::mt19937_64 &rng) {
  const V p = s[k], q = s[(k + 1) % 3], r = s[(k + 2) % 3];
  const double len = (q - p).norm();
  const V dir = (q - p) / len;
  const double along = (r - p).dot(dir), height = (r - p - along * dir).norm();
  const double at = uniform(rng, 0.05, 0.95) * len; // the origin's place on the edge
  Tri local;
  local[k] = V(-at, 0, 0);
  local[(k + 1) % 3] = V(len - at, 0, 0);
  local[(k + 2) % 3] = V(along - at, height * std::cos(phi), height * std::sin(phi));
  Upper u{{}, "edge " + std::to_string(k) + " phi " + std::to_string(phi)};
  for (int j = 0; j < 3; ++j)
    u.t[j] = rotate_z(local[j], angle);
  return u;
}

// Vertex down: a seeded rotation, the lowest corner moved to the origin (the others are at
// z >= 0 after the subtraction, since rounding is monotonic).
Upper vertex_down(const Tri &s, std::mt19937_64 &rng) {
  const Eigen::Matrix3d r = random_rotation(rng);
  Tri t = {r * s[0], r * s[1], r * s[2]};
  int low = 0;
  for (int k = 1; k < 3; ++k)
    if (t[k].z() < t[low].z())
      low = k;
  const V o = t[low];
  Upper u{{}, "vertex"};
  for (int k = 0; k < 3; ++k)
    u.t[k] = t[k] - o;
  return u;
}

struct Shape {
  Tri t;
  std::string name;
  bool sliver;
};

std::vector<Shape> shapes(double eta) {
  std::ostringstream e;
  e << eta;
  std::vector<Shape> s;
  for (double apex : {0.5, 0.0, 1.0, 0.02, 0.7})
    s.push_back(
        {sliver_shape(apex, eta), "sliver " + e.str() + " apex " + std::to_string(apex), true});
  s.push_back({regular_shape(), "regular", false});
  return s;
}

// One placement of shape s with the given kind of feature down (0 face, 1 edge, 2 vertex).
Upper place(const Shape &s, int kind, double angle, std::mt19937_64 &rng) {
  static const double phis[] = {0.01, 0.7, M_PI / 2, 2.9};
  if (kind == 0)
    return face_down(s.t, rng);
  if (kind == 1)
    return edge_down(s.t, static_cast<int>(rng() % 3), phis[rng() % 4], angle, rng);
  return vertex_down(s.t, rng);
}

// All sliver pairs of one sliver height at one scale; at least one triangle is a sliver.
std::vector<TriangleCase> sliver_cases(double eta, double scale, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::vector<Shape> all = shapes(eta);
  const double gaps[] = {0.3, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10};
  // Edge-edge crossing angles, down to parallel edges.
  const double crossings[] = {M_PI / 2, 0.3, 1e-4, 1e-8, 0.0};
  std::vector<TriangleCase> cases;
  for (const Shape &sa : all)
    for (const Shape &sb : all) {
      if (!sa.sliver && !sb.sliver)
        continue;
      for (int ka = 0; ka < 3; ++ka)
        for (int kb = 0; kb < 3; ++kb)
          for (int rep = 0; rep < 12; ++rep) {
            const double angle_a = uniform(rng, 0, 2 * M_PI);
            const double angle_b = angle_a + crossings[rng() % 5];
            const Upper ua = place(sa, ka, angle_a, rng), ub = place(sb, kb, angle_b, rng);
            const double d = gaps[rng() % 6];
            // Vertex orders: a cyclic shift and a reversal of each.
            const int shift_a = static_cast<int>(rng() % 3), shift_b = static_cast<int>(rng() % 3);
            const bool flip_a = rng() % 2, flip_b = rng() % 2;
            const Eigen::Matrix3d r = random_rotation(rng);
            const V t(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
            TriangleCase c;
            c.name = sa.name + " " + ua.what + " / " + sb.name + " " + ub.what;
            c.distance = d * scale;
            c.intersecting = false;
            for (int k = 0; k < 3; ++k) {
              const int ia = flip_a ? (3 - k + shift_a) % 3 : (k + shift_a) % 3;
              const int ib = flip_b ? (3 - k + shift_b) % 3 : (k + shift_b) % 3;
              const V pa = V(ua.t[ia].x(), ua.t[ia].y(), -ua.t[ia].z()); // A below z = 0
              const V pb = ub.t[ib] + V(0, 0, d);                        // B above z = d
              c.a[k] = scale * (r * pa + t);
              c.b[k] = scale * (r * pb + t);
            }
            cases.push_back(c);
          }
    }
  return cases;
}

double longest_edge(const TriangleCase &c) {
  double l = 0.0;
  for (int k = 0; k < 3; ++k)
    l = std::max({l, (c.a[(k + 1) % 3] - c.a[k]).norm(), (c.b[(k + 1) % 3] - c.b[k]).norm()});
  return l;
}

struct Worst {
  double error = 0.0; // |distance - known| / longest edge of the pair
  std::string name;
  void add(double e, const std::string &n) {
    if (e > error)
      error = e, name = n;
  }
};

} // namespace

class SliverDistance : public ::testing::TestWithParam<double> {};

TEST_P(SliverDistance, WithinOneE12OfThePairSizeOnEveryPath) {
  const double scale = GetParam();
  for (double eta : {1e-7, 2e-8}) {
    const std::vector<TriangleCase> cases =
        sliver_cases(eta, scale, 1000 + static_cast<std::uint64_t>(eta * 1e9));
    TriangleSoA sa, sb;
    std::vector<TrianglePairIndex> pairs;
    cases_to_soa(cases, sa, sb, pairs);
    const int n = static_cast<int>(cases.size());
    std::vector<TrianglePairDistance> block(n), list(n);
    brute_force_distances(sa, sb, pairs.data(), n, block.data());
    brute_force_scalar_distances(sa, sb, pairs.data(), n, list.data());
    Worst scalar, simd, reversed;
    for (int k = 0; k < n; ++k) {
      const TriangleCase &c = cases[k];
      const double size = longest_edge(c);
      const TrianglePairDistance s = triangle_distance(c.a, c.b);
      const TrianglePairDistance r = triangle_distance(c.b, c.a);
      scalar.add(std::abs(s.distance - c.distance) / size, c.name);
      reversed.add(std::abs(r.distance - c.distance) / size, c.name);
      simd.add(std::abs(block[k].distance - c.distance) / size, c.name);
      EXPECT_FALSE(s.intersecting) << c.name;
      // The block and the scalar pair list run the same operations; only FMA contraction may
      // differ between the two compilations (as in test_triangle_distance.cpp).
      EXPECT_NEAR(block[k].distance, list[k].distance, 1e-14 * size) << c.name;
      EXPECT_EQ(block[k].intersecting, list[k].intersecting) << c.name;
    }
    std::ostringstream tag;
    tag << "eta " << eta << " scale " << scale;
    RecordProperty("worst_scalar " + tag.str(), std::to_string(scalar.error));
    RecordProperty("worst_block " + tag.str(), std::to_string(simd.error));
    std::printf("%s: %d pairs, worst |d - known| / size: scalar %.3g (%s), reversed %.3g, "
                "block %.3g\n",
                tag.str().c_str(), n, scalar.error, scalar.name.c_str(), reversed.error,
                simd.error);
    EXPECT_LE(scalar.error, 1e-12) << tag.str() << ": " << scalar.name;
    EXPECT_LE(reversed.error, 1e-12) << tag.str() << ": " << reversed.name;
    EXPECT_LE(simd.error, 1e-12) << tag.str() << ": " << simd.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, SliverDistance, ::testing::Values(1e-6, 1e-3, 1.0, 1e3));
