#include "candidate_store.h"

#include <algorithm>

namespace tri_liggghts {

// The top bits of a multiplicative hash: pair keys are two tags, dense and close together, so
// the owner's tag is first folded into the low half, then the product's high bits depend on
// every bit of the key (the multiplier is odd: distinct keys stay distinct).
std::size_t CandidateStore::home(std::uint64_t key) const {
  const std::uint64_t folded = key ^ (key >> 32);
  return static_cast<std::size_t>((folded * 0x9e3779b97f4a7c15u) >> index_shift_);
}

CandidateStore::Entry *CandidateStore::find_or_add(std::uint64_t key) {
  if (2 * (live_ + 1) > index_.size())
    grow_index(); // at most half full: probes stay short
  const std::size_t mask = index_.size() - 1;
  std::size_t i = home(key);
  for (; index_[i].entry; i = (i + 1) & mask)
    if (index_[i].key == key)
      return index_[i].entry;
  return add(key, i);
}

// Out of line: the lookup above, run for every task after a neighbour-list rebuild, stays
// small; a new pair is rarer.
CandidateStore::Entry *CandidateStore::add(std::uint64_t key, std::size_t empty_slot) {
  if (free_.empty()) {
    chunks_.push_back(std::make_unique<Entry[]>(kChunk));
    for (std::size_t k = kChunk; k-- > 0;) // handed out from the chunk's start
      free_.push_back(&chunks_.back()[k]);
  }
  Entry *e = free_.back();
  free_.pop_back();
  // A dropped entry becomes a fresh one: copying a fresh cache sets every member as a new
  // cache has it (no kept list or gap is valid, no pause pending), while the vectors, assigned
  // from empty ones, keep their storage for the next keep() (libstdc++ and libc++ reuse storage
  // that suffices; test_candidate_store checks it through bytes()).
  static const tri::CandidateCache fresh;
  e->cache = fresh;
  e->key = key;
  e->live = true;
  index_[empty_slot] = {key, e};
  ++live_;
  return e;
}

void CandidateStore::grow_index() {
  std::vector<Slot> old(std::max<std::size_t>(64, 2 * index_.size()));
  old.swap(index_);
  index_shift_ = 64 - __builtin_ctzll(index_.size());
  const std::size_t mask = index_.size() - 1;
  for (const Slot &s : old)
    if (s.entry) {
      std::size_t i = home(s.key);
      while (index_[i].entry)
        i = (i + 1) & mask;
      index_[i] = s;
    }
}

// Deletion without tombstones (which would lengthen every later probe): the entries after the
// hole, up to the next empty slot, move back into it whenever their probe, from their home,
// passes the hole, so every key stays reachable from its home without a gap.
void CandidateStore::remove_from_index(const Entry *e) {
  const std::size_t mask = index_.size() - 1;
  std::size_t hole = home(e->key);
  while (index_[hole].entry != e)
    hole = (hole + 1) & mask;
  for (std::size_t next = (hole + 1) & mask; index_[next].entry; next = (next + 1) & mask) {
    const std::size_t probed = (next - home(index_[next].key)) & mask; // from its home
    if (probed >= ((next - hole) & mask)) {
      index_[hole] = index_[next];
      hole = next;
    }
  }
  index_[hole] = Slot{};
  --live_;
}

void CandidateStore::end_step() {
  // Entries asked for are distinct and live; the others are dropped (none: the settled pile's
  // usual step). The sweep stops at the last one.
  std::size_t touched = 0;
  for (const Lane &l : lanes_)
    touched += l.touched;
  std::size_t to_drop = live_ - touched;
  if (to_drop == 0)
    return;
  for (auto &chunk : chunks_)
    for (Entry *e = chunk.get(), *end = e + kChunk; e != end; ++e)
      if (e->live && e->step != step_) {
        remove_from_index(e);
        e->live = false;
        free_.push_back(e);
        if (--to_drop == 0)
          return;
      }
}

std::size_t CandidateStore::bytes() const {
  std::size_t total =
      chunks_.capacity() * sizeof(chunks_[0]) + chunks_.size() * kChunk * sizeof(Entry) +
      index_.capacity() * sizeof(Slot) +
      (free_.capacity() + hints_.capacity() + next_hints_.capacity()) * sizeof(Entry *);
  for (const auto &chunk : chunks_)
    for (std::size_t k = 0; k < kChunk; ++k)
      total += chunk[k].cache.bytes();
  return total;
}

} // namespace tri_liggghts
