// Hand-made triangle pairs whose distance is known by construction, the adversarial sets of
// the kernel tests: parallel edges and faces, coplanar overlapping and disjoint triangles,
// vertex-on-face, edge-on-edge, crossing triangles, slivers, degenerate triangles. Each is
// built at unit size and then moved by a seeded rigid motion and scaled (1e-6 .. 1e3), which
// scales the known distance exactly, so no oracle with absolute tolerances is needed.
#pragma once

#include "test_particles.h"

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace tri_test {

struct TriangleCase {
  std::string name;
  Eigen::Vector3d a[3], b[3];
  double distance; // known exactly (0 for touching and intersecting pairs)
  bool intersecting;
};

using V = Eigen::Vector3d;

// Unit-size cases with gap d (> 0 separated, 0 touching).
inline std::vector<TriangleCase> unit_cases(double d) {
  std::vector<TriangleCase> c;
  const bool touch = d == 0.0;
  const std::string tag = touch ? " touching" : " d=" + std::to_string(d);
  const V f0(0, 0, 0), f1(1, 0, 0), f2(0, 1, 0); // base triangle in z = 0
  c.push_back({"parallel faces" + tag,
               {f0, f1, f2},
               {f0 + V(0.2, 0.1, d), f1 + V(0.2, 0.1, d), f2 + V(0.2, 0.1, d)},
               d,
               touch});
  c.push_back({"antiparallel faces" + tag,
               {f0, f1, f2},
               {V(0.6, 0.3, d), V(0.1, 0.2, d), V(0.3, 0.6, d)},
               d,
               touch});
  c.push_back({"parallel edges" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, -1, 0)},
               {V(0.3, 0, d), V(1.5, 0, d), V(0.8, 0, d + 1)},
               d,
               touch});
  c.push_back({"collinear edges" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, -1, 0)},
               {V(1 + d, 0, 0), V(2 + d, 0, 0), V(1.5 + d, 1, 0.3)},
               d,
               touch});
  c.push_back({"coplanar disjoint" + tag,
               {f0, f1, f2},
               {V(1 + d, 0, 0), V(2 + d, 0, 0), V(1 + d, 1, 0)},
               d,
               touch});
  c.push_back({"vertex on face" + tag,
               {f0, f1, f2},
               {V(0.25, 0.25, d), V(0.3, 0.2, 1), V(0.2, 0.3, 1)},
               d,
               touch});
  c.push_back({"face on vertex" + tag,
               {V(0.25, 0.25, -d), V(0.3, 0.2, -1), V(0.2, 0.3, -1)},
               {f0, f1, f2},
               d,
               touch});
  c.push_back({"edge on edge" + tag,
               {f0, f1, f2},
               {V(0.5, -0.5, d), V(0.5, 0.5, d + 0.0), V(0.5, 0, d + 1)},
               d,
               touch});
  c.push_back({"edge over edge skew" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, -1, -1)},
               {V(0.4, -0.5, d), V(0.6, 0.5, d), V(0.5, 0, d + 1)},
               d,
               touch});
  c.push_back({"vertex on vertex" + tag,
               {f0, f1, f2},
               {V(0, 0, 0) - d * V(1, 1, 1).normalized(), V(-1, -0.2, -0.3), V(-0.2, -1, -0.4)},
               d,
               touch});
  c.push_back({"edge on face" + tag,
               {f0, f1, f2},
               {V(0.1, 0.2, d), V(0.6, 0.3, d), V(0.3, 0.3, 1)},
               d,
               touch});
  c.push_back({"sliver over face" + tag,
               {f0, f1, f2},
               {V(0.1, 0.2, d), V(0.7, 0.2, d), V(0.4, 0.2 + 1e-11, d)},
               d,
               touch});
  c.push_back({"sliver across edge" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, 1e-10, 0)},
               {V(0.5, -0.5, d), V(0.5, 0.5, d), V(0.5, 0, 1)},
               d,
               touch});
  c.push_back({"collinear triangle" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, 0, 0)},
               {V(0.5, -0.5, d), V(0.5, 0.5, d), V(0.5, 0, 1)},
               d,
               touch});
  c.push_back({"point triangle" + tag,
               {V(0.3, 0.3, -d), V(0.3, 0.3, -d), V(0.3, 0.3, -d)},
               {f0, f1, f2},
               d,
               touch});
  c.push_back({"near-parallel edges" + tag,
               {V(0, 0, 0), V(1, 0, 0), V(0.5, -1, 0)},
               {V(0.2, 0, d), V(0.8, 1e-9, d), V(0.5, 0, d + 1)},
               d,
               touch});
  return c;
}

// Pairs that cross (distance 0): an edge through the other's interior, two crossing faces,
// coplanar overlapping triangles, one triangle inside the other (coplanar).
inline std::vector<TriangleCase> crossing_cases() {
  const V f0(0, 0, 0), f1(1, 0, 0), f2(0, 1, 0);
  return {
      {"edge through face", {f0, f1, f2}, {V(0.2, 0.2, -1), V(0.3, 0.3, 1), V(2, 2, 0.1)}, 0, true},
      {"crossing faces",
       {f0, f1, f2},
       {V(0.2, -0.5, -0.5), V(0.2, 0.5, 0.5), V(0.3, 0.6, -0.5)},
       0,
       true},
      {"face through face",
       {V(-1, -1, 0), V(2, -1, 0), V(-1, 2, 0)},
       {V(0.2, 0.2, -0.5), V(0.4, 0.2, 0.5), V(0.3, 0.4, 0.5)},
       0,
       true},
      {"coplanar overlapping",
       {f0, f1, f2},
       {V(0.2, 0.2, 0), V(1.2, 0.2, 0), V(0.2, 1.2, 0)},
       0,
       true},
      {"coplanar contained", {V(-1, -1, 0), V(3, -1, 0), V(-1, 3, 0)}, {f0, f1, f2}, 0, true},
      {"identical", {f0, f1, f2}, {f0, f1, f2}, 0, true},
      {"slightly penetrating faces",
       {f0, f1, f2},
       {V(0.2, 0.1, -1e-3), V(0.7, 0.1, 1e-3), V(0.2, 0.6, -1e-3)},
       0,
       true},
  };
}

// All cases (several gaps, touching, crossing) moved by a seeded rigid motion and scaled.
inline std::vector<TriangleCase> adversarial_cases(double scale, std::uint64_t seed) {
  std::vector<TriangleCase> base;
  for (double d : {0.0, 1e-9, 1e-6, 1e-3, 0.05, 0.7})
    for (auto &c : unit_cases(d))
      base.push_back(c);
  for (auto &c : crossing_cases())
    base.push_back(c);
  std::mt19937_64 rng(seed);
  for (auto &c : base) {
    const Eigen::Matrix3d r = random_rotation(rng);
    const V t(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
    for (int k = 0; k < 3; ++k) {
      c.a[k] = scale * (r * c.a[k] + t);
      c.b[k] = scale * (r * c.b[k] + t);
    }
    c.distance *= scale;
  }
  return base;
}

// n random pairs within a few triangle sizes of each other (corners in [-scale, scale]^3, the
// second shifted by up to 2 sqrt(3) scale): mostly separated, some intersecting. Shared by
// the penalty and pair-list kernel tests, which compare against brute force: the distance is
// not known here (NaN, and `intersecting` is false without having been checked).
inline std::vector<TriangleCase> random_cases(int n, double scale, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<TriangleCase> cases;
  for (int k = 0; k < n; ++k) {
    TriangleCase c;
    c.name = "random " + std::to_string(k);
    c.distance = std::numeric_limits<double>::quiet_NaN();
    c.intersecting = false;
    const V offset =
        V(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) * uniform(rng, 0, 2);
    for (int v = 0; v < 3; ++v) {
      c.a[v] = scale * V(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
      c.b[v] = scale * (V(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) + offset);
    }
    cases.push_back(c);
  }
  return cases;
}

// Pair list helpers: case k becomes triangle k of `a` and of `b`.
inline void cases_to_soa(const std::vector<TriangleCase> &cases, tri::TriangleSoA &a,
                         tri::TriangleSoA &b, std::vector<tri::TrianglePairIndex> &pairs) {
  const int n = static_cast<int>(cases.size());
  a.resize(n);
  b.resize(n);
  pairs.clear();
  for (int k = 0; k < n; ++k) {
    for (int v = 0; v < 3; ++v) {
      a.set_vertex(k, v, cases[k].a[v]);
      b.set_vertex(k, v, cases[k].b[v]);
    }
    pairs.push_back({k, k});
  }
}

} // namespace tri_test
