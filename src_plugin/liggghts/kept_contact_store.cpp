#include "kept_contact_store.h"

#include <algorithm>
#include <cstring>

namespace tri_liggghts {

void KeptContactStore::begin_step(std::size_t slots) {
  ++step_;
  hints_.swap(next_hints_);
  next_hints_.assign(slots, {0, nullptr});
}

double *KeptContactStore::entry(std::size_t slot, std::uint64_t key) {
  // Each record is a node of its own, a miss per task: the one a few slots on is asked for now.
  if (slot + kHintAhead < hints_.size() && hints_[slot + kHintAhead].second)
    __builtin_prefetch(hints_[slot + kHintAhead].second);
  Record *r = slot < hints_.size() && hints_[slot].second && hints_[slot].first == key
                  ? hints_[slot].second
                  : nullptr;
  if (!r) {
    std::lock_guard<std::mutex> lock(records_mutex_);
    r = &records_[key];
  }
  if (slot >= next_hints_.size())
    next_hints_.resize(slot + 1, {0, nullptr});
  next_hints_[slot] = {key, r};
  if (r->step == step_)
    return nullptr; // another task's this step
  if (r->step < step_ - 1 && tri::kept_state(r->values.data()))
    tri::clear_kept_contacts(r->values.data()); // not asked for last step: starts afresh
  r->step = step_;
  return r->values.data();
}

void KeptContactStore::append(std::uint64_t key, const Record &r, std::vector<double> &parcel) {
  double k;
  std::memcpy(&k, &key, sizeof k);
  parcel.push_back(k);
  parcel.insert(parcel.end(), r.values.begin(), r.values.end());
}

void KeptContactStore::from_parcels(std::vector<std::vector<double>> &parcels, std::size_t count) {
  for (std::size_t i = 0; i < count && i < parcels.size(); ++i) {
    std::vector<double> &parcel = parcels[i];
    for (std::size_t at = 0; at + kParcelDoubles <= parcel.size(); at += kParcelDoubles) {
      std::uint64_t key;
      std::memcpy(&key, &parcel[at], sizeof key);
      auto [it, added] = records_.try_emplace(key);
      if (!added)
        continue;
      std::copy(parcel.begin() + static_cast<long>(at) + 1,
                parcel.begin() + static_cast<long>(at) + kParcelDoubles, it->second.values.begin());
      it->second.step = step_; // as asked for the step before the next one
    }
    parcel.clear();
  }
  hints_.clear();
  next_hints_.clear();
}

std::size_t KeptContactStore::bytes() const {
  return records_.size() * (sizeof(Record) + 2 * sizeof(void *) + sizeof(std::uint64_t)) +
         records_.bucket_count() * sizeof(void *) +
         (hints_.capacity() + next_hints_.capacity()) * sizeof(hints_[0]);
}

} // namespace tri_liggghts
