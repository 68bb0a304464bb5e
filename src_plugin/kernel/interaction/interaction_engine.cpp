#include "interaction/interaction_engine.h"

#include <algorithm>

namespace tri {

void InteractionEngine::prepare(std::size_t n, int threads) {
  if (static_cast<int>(scratch_.size()) < threads)
    scratch_.resize(threads);
  if (static_cast<int>(queues_.size()) < threads)
    queues_.resize(threads);
  thread_stats_.assign(threads, ThreadStats{});
  // Every task writes its slot (record_failure those that throw): no fill of all of them.
  results_.resize(n);
  recipients_.assign(n, Recipients{});
  for (int t = 0; t < threads; ++t) {
    scratch_[t].record_contacts = record_;
    scratch_[t].records.clear();
  }
  if (record_)
    record_ranges_.assign(n, RecordRange{});
  failed_task_ = n;
  failure_.clear();
}

void InteractionEngine::split_groups(long groups, int threads) {
  if (num_ranges_ < threads) {
    ranges_.reset(new GroupRange[static_cast<std::size_t>(threads)]);
    num_ranges_ = threads;
  }
  for (int t = 0; t < threads; ++t) {
    const auto front = static_cast<std::uint64_t>(groups * t / threads);
    const auto back = static_cast<std::uint64_t>(groups * (t + 1) / threads);
    ranges_[t].bounds.store(front << 32 | back, std::memory_order_relaxed);
  }
  for (int t = threads; t < num_ranges_; ++t)
    ranges_[t].bounds.store(0, std::memory_order_relaxed);
}

long InteractionEngine::take_group(int range, int thread) {
  std::atomic<std::uint64_t> &bounds = ranges_[range].bounds;
  std::uint64_t now = bounds.load(std::memory_order_relaxed);
  for (;;) {
    const std::uint64_t front = now >> 32, back = now & 0xffffffffu;
    if (front >= back)
      return -1;
    const bool own = range == thread;
    const std::uint64_t next = own ? (front + 1) << 32 | back : front << 32 | (back - 1);
    if (bounds.compare_exchange_weak(now, next, std::memory_order_relaxed))
      return static_cast<long>(own ? front : back - 1);
  }
}

void InteractionEngine::record_failure(std::size_t k, const char *what) {
  results_[k] = PairForceResult{}; // the task's own slot: no other thread writes it
  if (record_)
    record_ranges_[k] = RecordRange{};
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

void InteractionEngine::apply(double **f, double **torque) {
  // The order of a stable sort by (atom, partner): two images of one partner (a periodic box
  // smaller than a particle's reach) keep their tasks' order. A counting sort of the sides'
  // indices by atom (stable), then each atom's few by partner (insertion sort, stable): a
  // comparison sort of the whole list was 6 % of a settled pile's step. (Summing the atoms on
  // the run's threads measured slower on 2 threads: the fork cost more than the sums.)
  contributions_.clear();
  for (std::size_t k = 0; k < recipients_.size(); ++k) {
    const Recipients &r = recipients_[k];
    if (r.a >= 0)
      contributions_.push_back({r.a, r.partner_of_a, static_cast<std::uint32_t>(k), 0});
    if (r.b >= 0)
      contributions_.push_back({r.b, r.partner_of_b, static_cast<std::uint32_t>(k), 1});
  }
  int atoms = 0;
  for (const Contribution &c : contributions_)
    atoms = std::max(atoms, c.atom + 1);
  first_of_atom_.assign(static_cast<std::size_t>(atoms) + 1, 0);
  for (const Contribution &c : contributions_)
    ++first_of_atom_[static_cast<std::size_t>(c.atom) + 1];
  for (int a = 0; a < atoms; ++a)
    first_of_atom_[a + 1] += first_of_atom_[a];
  sorted_.resize(contributions_.size());
  {
    std::vector<std::size_t> &next = next_of_atom_;
    next.assign(first_of_atom_.begin(), first_of_atom_.end() - 1);
    for (std::size_t i = 0; i < contributions_.size(); ++i)
      sorted_[next[contributions_[i].atom]++] = static_cast<std::uint32_t>(i);
  }
  const Contribution *const from = contributions_.data();
  const PairForceResult *const results = results_.data();
  std::uint32_t *const order = sorted_.data();
  const std::size_t *const first = first_of_atom_.data();
  for (int a = 0; a < atoms; ++a) {
    const std::size_t begin = first[a], end = first[a + 1];
    for (std::size_t i = begin + 1; i < end; ++i)
      for (std::size_t j = i; j > begin && from[order[j]].partner < from[order[j - 1]].partner; --j)
        std::swap(order[j], order[j - 1]);
    for (std::size_t i = begin; i < end; ++i) {
      const Contribution &c = from[order[i]];
      const PairForceResult &r = results[c.task];
      const Eigen::Vector3d &t = c.side == 0 ? r.torque_a : r.torque_b;
      for (int d = 0; d < 3; ++d) {
        f[a][d] += c.side == 0 ? r.force_a[d] : -r.force_a[d];
        torque[a][d] += t[d];
      }
    }
  }
}

InteractionEngine::Records InteractionEngine::records(std::size_t k) const {
  if (!record_ || k >= record_ranges_.size())
    return {};
  const RecordRange &r = record_ranges_[k];
  return {scratch_[r.thread].records.data() + r.begin, r.end - r.begin};
}

Virial InteractionEngine::side_virial(const Contribution &c) const {
  Virial v{};
  for (const ContactRecord &rec : records(c.task)) {
    const Virial &w = c.side == 0 ? rec.virial_a : rec.virial_b;
    for (int d = 0; d < 6; ++d)
      v[d] += w[d];
  }
  return v;
}

void InteractionEngine::add_virial(double *global, double **vatom) const {
  if (!record_)
    return;
  if (global)
    for (const Contribution &c : contributions_) { // task order
      const Virial v = side_virial(c);
      for (int d = 0; d < 6; ++d)
        global[d] += v[d];
    }
  if (vatom)
    for (std::size_t i = 0; i < sorted_.size(); ++i) { // apply()'s order
      const Contribution &c = contributions_[sorted_[i]];
      const Virial v = side_virial(c);
      for (int d = 0; d < 6; ++d)
        vatom[c.atom][d] += v[d];
    }
}

std::size_t InteractionEngine::bytes() const {
  std::size_t b = results_.capacity() * sizeof(PairForceResult) +
                  contributions_.capacity() * sizeof(Contribution) +
                  recipients_.capacity() * sizeof(Recipients) +
                  thread_stats_.capacity() * sizeof(ThreadStats) +
                  sorted_.capacity() * sizeof(std::uint32_t) +
                  (first_of_atom_.capacity() + next_of_atom_.capacity()) * sizeof(std::size_t) +
                  record_ranges_.capacity() * sizeof(RecordRange);
  for (const InteractionScratch &s : scratch_)
    b += sizeof(s) + s.bytes();
  for (const ThreadQueue &q : queues_)
    b += sizeof(q) + q.kernels.bytes() + q.tasks.capacity() * sizeof(long);
  return b;
}

} // namespace tri
