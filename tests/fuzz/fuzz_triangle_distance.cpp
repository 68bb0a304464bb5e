// libFuzzer target: one triangle pair through every distance kernel, checked against the
// scalar brute force (triangle_distance.h) with the tolerances of the kernel GoogleTests.
//
// Input: byte 0 = scale (bits 0-1: 1e-6, 1e-3, 1, 1e3), coordinate encoding (bits 2-3,
// fuzz_common.h), Newton iterations (bits 4-6); byte 1 = contact cutoff in 1/64 of the scale
// (1 + byte, 255: none); byte 2 = batch size 1..8; then the 18 coordinates of a and b. Mode 3
// builds b from a's corners moved by at most 1e-6 of the scale, for pairs at the touch tolerance.
//
// Checks (a failure traps):
// - brute force (a, b): finite, distance >= 0, unit normal, |q - p| = distance, intersecting
//   exactly when distance is 0, depth >= 0; (b, a) gives the same distance and verdict;
//   brute_force_block agrees with the scalar call bit for bit (no FMA in this build);
// - penalty bounds bracket the brute-force distance; a certified result (lower > 0,
//   upper - lower <= tolerance) is within the tolerance of it;
// - hybrid (pair by pair and batched) and penalty_distances on the pair list
//   (a,b), (b,a), (a,a), (b,b): hybrid within the tolerance of brute force, same intersecting
//   verdict, same side of the cutoff; penalty alone never below brute force.
// Tolerances: hybrid 1e-7 x scale (test_distance_kernels.cpp), rounding 1e-12 x scale
// (test_penalty_distance.cpp), plus the brute force's sliver allowance and, for the
// intersecting verdict only, a band of a few touch tolerances (fuzz_common.h).
#include "distance/distance_kernels.h"
#include "distance/penalty_distance.h"
#include "distance/triangle_distance.h"
#include "fuzz_common.h"

#include <vector>

using namespace tri;
using tri_fuzz::require;

namespace {

void check_brute_force(const TrianglePairDistance &r, double scale) {
  require(tri_fuzz::finite(r), "brute force: non-finite result");
  require(r.distance >= 0, "brute force: negative distance", r.distance);
  require(std::abs(r.normal.norm() - 1.0) <= 1e-12, "brute force: normal not unit",
          r.normal.norm());
  require(std::abs((r.point_b - r.point_a).norm() - r.distance) <= 1e-12 * (scale + r.distance),
          "brute force: |q - p| != distance", (r.point_b - r.point_a).norm(), r.distance);
  require(r.intersecting == (r.distance == 0.0), "brute force: intersecting != (distance == 0)");
  require(r.penetration_depth >= 0, "brute force: negative depth", r.penetration_depth);
}

struct Pair {
  Eigen::Vector3d a[3], b[3];
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  tri_fuzz::ByteReader in(data, size);
  const std::uint8_t head = in.byte(), cutoff_byte = in.byte(), batch_byte = in.byte();
  const double scale = tri_fuzz::scale_of(head);
  const int mode = (head >> 2) & 3;
  static const int iteration_choices[8] = {1, 2, 3, 4, 6, 8, 16, 32};
  const int iterations = iteration_choices[(head >> 4) & 7];
  // A contact cutoff is eps_a + eps_b > 0 (distance_kernels.h); 0 is outside the contract.
  const double cutoff = cutoff_byte == 255 ? INFINITY : (1 + cutoff_byte) / 64.0 * scale;
  const int batch = 1 + batch_byte % 8;

  Pair p;
  for (auto &v : p.a)
    for (int k = 0; k < 3; ++k)
      v[k] = tri_fuzz::coordinate(in, mode == 3 ? 1 : mode, scale);
  if (mode == 3) {
    for (int i = 0; i < 3; ++i) {
      const int from = in.byte() % 3;
      for (int k = 0; k < 3; ++k)
        p.b[i][k] = p.a[from][k] + static_cast<std::int8_t>(in.byte()) / 128.0 * 1e-6 * scale;
    }
  } else {
    for (auto &v : p.b)
      for (int k = 0; k < 3; ++k)
        v[k] = tri_fuzz::coordinate(in, mode, scale);
  }
  if (tri_fuzz::print_inputs()) {
    std::fprintf(stderr, "scale %g iterations %d cutoff %.17g batch %d\n", scale, iterations,
                 cutoff, batch);
    tri_fuzz::print_triangle("a", p.a);
    tri_fuzz::print_triangle("b", p.b);
  }
  const double rounding = 1e-12 * scale;
  const double sliver = tri_fuzz::sliver_allowance(p.a, p.b);
  const double band = tri_fuzz::touch_band(p.a, p.b);

  // Scalar brute force, both argument orders.
  const TrianglePairDistance ref = triangle_distance(p.a, p.b);
  const TrianglePairDistance rev = triangle_distance(p.b, p.a);
  check_brute_force(ref, scale);
  check_brute_force(rev, scale);
  require(std::abs(ref.distance - rev.distance) <= rounding + sliver, "brute force: not symmetric",
          rev.distance, ref.distance);
  require(ref.intersecting == rev.intersecting ||
              std::max(ref.distance, rev.distance) <= band + sliver,
          "brute force: intersecting verdict not symmetric");

  // Vectorised brute force and penalty on a block: lane 0 (a, b), lane 1 (b, a), padded.
  TrianglePairBlock block;
  block.set_lane(0, p.a, p.b);
  block.set_lane(1, p.b, p.a);
  for (int l = 2; l < kPairLanes; ++l)
    block.copy_lane(l % 2, l);
  TrianglePairDistance lanes[kPairLanes];
  brute_force_block(block, 2, lanes);
  require(lanes[0].distance == ref.distance && lanes[0].intersecting == ref.intersecting &&
              lanes[0].point_a == ref.point_a && lanes[0].normal == ref.normal,
          "brute_force_block differs from triangle_distance", lanes[0].distance, ref.distance);
  require(lanes[1].distance == rev.distance && lanes[1].intersecting == rev.intersecting,
          "brute_force_block differs from triangle_distance (b, a)", lanes[1].distance,
          rev.distance);

  const double tolerance = 1e-7 * scale;
  PenaltyBlockResult pen;
  penalty_block(iterations, block, PenaltyParameters{}, 1e-9 * scale, pen);
  for (int l = 0; l < 2; ++l) {
    const double d = l == 0 ? ref.distance : rev.distance;
    // Brute force reports a pair closer than its touch tolerance as touching, distance 0
    // (triangle_distance.h): the true distance, and a valid lower bound, may be up to that.
    const double touching = (l == 0 ? ref.intersecting : rev.intersecting) ? band : 0.0;
    const double lower = pen.lower[l], upper = pen.upper[l];
    require(std::isfinite(upper) && !std::isnan(lower), "penalty: non-finite bound", upper);
    require(lower <= d + rounding + sliver + touching, "penalty: lower bound above brute force",
            lower, d);
    require(upper >= d - rounding - sliver, "penalty: upper bound below brute force", upper, d);
    if (lower > 0 && upper - lower <= tolerance)
      require(std::abs(upper - d) <= tolerance + rounding + sliver,
              "penalty: certified result off brute force", upper, d);
    require(pen.converged_at[l] >= 0 && pen.converged_at[l] <= iterations,
            "penalty: converged_at out of range", pen.converged_at[l]);
  }

  // The pair-list kernels on (a,b), (b,a), (a,a), (b,b).
  TriangleSoA sa, sb;
  sa.resize(2);
  sb.resize(2);
  for (int k = 0; k < 3; ++k) {
    sa.set_vertex(0, k, p.a[k]);
    sa.set_vertex(1, k, p.b[k]);
    sb.set_vertex(0, k, p.b[k]);
    sb.set_vertex(1, k, p.a[k]);
  }
  const std::vector<TrianglePairIndex> pairs = {{0, 0}, {1, 1}, {0, 1}, {1, 0}};
  const int n = static_cast<int>(pairs.size());
  std::vector<TrianglePairDistance> want(n), hybrid(n), batched(n), penalty(n);
  brute_force_scalar_distances(sa, sb, pairs.data(), n, want.data());
  HybridSettings hs;
  hs.newton_iterations = iterations;
  hs.tolerance = tolerance;
  hs.cutoff = cutoff;
  HybridCounters counters;
  hybrid_distances(sa, sb, pairs.data(), n, hs, 0, hybrid.data(), counters);
  hybrid_distances(sa, sb, pairs.data(), n, hs, batch, batched.data(), counters);
  penalty_distances(sa, sb, pairs.data(), n, hs, penalty.data(), counters);
  require(counters.penalty_pairs == 3 * n, "counters: penalty pairs");
  long long histogram = 0;
  for (long long h : counters.newton_histogram)
    histogram += h;
  require(histogram == counters.penalty_pairs, "counters: Newton histogram does not add up");

  for (int k = 0; k < n; ++k) {
    const TrianglePairDistance &w = want[k];
    for (const TrianglePairDistance *got : {&hybrid[k], &batched[k]}) {
      require(tri_fuzz::finite(*got), "hybrid: non-finite result");
      require(std::abs(got->normal.norm() - 1.0) <= 1e-12, "hybrid: normal not unit",
              got->normal.norm());
      if (std::isfinite(cutoff) && w.distance >= cutoff - rounding - sliver) {
        // Beyond (or at) the cutoff only the side matters; the distance is a bound.
        require(got->distance >= w.distance - rounding - sliver - tolerance,
                "hybrid: beyond-cutoff distance below brute force", got->distance, w.distance);
        if (w.distance > cutoff + rounding)
          require(!(got->distance < cutoff), "hybrid: in contact, brute force is not",
                  got->distance, w.distance);
        continue;
      }
      require(std::abs(got->distance - w.distance) <= tolerance + rounding + sliver,
              "hybrid: distance off brute force", got->distance, w.distance);
      require(got->intersecting == w.intersecting ||
                  std::max(got->distance, w.distance) <= band + tolerance + sliver,
              "hybrid: intersecting verdict differs from brute force", got->distance, w.distance);
      if (std::isfinite(cutoff))
        require(got->distance < cutoff, "hybrid: not in contact, brute force is", got->distance,
                w.distance);
    }
    require(penalty[k].normal.allFinite() && std::isfinite(penalty[k].distance),
            "penalty_distances: non-finite result");
    require(penalty[k].distance >= w.distance - rounding - sliver - band,
            "penalty_distances: below brute force", penalty[k].distance, w.distance);
  }
  return 0;
}
