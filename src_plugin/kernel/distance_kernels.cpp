#include "distance_kernels.h"

#include "triangle_intersection.h"

#include <algorithm>
#include <cmath>

namespace tri {

HybridCounters &HybridCounters::operator+=(const HybridCounters &o) {
  penalty_pairs += o.penalty_pairs;
  fallbacks += o.fallbacks;
  retries += o.retries;
  for (int k = 0; k <= kMaxPenaltyIterations; ++k)
    newton_histogram[k] += o.newton_histogram[k];
  return *this;
}

namespace {

// Gathers pairs [first, first + n) into `block`, padding lanes n.. with lane 0.
void gather(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex *pairs, int n,
            TrianglePairBlock &block) {
  for (int l = 0; l < n; ++l)
    block.set_lane(l, a, pairs[l].a, b, pairs[l].b);
  for (int l = n; l < kPairLanes; ++l)
    block.copy_lane(0, l);
}

// Collects pairs for brute force and runs brute_force_block whenever kPairLanes are pending,
// so that a low fallback rate still fills the vector lanes.
class PendingBruteForce {
public:
  PendingBruteForce(const TriangleSoA &a, const TriangleSoA &b, TrianglePairDistance *out)
      : a_(a), b_(b), out_(out) {}
  ~PendingBruteForce() { flush(); }
  void add(const TrianglePairIndex &pair, int out_index) {
    block_.set_lane(n_, a_, pair.a, b_, pair.b);
    target_[n_++] = out_index;
    if (n_ == kPairLanes)
      flush();
  }
  void flush() {
    if (n_ == 0)
      return;
    for (int l = n_; l < kPairLanes; ++l)
      block_.copy_lane(0, l);
    TrianglePairDistance result[kPairLanes];
    brute_force_block(block_, n_, result);
    for (int l = 0; l < n_; ++l)
      out_[target_[l]] = result[l];
    n_ = 0;
  }

private:
  const TriangleSoA &a_, &b_;
  TrianglePairDistance *out_;
  TrianglePairBlock block_;
  int target_[kPairLanes];
  int n_ = 0;
};

TrianglePairDistance accepted_result(const PenaltyBlockResult &r, int l) {
  TrianglePairDistance d;
  d.distance = r.upper[l];
  d.point_a = {r.point_a[0][l], r.point_a[1][l], r.point_a[2][l]};
  d.point_b = {r.point_b[0][l], r.point_b[1][l], r.point_b[2][l]};
  d.normal = (d.point_b - d.point_a) / d.distance;
  d.intersecting = false;
  d.penetration_depth = 0.0;
  d.lower_bound = r.lower[l];
  return d;
}

// Penalty's verdict on one lane.
enum class Verdict { Accepted, BeyondCutoff, NeedsBruteForce };

Verdict verdict(const PenaltyBlockResult &r, int l, const HybridSettings &s) {
  const double upper = r.upper[l], lower = r.lower[l];
  if (lower >= s.cutoff)
    return Verdict::BeyondCutoff;
  if (lower > 0.0 && upper - lower <= s.tolerance && upper < s.cutoff)
    return Verdict::Accepted;
  return Verdict::NeedsBruteForce;
}

void count_newton(const PenaltyBlockResult &r, int n, HybridCounters &c) {
  c.penalty_pairs += n;
  for (int l = 0; l < n; ++l)
    ++c.newton_histogram[r.converged_at[l]];
}

// Collects the pairs the first penalty run could not certify and runs them again with
// HybridSettings::retry_iterations steps whenever kPairLanes are pending (full lanes, as
// PendingBruteForce); what the second run cannot certify either goes to brute force. Each
// lane's result depends on its pair only, so the grouping changes no bits.
class PendingRetry {
public:
  PendingRetry(const TriangleSoA &a, const TriangleSoA &b, const HybridSettings &s,
               TrianglePairDistance *out, PendingBruteForce &brute_force, HybridCounters &c)
      : a_(a), b_(b), s_(s), out_(out), brute_force_(brute_force), counters_(c) {}
  // `first`: the first run's result, lane `lane` of it, where the second run goes on.
  void add(const TrianglePairIndex &pair, int out_index, const PenaltyBlockResult &first,
           int lane) {
    block_.set_lane(n_, a_, pair.a, b_, pair.b);
    for (int k = 0; k < 4; ++k)
      start_[k][n_] = first.z[k][lane];
    pair_[n_] = pair;
    target_[n_++] = out_index;
    if (n_ == kPairLanes)
      flush();
  }
  void flush() {
    if (n_ == 0)
      return;
    for (int l = n_; l < kPairLanes; ++l) {
      block_.copy_lane(0, l);
      for (int k = 0; k < 4; ++k)
        start_[k][l] = start_[k][0];
    }
    penalty_block_resume(s_.retry_iterations - s_.newton_iterations, block_, start_, s_.penalty,
                         s_.tolerance, r_, n_);
    counters_.retries += n_;
    for (int l = 0; l < n_; ++l) {
      if (verdict(r_, l, s_) == Verdict::NeedsBruteForce) {
        brute_force_.add(pair_[l], target_[l]);
        ++counters_.fallbacks;
      } else {
        out_[target_[l]] = accepted_result(r_, l);
      }
    }
    n_ = 0;
  }

private:
  const TriangleSoA &a_, &b_;
  const HybridSettings &s_;
  TrianglePairDistance *out_;
  PendingBruteForce &brute_force_;
  HybridCounters &counters_;
  TrianglePairBlock block_;
  PenaltyBlockResult r_;
  alignas(64) double start_[4][kPairLanes];
  TrianglePairIndex pair_[kPairLanes];
  int target_[kPairLanes];
  int n_ = 0;
};

} // namespace

void brute_force_distances(const TriangleSoA &a, const TriangleSoA &b,
                           const TrianglePairIndex *pairs, int count, TrianglePairDistance *out) {
  TrianglePairBlock block;
  for (int first = 0; first < count; first += kPairLanes) {
    const int n = std::min(kPairLanes, count - first);
    gather(a, b, pairs + first, n, block);
    brute_force_block(block, n, out + first);
  }
}

void brute_force_scalar_distances(const TriangleSoA &a, const TriangleSoA &b,
                                  const TrianglePairIndex *pairs, int count,
                                  TrianglePairDistance *out) {
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d ta[3] = {a.vertex(pairs[k].a, 0), a.vertex(pairs[k].a, 1),
                                   a.vertex(pairs[k].a, 2)};
    const Eigen::Vector3d tb[3] = {b.vertex(pairs[k].b, 0), b.vertex(pairs[k].b, 1),
                                   b.vertex(pairs[k].b, 2)};
    out[k] = triangle_distance(ta, tb);
  }
}

void penalty_distances(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex *pairs,
                       int count, const HybridSettings &settings, TrianglePairDistance *out,
                       HybridCounters &counters) {
  TrianglePairBlock block;
  PenaltyBlockResult r;
  for (int first = 0; first < count; first += kPairLanes) {
    const int n = std::min(kPairLanes, count - first);
    gather(a, b, pairs + first, n, block);
    penalty_block(settings.newton_iterations, block, settings.penalty, settings.tolerance, r, n);
    count_newton(r, n, counters);
    for (int l = 0; l < n; ++l) {
      Eigen::Vector3d ta[3], tb[3];
      block.get_lane(l, ta, tb);
      double l2 = 0.0;
      for (int k = 0; k < 3; ++k)
        l2 = std::max(
            {l2, (ta[(k + 1) % 3] - ta[k]).squaredNorm(), (tb[(k + 1) % 3] - tb[k]).squaredNorm()});
      if (r.upper[l] > kTouchRatio * std::sqrt(l2)) {
        out[first + l] = accepted_result(r, l);
      } else {
        TrianglePairDistance &d = out[first + l];
        d.distance = 0.0;
        d.point_a = d.point_b = {r.point_a[0][l], r.point_a[1][l], r.point_a[2][l]};
        const SeparatingAxis axis = min_overlap_axis(ta, tb);
        d.normal = axis.normal;
        d.penetration_depth = axis.depth;
        d.intersecting = true;
      }
    }
  }
}

void hybrid_distances(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex *pairs,
                      int count, const HybridSettings &settings, int batch_size,
                      TrianglePairDistance *out, HybridCounters &counters) {
  TrianglePairBlock block;
  PenaltyBlockResult r;
  PendingBruteForce pending(a, b, out);
  const auto run_penalty = [&](int first, int n) {
    gather(a, b, pairs + first, n, block);
    penalty_block(settings.newton_iterations, block, settings.penalty, settings.tolerance, r, n);
    count_newton(r, n, counters);
  };
  if (batch_size <= 0) {
    const bool retry = settings.retry_iterations > settings.newton_iterations &&
                       penalty_resume_supported(settings.retry_iterations -
                                                settings.newton_iterations);
    PendingRetry again(a, b, settings, out, pending, counters);
    for (int first = 0; first < count; first += kPairLanes) {
      const int n = std::min(kPairLanes, count - first);
      run_penalty(first, n);
      for (int l = 0; l < n; ++l) {
        const Verdict v = verdict(r, l, settings);
        if (v != Verdict::NeedsBruteForce) {
          out[first + l] = accepted_result(r, l);
        } else if (retry) {
          again.add(pairs[first + l], first + l, r, l);
        } else {
          pending.add(pairs[first + l], first + l);
          ++counters.fallbacks;
        }
      }
    }
    again.flush(); // before `pending` flushes (its destructor): it may add to it
    return;
  }
  for (int batch = 0; batch < count; batch += batch_size) {
    const int batch_end = std::min(count, batch + batch_size);
    bool batch_ok = true;
    for (int first = batch; first < batch_end; first += kPairLanes) {
      const int n = std::min(kPairLanes, batch_end - first);
      run_penalty(first, n);
      for (int l = 0; l < n; ++l) {
        batch_ok &= verdict(r, l, settings) != Verdict::NeedsBruteForce;
        out[first + l] = accepted_result(r, l);
      }
    }
    if (!batch_ok) {
      for (int k = batch; k < batch_end; ++k)
        pending.add(pairs[k], k);
      counters.fallbacks += batch_end - batch;
    }
  }
}

} // namespace tri
