#include "interaction/interaction_engine.h"

#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

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

// The results' tally in blocks of kTallyTasks tasks, on the run's threads, the blocks added in
// order: the energy's sum depends on the blocks, which do not depend on the thread count.
void InteractionEngine::finish() {
  tally_ = InteractionTally{};
  for (const ContactStats &s : thread_stats_) // counts: the order does not matter
    tally_.distance += s;
  const std::size_t n = results_.size();
  const long blocks = static_cast<long>((n + kTallyTasks - 1) / kTallyTasks);
  block_tallies_.assign(static_cast<std::size_t>(blocks), InteractionTally{});
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1 && blocks > 1)
  for (long b = 0; b < blocks; ++b) {
    InteractionTally &t = block_tallies_[static_cast<std::size_t>(b)];
    const std::size_t first = static_cast<std::size_t>(b) * kTallyTasks;
    for (std::size_t k = first; k < std::min(n, first + kTallyTasks); ++k)
      t.add(results_[k]);
  }
  for (const InteractionTally &t : block_tallies_)
    tally_ += t;
}

void InteractionEngine::apply(double **f, double **torque) {
  int atoms = 0;
  for (const Recipients &r : recipients_)
    atoms = std::max(atoms, std::max(r.a, r.b) + 1);
  // On the last run's threads, each summing a contiguous share of the atoms: every atom's
  // terms are summed by one thread, in the same order as by one thread alone.
  const int shares =
      threads_ > 1 && recipients_.size() >= kApplyTasksPerThread * static_cast<std::size_t>(threads_)
          ? threads_
          : 1;
  if (static_cast<int>(shares_.size()) < shares)
    shares_.resize(static_cast<std::size_t>(shares));
  used_shares_ = shares;
  if (shares == 1) {
    sum_share(shares_[0], 0, atoms, f, torque);
    return;
  }
#pragma omp parallel num_threads(shares)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    const long first = static_cast<long>(atoms) * t / shares;
    const long last = static_cast<long>(atoms) * (t + 1) / shares;
    sum_share(shares_[static_cast<std::size_t>(t)], static_cast<int>(first),
              static_cast<int>(last), f, torque);
  }
}

// The order of a stable sort by (atom, partner): two images of one partner (a periodic box
// smaller than a particle's reach) keep their tasks' order. A counting sort of the sides'
// indices by atom (stable), then each atom's few by partner (insertion sort, stable): a
// comparison sort of the whole list was 6 % of a settled pile's step.
void InteractionEngine::sum_share(AtomShare &share, int first_atom, int last_atom, double **f,
                                  double **torque) {
  std::vector<Contribution> &from_list = share.contributions;
  from_list.clear();
  for (std::size_t k = 0; k < recipients_.size(); ++k) {
    const Recipients &r = recipients_[k];
    if (r.a >= first_atom && r.a < last_atom)
      from_list.push_back({r.a, r.partner_of_a, static_cast<std::uint32_t>(k), 0});
    if (r.b >= first_atom && r.b < last_atom)
      from_list.push_back({r.b, r.partner_of_b, static_cast<std::uint32_t>(k), 1});
  }
  const std::size_t atoms = static_cast<std::size_t>(std::max(last_atom - first_atom, 0));
  std::vector<std::size_t> &first = share.first_of_atom;
  first.assign(atoms + 1, 0);
  for (const Contribution &c : from_list)
    ++first[static_cast<std::size_t>(c.atom - first_atom) + 1];
  for (std::size_t a = 0; a < atoms; ++a)
    first[a + 1] += first[a];
  share.sorted.resize(from_list.size());
  std::vector<std::size_t> &next = share.next_of_atom;
  next.assign(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < from_list.size(); ++i)
    share.sorted[next[static_cast<std::size_t>(from_list[i].atom - first_atom)]++] =
        static_cast<std::uint32_t>(i);
  const Contribution *const from = from_list.data();
  const PairForceResult *const results = results_.data();
  std::uint32_t *const order = share.sorted.data();
  for (std::size_t a = 0; a < atoms; ++a) {
    const std::size_t begin = first[a], end = first[a + 1];
    for (std::size_t i = begin + 1; i < end; ++i)
      for (std::size_t j = i; j > begin && from[order[j]].partner < from[order[j - 1]].partner; --j)
        std::swap(order[j], order[j - 1]);
    double *const fa = f[first_atom + static_cast<long>(a)];
    double *const ta = torque[first_atom + static_cast<long>(a)];
    for (std::size_t i = begin; i < end; ++i) {
      const Contribution &c = from[order[i]];
      const PairForceResult &r = results[c.task];
      const Eigen::Vector3d &t = c.side == 0 ? r.torque_a : r.torque_b;
      for (int d = 0; d < 3; ++d) {
        fa[d] += c.side == 0 ? r.force_a[d] : -r.force_a[d];
        ta[d] += t[d];
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
    for (std::size_t k = 0; k < recipients_.size(); ++k) // task order, a before b
      for (int side = 0; side < 2; ++side) {
        const int atom = side == 0 ? recipients_[k].a : recipients_[k].b;
        if (atom < 0)
          continue;
        const Virial v = side_virial({atom, 0, static_cast<std::uint32_t>(k), side});
        for (int d = 0; d < 6; ++d)
          global[d] += v[d];
      }
  if (vatom)
    for (int s = 0; s < used_shares_; ++s) { // apply()'s order
      const AtomShare &share = shares_[static_cast<std::size_t>(s)];
      for (std::uint32_t i : share.sorted) {
        const Contribution &c = share.contributions[i];
        const Virial v = side_virial(c);
        for (int d = 0; d < 6; ++d)
          vatom[c.atom][d] += v[d];
      }
    }
}

std::size_t InteractionEngine::bytes() const {
  std::size_t b = results_.capacity() * sizeof(PairForceResult) +
                  block_tallies_.capacity() * sizeof(InteractionTally) +
                  recipients_.capacity() * sizeof(Recipients) +
                  thread_stats_.capacity() * sizeof(ThreadStats) +
                  record_ranges_.capacity() * sizeof(RecordRange);
  for (const AtomShare &s : shares_)
    b += sizeof(s) + s.contributions.capacity() * sizeof(Contribution) +
         s.sorted.capacity() * sizeof(std::uint32_t) +
         (s.first_of_atom.capacity() + s.next_of_atom.capacity()) * sizeof(std::size_t);
  for (const InteractionScratch &s : scratch_)
    b += sizeof(s) + s.bytes();
  for (const ThreadQueue &q : queues_)
    b += sizeof(q) + q.kernels.bytes() + q.tasks.capacity() * sizeof(long);
  return b;
}

} // namespace tri
