// Small deterministic convex particles for the kernel tests and the kernel benchmark
// (validation/performance/kernel_bench.cpp includes this header). Not the official shape
// generator (src_plugin/kernel/body/random_rock.h): these are bipyramids over an n-gon (2n
// triangles, so 20 and 40 triangles for n = 10 and 20) with a randomly perturbed ring
// radius, stretched along random axes and rotated, so that every seed gives a different
// convex "rock" of exactly 2n triangles with bounding diameter about `size`.
#pragma once

#include "distance/distance_kernels.h"
#include "geometry/triangle_mesh.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>

namespace tri_test {

// Uniform double in [lo, hi) from a 64-bit Mersenne twister, independent of the standard
// library's distribution implementations.
inline double uniform(std::mt19937_64 &rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

inline Eigen::Matrix3d random_rotation(std::mt19937_64 &rng) {
  Eigen::Quaterniond q(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1),
                       uniform(rng, -1, 1));
  if (q.norm() < 1e-3)
    q = Eigen::Quaterniond::Identity();
  return q.normalized().toRotationMatrix();
}

// Convex bipyramid with ntri = 2 n triangles (ntri even, >= 6), centred at the origin.
inline tri::TriangleMesh test_particle(int ntri, double size, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const int n = ntri / 2;
  tri::TriangleMesh mesh;
  const double pi = std::acos(-1.0);
  // Ring radii within +-2 %: for n <= 20 every ring vertex stays outside the chord of its
  // neighbours, so the ring, and the bipyramid, stay convex.
  for (int k = 0; k < n; ++k) {
    const double phi = 2 * pi * k / n, r = 0.5 * uniform(rng, 0.98, 1.02);
    mesh.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), 0.0);
  }
  mesh.vertices.emplace_back(0.0, 0.0, 0.5 * uniform(rng, 0.7, 1.0));  // top apex, index n
  mesh.vertices.emplace_back(0.0, 0.0, -0.5 * uniform(rng, 0.7, 1.0)); // bottom apex
  for (int k = 0; k < n; ++k) {
    const int next = (k + 1) % n;
    mesh.triangles.push_back({k, next, n});
    mesh.triangles.push_back({next, k, n + 1});
  }
  // Stretch along random axes (keeps convexity), rotate, scale to the requested size.
  const Eigen::Matrix3d axes = random_rotation(rng);
  const Eigen::Vector3d stretch(uniform(rng, 0.8, 1.2), uniform(rng, 0.8, 1.2),
                                uniform(rng, 0.8, 1.2));
  const Eigen::Matrix3d map = random_rotation(rng) * axes * stretch.asDiagonal() * axes.transpose();
  double radius = 0.0;
  for (auto &v : mesh.vertices) {
    v = map * v;
    radius = std::max(radius, v.norm());
  }
  for (auto &v : mesh.vertices)
    v *= 0.5 * size / radius;
  return mesh;
}

// Brute-force distance between two particles (minimum over all triangle pairs).
inline double particle_distance(const tri::TriangleSoA &a, const tri::TriangleSoA &b) {
  std::vector<tri::TrianglePairIndex> pairs;
  for (int i = 0; i < a.num_triangles(); ++i)
    for (int j = 0; j < b.num_triangles(); ++j)
      pairs.push_back({i, j});
  std::vector<tri::TrianglePairDistance> d(pairs.size());
  tri::brute_force_scalar_distances(a, b, pairs.data(), static_cast<int>(pairs.size()), d.data());
  double m = INFINITY;
  for (const auto &r : d)
    m = std::min(m, r.distance);
  return m;
}

// Places `body` (a convex particle centred near the origin) along `direction` from `fixed`
// so that their distance is `gap` (> 0), and returns it in world frame. Converges from
// outside: moving by the distance surplus never crosses the target for convex bodies.
inline tri::TriangleSoA place_at_gap(const tri::TriangleSoA &fixed, const tri::TriangleSoA &body,
                                     Eigen::Vector3d direction, double gap) {
  direction.normalize();
  double reach = 0.0; // sum of the two bounding radii about the origin
  for (const tri::TriangleSoA *s : {&fixed, &body}) {
    double r = 0.0;
    for (std::size_t i = 0; i < s->x.size(); ++i)
      r = std::max(r, Eigen::Vector3d(s->x[i], s->y[i], s->z[i]).norm());
    reach += r;
  }
  double t = reach + gap;
  tri::TriangleSoA world;
  for (int it = 0; it < 200; ++it) {
    tri::transform_soa(body, Eigen::Matrix3d::Identity(), t * direction, world);
    const double d = particle_distance(fixed, world);
    if (std::abs(d - gap) <= 1e-13 * reach)
      break;
    t -= d - gap;
  }
  return world;
}

} // namespace tri_test
