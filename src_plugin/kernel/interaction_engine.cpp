#include "interaction_engine.h"

#include <algorithm>

namespace tri {

void InteractionEngine::prepare(std::size_t n, int threads) {
  if (static_cast<int>(scratch_.size()) < threads)
    scratch_.resize(threads);
  if (static_cast<int>(deferred_.size()) < threads)
    deferred_.resize(threads);
  thread_stats_.assign(threads, ThreadStats{});
  results_.assign(n, PairForceResult{});
  failed_task_ = n;
  failure_.clear();
}

void InteractionEngine::record_failure(std::size_t k, const char *what) {
#pragma omp critical(tri_engine_failure)
  if (k < failed_task_) {
    failed_task_ = k;
    failure_ = what;
  }
}

void InteractionEngine::finish() {
  tally_ = InteractionTally{};
  for (const ContactStats &s : thread_stats_) // counts: the order does not matter
    tally_.distance += s;
  for (const PairForceResult &r : results_)
    tally_.add(r);
}

void InteractionEngine::contribute(int atom, long long partner, const Eigen::Vector3d &force,
                                   const Eigen::Vector3d &torque) {
  Contribution c{atom, partner, {}, {}};
  for (int d = 0; d < 3; ++d) {
    c.force[d] = force[d];
    c.torque[d] = torque[d];
  }
  contributions_.push_back(c);
}

void InteractionEngine::apply(double **f, double **torque) {
  // Stable: two images of one partner (a periodic box smaller than a particle's reach) keep
  // the order they were contributed in.
  std::stable_sort(contributions_.begin(), contributions_.end(),
                   [](const Contribution &x, const Contribution &y) {
                     return x.atom != y.atom ? x.atom < y.atom : x.partner < y.partner;
                   });
  for (const Contribution &c : contributions_)
    for (int d = 0; d < 3; ++d) {
      f[c.atom][d] += c.force[d];
      torque[c.atom][d] += c.torque[d];
    }
}

std::size_t InteractionEngine::bytes() const {
  std::size_t b = results_.capacity() * sizeof(PairForceResult) +
                  contributions_.capacity() * sizeof(Contribution) +
                  thread_stats_.capacity() * sizeof(ThreadStats);
  for (const InteractionScratch &s : scratch_)
    b += sizeof(s) + s.bytes();
  for (const std::vector<long> &d : deferred_)
    b += sizeof(d) + d.capacity() * sizeof(long);
  return b;
}

} // namespace tri
