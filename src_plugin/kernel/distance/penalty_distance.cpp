#include "distance/penalty_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tri {

namespace {

#define TRI_LANE inline __attribute__((always_inline))

TRI_LANE double positive(double v) { return std::max(0.0, v); }
TRI_LANE double dot3(const double u[3], const double v[3]) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}

// One lane. A separate function so that its locals stay out of the caller's `omp simd`
// lowering (see brute_force_lane); after inlining everything is in registers.
template <int Iterations, bool Resume>
TRI_LANE void penalty_lane(const double (*c)[kPairLanes], int l, double weight, double reg,
                           double max_step, double step_tol2, const double (*start)[kPairLanes],
                           PenaltyBlockResult &out) {
  double a0[3], b0[3], col[4][3], r0[3];
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    a0[k] = c[k][l];
    b0[k] = c[9 + k][l];
    col[0][k] = c[3 + k][l] - a0[k];  // A1 - A0
    col[1][k] = c[6 + k][l] - a0[k];  // A2 - A0
    col[2][k] = b0[k] - c[12 + k][l]; // -(B1 - B0)
    col[3][k] = b0[k] - c[15 + k][l]; // -(B2 - B0)
    r0[k] = a0[k] - b0[k];
  }
  // J^T J and J^T r0; r(z) = r0 + J z.
  const double g00 = dot3(col[0], col[0]), g01 = dot3(col[0], col[1]), g02 = dot3(col[0], col[2]),
               g03 = dot3(col[0], col[3]);
  const double g11 = dot3(col[1], col[1]), g12 = dot3(col[1], col[2]), g13 = dot3(col[1], col[3]);
  const double g22 = dot3(col[2], col[2]), g23 = dot3(col[2], col[3]);
  const double g33 = dot3(col[3], col[3]);
  const double q0 = dot3(col[0], r0), q1 = dot3(col[1], r0), q2 = dot3(col[2], r0),
               q3 = dot3(col[3], r0);
  const double s2 = 0.25 * (g00 + g11 + g22 + g33);
  const double alpha = weight * s2, beta = reg * s2;
  const double tol2 = step_tol2 / s2; // step tolerance in barycentric units, squared

  double z0 = 1.0 / 3.0, z1 = 1.0 / 3.0, z2 = 1.0 / 3.0, z3 = 1.0 / 3.0;
  if constexpr (Resume) {
    z0 = start[0][l], z1 = start[1][l], z2 = start[2][l], z3 = start[3][l];
  }
  // The first iteration whose step was within tolerance, carried as a double: an int select
  // on a double comparison mixes mask widths, which g++ 12 does not vectorise. Without a select
  // at all: g++ 12 stops with an internal error on this loop's selects for plain x86-64 (no
  // SSE4.1 blend). -copysign(inf, tol2 - step2) is -inf where step2 <= tol2, else +inf (a
  // NaN step: either, by its sign; converged_at is a statistic only).
  double first_converged = INFINITY;
#pragma GCC unroll 32
  for (int it = 1; it <= Iterations; ++it) {
    // Penalty terms: violations of the six constraints and their active-set indicators.
    const double va = positive(-z0), vb = positive(-z1), vab = positive(z0 + z1 - 1.0);
    const double vc = positive(-z2), vd = positive(-z3), vcd = positive(z2 + z3 - 1.0);
    const double ia = z0 < 0.0 ? alpha : 0.0, ib = z1 < 0.0 ? alpha : 0.0;
    const double iab = z0 + z1 > 1.0 ? alpha : 0.0;
    const double ic = z2 < 0.0 ? alpha : 0.0, id = z3 < 0.0 ? alpha : 0.0;
    const double icd = z2 + z3 > 1.0 ? alpha : 0.0;
    const double grad0 = q0 + g00 * z0 + g01 * z1 + g02 * z2 + g03 * z3 + alpha * (vab - va);
    const double grad1 = q1 + g01 * z0 + g11 * z1 + g12 * z2 + g13 * z3 + alpha * (vab - vb);
    const double grad2 = q2 + g02 * z0 + g12 * z1 + g22 * z2 + g23 * z3 + alpha * (vcd - vc);
    const double grad3 = q3 + g03 * z0 + g13 * z1 + g23 * z2 + g33 * z3 + alpha * (vcd - vd);
    const double h00 = g00 + ia + iab + beta, h11 = g11 + ib + iab + beta;
    const double h22 = g22 + ic + icd + beta, h33 = g33 + id + icd + beta;
    const double h01 = g01 + iab, h23 = g23 + icd;
    // LDL^T of the symmetric positive definite H + beta I.
    const double d0 = h00, inv0 = 1.0 / d0;
    const double l10 = h01 * inv0, l20 = g02 * inv0, l30 = g03 * inv0;
    const double d1 = h11 - l10 * h01, inv1 = 1.0 / d1;
    const double l21 = (g12 - l20 * h01) * inv1, l31 = (g13 - l30 * h01) * inv1;
    const double d2 = h22 - l20 * g02 - l21 * l21 * d1, inv2 = 1.0 / d2;
    const double l32 = (h23 - l30 * g02 - l31 * l21 * d1) * inv2;
    const double d3 = h33 - l30 * g03 - l31 * l31 * d1 - l32 * l32 * d2, inv3 = 1.0 / d3;
    // Solve L D L^T dz = -grad.
    const double y0 = -grad0;
    const double y1 = -grad1 - l10 * y0;
    const double y2 = -grad2 - l20 * y0 - l21 * y1;
    const double y3 = -grad3 - l30 * y0 - l31 * y1 - l32 * y2;
    const double x3 = y3 * inv3;
    const double x2 = y2 * inv2 - l32 * x3;
    const double x1 = y1 * inv1 - l21 * x2 - l31 * x3;
    const double x0 = y0 * inv0 - l10 * x1 - l20 * x2 - l30 * x3;
    // The step, shortened to max_step in its largest barycentric component (penalty_distance.h).
    const double longest =
        std::max(std::max(std::fabs(x0), std::fabs(x1)), std::max(std::fabs(x2), std::fabs(x3)));
    const double shorten = std::min(1.0, max_step / std::max(longest, 1e-300));
    z0 += shorten * x0, z1 += shorten * x1, z2 += shorten * x2, z3 += shorten * x3;
    const double step2 = shorten * shorten * (x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3);
    first_converged =
        std::min(first_converged, std::max(-std::copysign(INFINITY, tol2 - step2), double(it)));
  }

  out.z[0][l] = z0, out.z[1][l] = z1, out.z[2][l] = z2, out.z[3][l] = z3;
  // Feasible points: clamp at 0, scale back onto a + b <= 1.
  const double fa = positive(z0), fb = positive(z1), fc = positive(z2), fd = positive(z3);
  const double sab = 1.0 / std::max(1.0, fa + fb), scd = 1.0 / std::max(1.0, fc + fd);
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    const double p = a0[k] + (fa * sab) * col[0][k] + (fb * sab) * col[1][k];
    const double q = b0[k] - (fc * scd) * col[2][k] - (fd * scd) * col[3][k];
    out.point_a[k][l] = p;
    out.point_b[k][l] = q;
  }
  out.converged_at[l] = static_cast<int>(first_converged <= Iterations ? first_converged : 0.0);
}

// Second vectorised pass: the bounds, after the lanes' distances |q - p| (a loop of their own,
// vectorised since tri_kernel builds with -fno-math-errno).
TRI_LANE void bounds_lane(const double (*c)[kPairLanes], int l, PenaltyBlockResult &out) {
  double diff[3], n[3];
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k)
    diff[k] = out.point_b[k][l] - out.point_a[k][l];
  const double inv_upper = 1.0 / std::max(out.upper[l], 1e-300);
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k)
    n[k] = diff[k] * inv_upper;
  // Projections of the vertices on n: b's lowest minus a's highest.
  double a_hi = -INFINITY, b_lo = INFINITY;
#pragma GCC unroll 3
  for (int v = 0; v < 3; ++v) {
    a_hi = std::max(a_hi, n[0] * c[3 * v][l] + n[1] * c[3 * v + 1][l] + n[2] * c[3 * v + 2][l]);
    b_lo =
        std::min(b_lo, n[0] * c[9 + 3 * v][l] + n[1] * c[10 + 3 * v][l] + n[2] * c[11 + 3 * v][l]);
  }
  out.lower[l] = b_lo - a_hi;
}

// The first `Lanes` lanes of a block (the same per-lane code for any Lanes).
template <int Iterations, int Lanes, bool Resume>
void penalty_lanes(const TrianglePairBlock &block, const PenaltyParameters &params,
                   double step_tolerance, const double (*start)[kPairLanes],
                   PenaltyBlockResult &out) {
  const double weight = params.penalty_weight, reg = params.regularisation;
  const double max_step = params.max_step;
  const double step_tol2 = step_tolerance * step_tolerance;
#pragma omp simd
  for (int l = 0; l < Lanes; ++l)
    penalty_lane<Iterations, Resume>(block.c, l, weight, reg, max_step, step_tol2, start, out);
  for (int l = 0; l < Lanes; ++l) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = out.point_b[k][l] - out.point_a[k][l];
      d2 += d * d;
    }
    out.upper[l] = std::sqrt(d2);
  }
#pragma omp simd
  for (int l = 0; l < Lanes; ++l)
    bounds_lane(block.c, l, out);
}

} // namespace

template <int Iterations>
void penalty_block(const TrianglePairBlock &block, const PenaltyParameters &params,
                   double step_tolerance, PenaltyBlockResult &out, int used) {
  // A block with at most half its lanes used (the last of a short list) runs half a block:
  // each lane's result is the same bits either way (tested).
  if (used <= kPairLanes / 2)
    penalty_lanes<Iterations, kPairLanes / 2, false>(block, params, step_tolerance, nullptr, out);
  else
    penalty_lanes<Iterations, kPairLanes, false>(block, params, step_tolerance, nullptr, out);
}

template <int Iterations>
void penalty_block_resume(const TrianglePairBlock &block, const double (*start)[kPairLanes],
                          const PenaltyParameters &params, double step_tolerance,
                          PenaltyBlockResult &out, int used) {
  if (used <= kPairLanes / 2)
    penalty_lanes<Iterations, kPairLanes / 2, true>(block, params, step_tolerance, start, out);
  else
    penalty_lanes<Iterations, kPairLanes, true>(block, params, step_tolerance, start, out);
}

#define TRI_PENALTY_COUNTS(X) X(1) X(2) X(3) X(4) X(5) X(6) X(7) X(8) X(10) X(12) X(16) X(24) X(32)

#define TRI_INSTANTIATE(N)                                                                         \
  template void penalty_block<N>(const TrianglePairBlock &, const PenaltyParameters &, double,     \
                                 PenaltyBlockResult &, int);
TRI_PENALTY_COUNTS(TRI_INSTANTIATE)
#undef TRI_INSTANTIATE

// Resumed runs: only the counts a retry after the default 4 steps needs (4 more to 8, 8 more to 12, 12 more to 16).
template void penalty_block_resume<4>(const TrianglePairBlock &, const double (*)[kPairLanes],
                                      const PenaltyParameters &, double, PenaltyBlockResult &, int);
template void penalty_block_resume<8>(const TrianglePairBlock &, const double (*)[kPairLanes],
                                      const PenaltyParameters &, double, PenaltyBlockResult &, int);
template void penalty_block_resume<12>(const TrianglePairBlock &, const double (*)[kPairLanes],
                                       const PenaltyParameters &, double, PenaltyBlockResult &, int);

bool penalty_resume_supported(int iterations) {
  return iterations == 4 || iterations == 8 || iterations == 12;
}

void penalty_block_resume(int iterations, const TrianglePairBlock &block,
                          const double (*start)[kPairLanes], const PenaltyParameters &params,
                          double step_tolerance, PenaltyBlockResult &out, int used) {
  switch (iterations) {
  case 4:
    return penalty_block_resume<4>(block, start, params, step_tolerance, out, used);
  case 8:
    return penalty_block_resume<8>(block, start, params, step_tolerance, out, used);
  case 12:
    return penalty_block_resume<12>(block, start, params, step_tolerance, out, used);
  default:
    throw std::invalid_argument("penalty_block_resume: unsupported Newton iteration count " +
                                std::to_string(iterations));
  }
}

bool penalty_iterations_supported(int iterations) {
#define TRI_CASE(N) case N:
  switch (iterations) {
    TRI_PENALTY_COUNTS(TRI_CASE)
    return true;
  default:
    return false;
  }
#undef TRI_CASE
}

void penalty_block(int iterations, const TrianglePairBlock &block, const PenaltyParameters &params,
                   double step_tolerance, PenaltyBlockResult &out, int used) {
#define TRI_CASE(N)                                                                                \
  case N:                                                                                          \
    return penalty_block<N>(block, params, step_tolerance, out, used);
  switch (iterations) {
    TRI_PENALTY_COUNTS(TRI_CASE)
  default:
    throw std::invalid_argument("penalty_block: unsupported Newton iteration count " +
                                std::to_string(iterations));
  }
#undef TRI_CASE
}

} // namespace tri
