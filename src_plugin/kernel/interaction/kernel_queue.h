// The kernel requests of a group of body pairs (body_interaction.h: plan_body_pair), run
// together: hybrid_distances_jobs fills its vector lanes, retries and fallbacks across the
// pairs, and fetches the jobs' triangles well ahead (distance_kernels.cpp). Each pair's
// results are bitwise those of its job run alone. One queue per thread; the interaction engine
// fills it with a group's requests, runs it, and finishes each pair from its results.
#pragma once

#include "distance/distance_kernels.h"
#include "interaction/body_interaction.h"

#include <cstddef>
#include <vector>

namespace tri {

class KernelQueue {
public:
  // Queues `request` as job size() - 1. A search's pairs (CandidateList::searched...) are
  // copied now, since the next search with that scratch overwrites them; kept candidates stay
  // where they are (their owner does not change them before the pair is finished).
  void add(const KernelRequest &request);
  // Runs every queued job, the kernel's counters into `stats`. Throws what the kernel throws.
  void run(HybridCounters &stats);
  // After run(), until clear(): job j's request (its pairs where they now lie) and its
  // request.job.count results, in its pairs' order.
  const KernelRequest &request(std::size_t j) const { return requests_[j]; }
  const TrianglePairDistance *results(std::size_t j) const { return results_.data() + offsets_[j]; }
  std::size_t size() const { return requests_.size(); }
  bool empty() const { return requests_.empty(); }
  void clear();

  std::size_t bytes() const; // heap memory held

private:
  std::vector<KernelRequest> requests_;
  // Per job: where its copied pairs start in copied_pairs_; -1 for kept candidates.
  std::vector<std::ptrdiff_t> copied_from_;
  std::vector<TrianglePairIndex> copied_pairs_;
  std::vector<HybridJob> jobs_;      // the requests' jobs, as hybrid_distances_jobs takes them
  std::vector<std::size_t> offsets_; // job j's results: results_[offsets_[j]...]
  std::vector<TrianglePairDistance> results_;
};

} // namespace tri
