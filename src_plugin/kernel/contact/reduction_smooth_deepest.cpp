// Step 5 of the reduction (README.md): a class without contact polygons gets the smooth
// maximum F of its members' overlaps, and its point, normal and force from F's gradient.
//
// With a_i = 1 - (D - o_i) / taper (D the largest o_i; only a_i > 0 count), w_i the member's
// share of its closest point, weights m_i = w_i a_i^2 / sum w_j a_j^2 and u <= 0 solving
// sum m_i (a_i - u)^2 = 1:
//   u = A - sqrt(A^2 + 1 - B),  A = sum w a^3 / sum w a^2,  B = sum w a^4 / sum w a^2,
//   F = D + g taper u,  g = smoothstep(D / taper) (F is 0 when a contact starts or ends).
// F = D for a lone deepest member and for any number tied with it, dips by at most a fraction
// of the taper in between, and is C1 in every o_i (a member enters with weight and slope 0).
// Its gradient: c_k = dF/do_k = g du/da_k, plus, shared by the members tied with the deepest
// in proportion to w_k, 1 + taper u g' - g sum_i du/da_i.
#include "contact/reduction_steps.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace tri::reduction {
namespace {

// The power sums of the active members' a_k, each weighted by its share w_k.
struct ShareSums {
  double s2 = 0.0, s3 = 0.0, s4 = 0.0;
};

// Each closest point counts once, however many triangle pairs see it: an edge crossing a
// face's edge is seen by up to four, and when a pair's closest point jumps from one end of a
// parallel edge to the other (two crossings tied in depth), the counts of the two points swap.
// Counted per member, the weights (and with them the point of the force) would jump there by a
// third of the distance between the points, so a member's share is 1 / (the active members at
// its point with its overlap). Ties within tie_band only: a merge or split then moves F by at
// most half of it. `weights` holds the a_k; `share` receives the w_k.
ShareSums closest_point_shares(const std::vector<Raw> &raw, const std::vector<int> &cands,
                               const SmoothDeepestBands &bands, const std::vector<double> &weights,
                               std::vector<double> &share) {
  const double tie_band = bands.tie_band;
  ShareSums sums;
  share.assign(cands.size(), 0.0);
  // Deepest first (the reduction's order, mostly): ties with a member are then a window
  // around it, since |o_j - o_k| only grows (rounding included) with the distance in order.
  bool sorted = true;
  for (std::size_t k = 1; k < cands.size(); ++k)
    sorted = sorted && raw[cands[k - 1]].overlap >= raw[cands[k]].overlap;
  const double same2 = bands.same_point * bands.same_point;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const double a = weights[k];
    if (!(a > 0.0))
      continue;
    const Raw &rk = raw[cands[k]];
    int count = 0;
    if (sorted) { // the members tied with k's overlap are the ones next to it
      std::size_t lo = k, hi = k + 1;
      while (lo > 0 && std::abs(raw[cands[lo - 1]].overlap - rk.overlap) <= tie_band)
        --lo;
      while (hi < cands.size() && std::abs(raw[cands[hi]].overlap - rk.overlap) <= tie_band)
        ++hi;
      for (std::size_t j = lo; j < hi; ++j)
        count += weights[j] > 0.0 && (raw[cands[j]].point - rk.point).squaredNorm() <= same2;
    } else {
      for (std::size_t j = 0; j < cands.size(); ++j) {
        const Raw &rj = raw[cands[j]];
        count += weights[j] > 0.0 && std::abs(rj.overlap - rk.overlap) <= tie_band &&
                 (rj.point - rk.point).squaredNorm() <= same2;
      }
    }
    const double w = 1.0 / std::max(1, count);
    share[k] = w;
    sums.s2 += w * a * a;
    sums.s3 += w * a * a * a;
    sums.s4 += w * a * a * a * a;
  }
  return sums;
}

} // namespace

SmoothDeepest smooth_deepest(const std::vector<Raw> &raw, const std::vector<int> &cands,
                             const SmoothDeepestBands &bands, const Vector3d &fallback_point,
                             const Vector3d &fallback_normal, std::vector<double> &weights,
                             std::vector<double> &share) {
  const double taper = bands.taper, tie_band = bands.tie_band;
  double D = -std::numeric_limits<double>::infinity();
  for (int i : cands)
    D = std::max(D, raw[i].overlap);
  int num_active = 0, last_active = 0;
  weights.resize(cands.size()); // a_k for now
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const double a = 1.0 - (D - raw[cands[k]].overlap) / taper;
    weights[k] = a;
    if (a > 0.0) {
      ++num_active;
      last_active = static_cast<int>(k);
    }
  }
  if (num_active == 1) { // the usual case: one deepest member, F = D, all of its gradient
    const Raw &d = raw[cands[last_active]];
    weights.assign(cands.size(), 0.0);
    weights[last_active] = 1.0;
    SmoothDeepest out;
    out.overlap = D;
    out.point = d.point;
    out.placing.extend(d.point);
    out.normal = finite(d.normal) ? d.normal : fallback_normal; // unit (raw_normal)
    return out;
  }
  const ShareSums sums = closest_point_shares(raw, cands, bands, weights, share);
  const double s2 = sums.s2, s3 = sums.s3, s4 = sums.s4;
  const double A = s3 / s2, B = s4 / s2; // s2 >= 1 to rounding: the deepest point has a = 1
  const double R = std::sqrt(std::max(0.0, A * A + 1.0 - B));
  const double u = A - R;
  const double x = D / taper;
  const double g = smoothstep(x);
  const double g_slope = x > 0.0 && x < 1.0 ? 6.0 * x * (1.0 - x) / taper : 0.0;
  // du/da_k = dA - (A dA - dB / 2) / R, dA = (3 a^2 s2 - 2 a s3) / s2^2, dB likewise.
  std::vector<double> &slope = weights; // a_k, then du/da_k, then c_k in place
  double sum_slope = 0.0;
  const double inv_s2s2 = 1.0 / (s2 * s2);
  for (std::size_t k = 0; k < slope.size(); ++k) {
    const double a = slope[k];
    double du = 0.0;
    if (a > 0.0 && R > 0.0) {
      const double dA = share[k] * (3.0 * a * s2 - 2.0 * s3) * a * inv_s2s2;
      const double dB = share[k] * (4.0 * a * a * s2 - 2.0 * s4) * a * inv_s2s2;
      du = dA - (A * dA - 0.5 * dB) / R;
    }
    slope[k] = du;
    sum_slope += du;
  }
  // The deepest's own part of the gradient, split over the members tied with it by their
  // shares: each tied point gets an equal part, however many pairs see it.
  SmoothDeepest out;
  double top_weight = 0.0;
  for (std::size_t k = 0; k < cands.size(); ++k)
    if (raw[cands[k]].overlap >= D - tie_band)
      top_weight += share[k];
  const double top_part = (1.0 + taper * u * g_slope - g * sum_slope) / top_weight;
  Vector3d sum_p = Vector3d::Zero(), sum_n = Vector3d::Zero();
  double sum_c = 0.0;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const Raw &d = raw[cands[k]];
    double c_k = g * slope[k];
    if (d.overlap >= D - tie_band)
      c_k += top_part * share[k];
    weights[k] = c_k;
    if (c_k == 0.0)
      continue;
    out.placing.extend(d.point);
    sum_p += c_k * d.point;
    sum_c += c_k;
    if (finite(d.normal))
      sum_n += c_k * d.normal;
  }
  out.overlap = D + taper * u * g;
  out.point = sum_c > 0.0 ? Vector3d(sum_p / sum_c) : fallback_point;
  const double len = sum_n.norm();
  if (std::isfinite(len) && len > 1e-3 * std::abs(sum_c)) {
    out.normal = sum_n / len;
    out.normal_scale = len;
    // F's gradient under rotation is the moment sum_k c_k x_k x n_k; one force N = sum c n
    // has it exactly, but for its part along N (a twist), when it acts at p + N x M / |N|^2
    // (M the moment about p, the weighted centroid): members with different normals at
    // different points (a gear's teeth) would otherwise turn the bodies the wrong amount.
    Vector3d moment = Vector3d::Zero();
    for (std::size_t k = 0; k < cands.size(); ++k)
      if (weights[k] != 0.0 && finite(raw[cands[k]].normal))
        moment += weights[k] * (raw[cands[k]].point - out.point).cross(raw[cands[k]].normal);
    const Vector3d shift = sum_n.cross(moment) / (len * len);
    if (finite(shift))
      out.point += shift;
  } else {
    out.normal = fallback_normal;
    out.normal_scale = sum_c;
  }
  return out;
}
} // namespace tri::reduction
