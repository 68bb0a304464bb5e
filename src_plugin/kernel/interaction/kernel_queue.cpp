#include "interaction/kernel_queue.h"

namespace tri {

void KernelQueue::add(const KernelRequest &request) {
  requests_.push_back(request);
  if (request.candidates == CandidateList::kept) {
    copied_from_.push_back(-1);
    return;
  }
  copied_from_.push_back(static_cast<std::ptrdiff_t>(copied_pairs_.size()));
  copied_pairs_.insert(copied_pairs_.end(), request.job.pairs,
                       request.job.pairs + request.job.count);
}

void KernelQueue::run(HybridCounters &stats) {
  std::size_t total = 0;
  offsets_.resize(requests_.size());
  for (std::size_t j = 0; j < requests_.size(); ++j) {
    offsets_[j] = total;
    total += static_cast<std::size_t>(requests_[j].job.count);
  }
  results_.resize(total);
  jobs_.resize(requests_.size());
  for (std::size_t j = 0; j < requests_.size(); ++j) {
    HybridJob &job = requests_[j].job;
    job.out = results_.data() + offsets_[j];
    if (copied_from_[j] >= 0) // copied_pairs_ has stopped growing: pointers now
      job.pairs = copied_pairs_.data() + copied_from_[j];
    jobs_[j] = job;
  }
  hybrid_distances_jobs(jobs_.data(), static_cast<int>(jobs_.size()), stats);
}

void KernelQueue::clear() {
  requests_.clear();
  copied_from_.clear();
  copied_pairs_.clear();
  jobs_.clear();
  offsets_.clear();
}

std::size_t KernelQueue::bytes() const {
  return requests_.capacity() * sizeof(KernelRequest) +
         copied_from_.capacity() * sizeof(std::ptrdiff_t) +
         copied_pairs_.capacity() * sizeof(TrianglePairIndex) +
         jobs_.capacity() * sizeof(HybridJob) + offsets_.capacity() * sizeof(std::size_t) +
         results_.capacity() * sizeof(TrianglePairDistance);
}

} // namespace tri
