// Penalty distance of triangle pairs (paper, section 3), vectorised across the pairs of a
// TrianglePairBlock.
//
// With barycentric unknowns z = (a, b, c, d), x_a = A0 + a (A1 - A0) + b (A2 - A0) on
// triangle a and x_b = B0 + c (B1 - B0) + d (B2 - B0) on triangle b, minimise
//   1/2 |x_a - x_b|^2 + alpha/2 * sum_k max(0, c_k)^2,
//   c = (-a, -b, a + b - 1, -c, -d, c + d - 1),
// from the centroids (all 1/3) with `Iterations` quasi-Newton steps
//   (H + beta I) dz = -grad,  H = J^T J + alpha * sum_{k: c_k > 0} grad c_k grad c_k^T,
// (the generalised Hessian of the piecewise quadratic objective) solved by an unrolled 4x4
// LDL^T, each step shortened to at most max_step in its largest component
// (PenaltyParameters). The iteration count is a template parameter and the loop has no
// branches (max/compare-select only), so it vectorises across pairs.
//
// Scaling: the objective is ~ s^2 |dz|^2 with s^2 the mean squared edge of the two
// triangles, so alpha = penalty_weight * s^2 and beta = regularisation * s^2 and the
// iteration is the same at every scale (tested 1e-6 .. 1e3). The penalty optimum leaves
// constraints violated by ~ distance / (penalty_weight * s), i.e. a positional error
// ~ distance / penalty_weight; see the defaults below.
//
// Geometric error (length units): the final barycentrics are made feasible (clamped at 0
// and scaled back onto a + b <= 1), giving points p in a and q in b. Then
//   upper = |q - p|                  >= true distance (p and q are points of the triangles)
//   lower = min_k n.B_k - max_k n.A_k  <= true distance, n = (q - p) / |q - p|
// (the gap of the triangles' projections on any unit axis never exceeds their distance).
// upper - lower bounds the error of `upper`; it is 0 when p, q are the exact closest
// points of separated triangles. lower > 0 proves the triangles separated. Both are rigorous
// up to rounding, so callers can accept a result without comparing with brute force.
#pragma once

#include "distance/triangle_pair_block.h"

namespace tri {

struct PenaltyParameters {
  // alpha / s^2. The positional error at the penalty optimum is ~ distance / penalty_weight,
  // so 1e6 keeps it below 1e-6 of the distance; Newton with the exact generalised Hessian is
  // unaffected by the stiffness.
  double penalty_weight = 1e6;
  // beta / s^2. Only keeps H + beta I invertible where J^T J is singular (parallel edges or
  // faces, slivers); constant over the iterations (unlike the paper's reference code, which
  // grows it until the steps vanish), so a small step really means convergence.
  double regularisation = 1e-9;
  // Longest step in any barycentric unknown: a triangle's span. Generalised Newton on the
  // piecewise quadratic objective can cycle between active sets (seen: a period of three
  // steps between a corner and two points far outside the triangles, for ever); a step that
  // cannot cross a triangle in one go breaks such cycles. Of the triangle pairs a formed hopper
  // tests, the share the first 4 steps cannot certify falls from 22 % to 19 %, after 8 steps
  // from 5.9 % to 1.7 %. Steps within it, the last ones of a converging run, are unchanged.
  double max_step = 1.0;

  // Every field: the lanes of one block run with one set (distance_kernels.cpp).
  bool operator==(const PenaltyParameters &o) const {
    return penalty_weight == o.penalty_weight && regularisation == o.regularisation &&
           max_step == o.max_step;
  }
};

// Per-lane output of penalty_block; lengths in the input unit.
struct alignas(64) PenaltyBlockResult {
  double upper[kPairLanes];      // |q - p|, see above
  double lower[kPairLanes];      // separation along n, see above
  double point_a[3][kPairLanes]; // p (x, y, z)
  double point_b[3][kPairLanes]; // q
  int converged_at[kPairLanes];  // first iteration whose step s |dz|_2 was below
                                 // the step tolerance; 0 if none was
  double z[4][kPairLanes];       // the barycentric unknowns (a, b, c, d) after the last step,
                                 // before the clamping: where penalty_block_resume goes on
};

// Runs `Iterations` steps on the lanes of `block`: all of them, or, when the caller uses at
// most half (`used` <= kPairLanes / 2), only the first half, at half the cost; every lane's
// result is the same either way. `step_tolerance` (length) only feeds converged_at, the
// Newton histogram; it does not change the result.
template <int Iterations>
void penalty_block(const TrianglePairBlock &block, const PenaltyParameters &params,
                   double step_tolerance, PenaltyBlockResult &out, int used = kPairLanes);

// The iteration counts that are instantiated: 1..8, 10, 12, 16, 24, 32.
bool penalty_iterations_supported(int iterations);
constexpr int kMaxPenaltyIterations = 32;

// Run-time choice among the instantiated counts; throws std::invalid_argument otherwise.
void penalty_block(int iterations, const TrianglePairBlock &block, const PenaltyParameters &params,
                   double step_tolerance, PenaltyBlockResult &out, int used = kPairLanes);

// `Iterations` more steps from the unknowns `start` (a PenaltyBlockResult::z, lanes as in
// `block`) instead of the centroids: N steps and then M resumed steps give bit for bit the
// result of N + M steps (converged_at counts from the resumed start). The retry of the hybrid
// kernel (distance_kernels.h) goes on where the first run stopped. Instantiated for 4, 8, 12.
bool penalty_resume_supported(int iterations);
void penalty_block_resume(int iterations, const TrianglePairBlock &block,
                          const double (*start)[kPairLanes], const PenaltyParameters &params,
                          double step_tolerance, PenaltyBlockResult &out, int used = kPairLanes);

// Floating-point operations per pair, counted by hand from penalty_distance.cpp (FMA = 2),
// for the benchmark's GFLOP/s estimate only.
constexpr int kPenaltySetupFlops = 110, kPenaltyIterationFlops = 140, kPenaltyEpilogueFlops = 70;
constexpr int penalty_flops_per_pair(int iterations) {
  return kPenaltySetupFlops + iterations * kPenaltyIterationFlops + kPenaltyEpilogueFlops;
}

} // namespace tri
