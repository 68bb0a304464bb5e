#include "candidate_store.h"

#include <algorithm>

namespace tri_liggghts {

void CandidateStore::end_step() {
  if (touched_ == entries_.size())
    return; // every entry was asked for: nothing to drop (the settled pile's usual step)
  for (auto it = entries_.begin(); it != entries_.end();)
    it = it->second.step == step_ ? std::next(it) : entries_.erase(it);
}

std::size_t CandidateStore::bytes() const {
  std::size_t total = entries_.bucket_count() * sizeof(void *) +
                      (hints_.capacity() + next_hints_.capacity()) * sizeof(Entry *);
  for (const auto &e : entries_)
    total += sizeof(e) + 2 * sizeof(void *) + e.second.cache.bytes();
  return total;
}

// LIGGGHTS tags are positive and below 2^31 (tagint is int in 3.8), so 32 bits each.
std::uint64_t CandidateStore::pair_key(long long tag_owner, long long tag_other) {
  return (static_cast<std::uint64_t>(tag_owner) << 32) |
         (static_cast<std::uint64_t>(tag_other) & 0xffffffffu);
}

std::uint64_t CandidateStore::wall_key(long long tag, int mesh) {
  return (static_cast<std::uint64_t>(tag) << 32) | static_cast<std::uint32_t>(mesh);
}

} // namespace tri_liggghts
