#include "distance/distance_kernels.h"

#include "geometry/triangle_intersection.h"

#include <algorithm>
#include <cmath>

namespace tri {

HybridCounters &HybridCounters::operator+=(const HybridCounters &o) {
  triangle_pairs_tested += o.triangle_pairs_tested;
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

// One block's lanes, filled pair by pair by the pools below, each of which runs its block
// once all kPairLanes are taken (or when flushed), the unused lanes padded with lane 0.
struct LaneFill {
  TrianglePairBlock block;
  int n = 0;
  // Takes the next lane; true when the block is full.
  bool take(const TriangleSoA &a, int ta, const TriangleSoA &b, int tb) {
    block.set_lane(n++, a, ta, b, tb);
    return n == kPairLanes;
  }
  // Pads the unused lanes and empties the fill for the next block; returns the lanes used.
  int drain() {
    for (int l = n; l < kPairLanes; ++l)
      block.copy_lane(0, l);
    const int used = n;
    n = 0;
    return used;
  }
};

// Collects pairs for brute force and runs brute_force_block whenever kPairLanes are pending,
// so that a low fallback rate still fills the vector lanes. Pairs may come from different
// triangle lists (body pairs).
class PendingBruteForce {
public:
  ~PendingBruteForce() { flush(); }
  void add(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex &pair,
           TrianglePairDistance *out) {
    target_[fill_.n] = out;
    if (fill_.take(a, pair.a, b, pair.b))
      flush();
  }
  void flush() {
    const int n = fill_.drain();
    if (n == 0)
      return;
    TrianglePairDistance result[kPairLanes];
    brute_force_block(fill_.block, n, result);
    for (int l = 0; l < n; ++l)
      *target_[l] = result[l];
  }

private:
  LaneFill fill_;
  TrianglePairDistance *target_[kPairLanes];
};

// Written field by field into the caller's slot, inlined: built as a value and assigned, the
// result went through a stack temporary and a second copy of its 104 bytes.
inline __attribute__((always_inline)) void store_accepted(const PenaltyBlockResult &r, int l,
                                                          TrianglePairDistance &d) {
  // The normal from the locals, not from the result's fields just stored: read back, those
  // stalled on store forwarding (two 8-byte stores, one 16-byte load).
  const double distance = r.upper[l];
  const Eigen::Vector3d a(r.point_a[0][l], r.point_a[1][l], r.point_a[2][l]);
  const Eigen::Vector3d b(r.point_b[0][l], r.point_b[1][l], r.point_b[2][l]);
  d.distance = distance;
  d.point_a = a;
  d.point_b = b;
  d.normal = (b - a) / distance;
  d.intersecting = false;
  d.penetration_depth = 0.0;
  d.lower_bound = r.lower[l];
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
// lane's result depends on its pair only, so the grouping changes no bits. Pairs may come
// from different body pairs; each lane keeps its own settings (tolerance, cutoff), and a pair
// whose penalty settings or step counts differ from the pending ones flushes them first.
class PendingRetry {
public:
  PendingRetry(PendingBruteForce &brute_force, HybridCounters &c)
      : brute_force_(brute_force), counters_(c) {}
  // `first`: the first run's result, lane `lane` of it, where the second run goes on.
  void add(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex &pair,
           const HybridSettings &s, TrianglePairDistance *out, const PenaltyBlockResult &first,
           int lane) {
    if (fill_.n > 0 && !same_run(*settings_[0], s))
      flush();
    const int l = fill_.n;
    for (int k = 0; k < 4; ++k)
      start_[k][l] = first.z[k][lane];
    a_[l] = &a;
    b_[l] = &b;
    pair_[l] = pair;
    settings_[l] = &s;
    target_[l] = out;
    if (fill_.take(a, pair.a, b, pair.b))
      flush();
  }
  void flush() {
    const int n = fill_.drain();
    if (n == 0)
      return;
    for (int l = n; l < kPairLanes; ++l)
      for (int k = 0; k < 4; ++k)
        start_[k][l] = start_[k][0];
    const HybridSettings &s = *settings_[0];
    penalty_block_resume(s.retry_iterations - s.newton_iterations, fill_.block, start_, s.penalty,
                         s.tolerance, r_, n);
    counters_.retries += n;
    for (int l = 0; l < n; ++l) {
      if (verdict(r_, l, *settings_[l]) == Verdict::NeedsBruteForce) {
        brute_force_.add(*a_[l], *b_[l], pair_[l], target_[l]);
        ++counters_.fallbacks;
      } else {
        store_accepted(r_, l, *target_[l]);
      }
    }
  }

private:
  // Whether two pairs' second runs are the same computation (the lanes of one block).
  static bool same_run(const HybridSettings &x, const HybridSettings &y) {
    return x.newton_iterations == y.newton_iterations && x.retry_iterations == y.retry_iterations &&
           x.penalty == y.penalty && x.tolerance == y.tolerance;
  }
  PendingBruteForce &brute_force_;
  HybridCounters &counters_;
  LaneFill fill_;
  PenaltyBlockResult r_;
  alignas(64) double start_[4][kPairLanes];
  const TriangleSoA *a_[kPairLanes], *b_[kPairLanes];
  TrianglePairIndex pair_[kPairLanes];
  const HybridSettings *settings_[kPairLanes];
  TrianglePairDistance *target_[kPairLanes];
};

bool retries(const HybridSettings &s) {
  return s.retry_iterations > s.newton_iterations &&
         penalty_resume_supported(s.retry_iterations - s.newton_iterations);
}

// The first penalty run of the unbatched hybrid, on blocks filled across jobs (a body pair's
// list is mostly shorter than a block); each lane's verdict with its own job's settings, and
// what it cannot certify handed to the retry pool (or straight to brute force).
class PendingFirst {
public:
  PendingFirst(PendingRetry &again, PendingBruteForce &brute_force, HybridCounters &c)
      : again_(again), brute_force_(brute_force), counters_(c) {}
  // Before a job's pairs: flushes the pending lanes if the job's first run differs from theirs.
  void begin(const HybridJob &job) {
    if (fill_.n > 0 && !same_run(*job_[0], job))
      flush();
  }
  // Pair k of the job last begun.
  void add(const HybridJob &job, int k) {
    job_[fill_.n] = &job;
    index_[fill_.n] = k;
    if (fill_.take(*job.a, job.pairs[k].a, *job.b, job.pairs[k].b))
      flush();
  }
  void flush() {
    const int n = fill_.drain();
    if (n == 0)
      return;
    const HybridSettings &first = job_[0]->settings;
    penalty_block(first.newton_iterations, fill_.block, first.penalty, first.tolerance, r_, n);
    count_newton(r_, n, counters_);
    for (int l = 0; l < n; ++l) {
      const HybridJob &job = *job_[l];
      const int k = index_[l];
      if (verdict(r_, l, job.settings) != Verdict::NeedsBruteForce) {
        store_accepted(r_, l, job.out[k]);
      } else if (retries(job.settings)) {
        again_.add(*job.a, *job.b, job.pairs[k], job.settings, job.out + k, r_, l);
      } else {
        brute_force_.add(*job.a, *job.b, job.pairs[k], job.out + k);
        ++counters_.fallbacks;
      }
    }
  }

private:
  // Whether two jobs' first runs are the same computation (the lanes of one block). The step
  // tolerance only feeds the Newton histogram, which is per lane.
  static bool same_run(const HybridJob &x, const HybridJob &y) {
    return x.settings.newton_iterations == y.settings.newton_iterations &&
           x.settings.penalty == y.settings.penalty && x.settings.tolerance == y.settings.tolerance;
  }
  PendingRetry &again_;
  PendingBruteForce &brute_force_;
  HybridCounters &counters_;
  LaneFill fill_;
  PenaltyBlockResult r_;
  const HybridJob *job_[kPairLanes];
  int index_[kPairLanes];
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
        store_accepted(r, l, out[first + l]);
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
  if (batch_size <= 0) {
    const HybridJob job{&a, &b, pairs, count, settings, out};
    return hybrid_distances_jobs(&job, 1, counters);
  }
  TrianglePairBlock block;
  PenaltyBlockResult r;
  PendingBruteForce pending;
  const auto run_penalty = [&](int first, int n) {
    gather(a, b, pairs + first, n, block);
    penalty_block(settings.newton_iterations, block, settings.penalty, settings.tolerance, r, n);
    count_newton(r, n, counters);
  };
  for (int batch = 0; batch < count; batch += batch_size) {
    const int batch_end = std::min(count, batch + batch_size);
    bool batch_ok = true;
    for (int first = batch; first < batch_end; first += kPairLanes) {
      const int n = std::min(kPairLanes, batch_end - first);
      run_penalty(first, n);
      for (int l = 0; l < n; ++l) {
        batch_ok &= verdict(r, l, settings) != Verdict::NeedsBruteForce;
        store_accepted(r, l, out[first + l]);
      }
    }
    if (!batch_ok) {
      for (int k = batch; k < batch_end; ++k)
        pending.add(a, b, pairs[k], out + k);
      counters.fallbacks += batch_end - batch;
    }
  }
}

namespace {

// The jobs' pair lists and triangles are scattered over the heap (each body pair's kept list,
// each particle's world-frame triangles) and mostly out of cache: the gather of a block waited
// on its loads. While job j runs, job j + 3's triangles and job j + 4's list are fetched: a
// job's dozen pairs take less than a miss to memory, and with one job ahead the gather still
// waited (paired runs, the formed hopper: 3 ahead 4-6 % faster than 1; 6 ahead no better).
void prefetch_list(const HybridJob &job) {
  const char *p = reinterpret_cast<const char *>(job.pairs);
  const std::size_t bytes = static_cast<std::size_t>(job.count) * sizeof(TrianglePairIndex);
  for (std::size_t offset = 0; offset < bytes; offset += 64)
    __builtin_prefetch(p + offset);
  const char *q = reinterpret_cast<const char *>(job.lower);
  const std::size_t lower_bytes = static_cast<std::size_t>(job.count) * sizeof(double);
  for (std::size_t offset = 0; q && offset < lower_bytes; offset += 64)
    __builtin_prefetch(q + offset);
}
void prefetch_triangles(const HybridJob &job) {
  for (int k = 0; k < job.count; ++k) {
    const std::size_t ia = 3 * static_cast<std::size_t>(job.pairs[k].a);
    const std::size_t ib = 3 * static_cast<std::size_t>(job.pairs[k].b);
    __builtin_prefetch(job.a->x.data() + ia);
    __builtin_prefetch(job.a->y.data() + ia);
    __builtin_prefetch(job.a->z.data() + ia);
    __builtin_prefetch(job.b->x.data() + ib);
    __builtin_prefetch(job.b->y.data() + ib);
    __builtin_prefetch(job.b->z.data() + ib);
  }
}

} // namespace

void hybrid_distances_jobs(const HybridJob *jobs, int num_jobs, HybridCounters &counters) {
  PendingBruteForce pending;
  PendingRetry again(pending, counters);
  PendingFirst first(again, pending, counters);
  for (int j = 0; j < std::min(num_jobs, 4); ++j)
    prefetch_list(jobs[j]);
  for (int j = 0; j < std::min(num_jobs, 3); ++j)
    prefetch_triangles(jobs[j]);
  for (int j = 0; j < num_jobs; ++j) {
    if (j + 4 < num_jobs)
      prefetch_list(jobs[j + 4]);
    if (j + 3 < num_jobs)
      prefetch_triangles(jobs[j + 3]);
    const HybridJob &job = jobs[j];
    const bool bounded = job.lower && std::isfinite(job.skip_from);
    first.begin(job);
    for (int k = 0; k < job.count; ++k) {
      if (bounded && job.lower[k] >= job.skip_from) { // cannot be within the cutoff
        job.out[k].distance = std::numeric_limits<double>::infinity();
        --counters.triangle_pairs_tested;
      } else {
        first.add(job, k);
      }
    }
  }
  first.flush(); // before `again`, which it may add to, and `pending` (its destructor)
  again.flush();
}

} // namespace tri
