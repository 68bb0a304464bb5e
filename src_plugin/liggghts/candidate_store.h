// The kept triangle-pair candidates of one contact style's body pairs (tri::CandidateCache,
// candidate_cache.h), keyed by what names a body pair on every rank and across steps: two atom
// tags for pair tri/gran, an atom tag and a mesh for fix tri/wall. An entry lives while its body
// pair is evaluated every step; the first step a pair is not (apart, or gone to another rank),
// it is dropped. Nothing here is written to restart files: a restarted run searches afresh,
// with the same contacts (candidate_cache.h).
//
// Use: begin_step(); for each task, entry(slot, key) (pointers stay valid while the store
// grows: entries live in fixed chunks that never move); evaluate the tasks (threads may use
// their own entries); end_step() drops what was not asked for. An entry is handed to one task a
// step: a key asked for twice in one step (two images of one pair in a small periodic box) gets
// null the second time, so no two tasks, on two threads, ever write one entry.
//
// Several threads may ask at once (pair tri/gran lists its neighbour rows on its threads) when
// begin_step was given every slot and the number of lanes, each thread passes a lane of its own,
// and all the asks for one key come from one thread, in slot order (a pair's key names the atom
// whose neighbour list holds it, and a thread lists whole rows): then which task gets an entry
// is the serial order's. A hint is read without a lock (an entry never moves, and a hinted one
// keeps its key all step: only dropped entries are reused); the index is searched and grown
// under the lock.
//
// `slot` is the task's index in the step's task list. Between neighbour-list rebuilds the list
// is the same every step, so the entry a slot named last step is almost always the one it
// names now: it is tried first (its key compared), and the index is searched only when it
// differs. Such a hint is always valid: it was asked for last step, so last step's end_step
// kept it, and hints are renewed every step.
//
// Layout. In a flowing pile the neighbour lists rebuild often and the hints miss, so the index
// and the drops are on the hot path: the index is an open-addressing table (linear probing,
// keys next to their entries' addresses: one cache line per probe, no node to chase), and a
// dropped entry goes to a free list and is reused for the next new key (no allocation per
// pair). A reused entry is reset to a fresh cache's state but keeps its vectors' capacity, so
// the memory held follows the most pairs within reach so far, not the pairs now.
#pragma once

#include "distance/candidate_cache.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace tri_liggghts {

class CandidateStore {
public:
  // `slots`: how many slots the host may name this step, if it knows (pair tri/gran: its
  // neighbour pairs, of which it asks for those within reach).
  // `lanes`: how many threads will ask at once (above).
  void begin_step(std::size_t slots = 0, int lanes = 1) {
    ++step_;
    lanes_.assign(static_cast<std::size_t>(std::max(lanes, 1)), Lane{});
    hints_.swap(next_hints_);
    next_hints_.assign(slots, nullptr);
  }
  tri::CandidateCache *entry(std::size_t slot, std::uint64_t key, int lane = 0) {
    // The hints of slots kHintAhead further are fetched now: a host asks for its slots in
    // order, and each entry (one per task, each on lines of its own) missed the cache. Two of
    // them: a host may skip slots (pairs out of reach), which have none.
    for (std::size_t ahead = slot + kHintAhead; ahead < slot + kHintAhead + 2; ++ahead)
      if (ahead < hints_.size() && hints_[ahead])
        __builtin_prefetch(hints_[ahead]);
    Entry *e = slot < hints_.size() ? hints_[slot] : nullptr;
    if (!e || e->key != key) {
      std::lock_guard<std::mutex> lock(index_mutex_);
      e = find_or_add(key);
    }
    // Slots come in order, one more each call: an inline push_back (a resize per slot is an
    // out-of-line fill call per task).
    if (slot < next_hints_.size()) {
      next_hints_[slot] = e;
    } else {
      next_hints_.resize(slot, nullptr); // slots skipped, if any, have no hint
      next_hints_.push_back(e);
    }
    if (e->step == step_)
      return nullptr; // already another task's this step
    ++lanes_[static_cast<std::size_t>(lane)].touched;
    e->step = step_;
    return &e->cache;
  }
  void end_step();
  std::size_t bytes() const; // heap memory held, dropped entries' included

  // Keys: the tag of the atom whose neighbour list holds the pair, then the other's (with
  // newton off, a pair across a periodic boundary is in both atoms' lists, with the other as an
  // image: two tasks, two keys); a tag and a mesh index. Inline: one per task. LIGGGHTS tags
  // are positive and below 2^31 (tagint is int in 3.8), so 32 bits each.
  static std::uint64_t pair_key(long long tag_owner, long long tag_other) {
    return (static_cast<std::uint64_t>(tag_owner) << 32) |
           (static_cast<std::uint64_t>(tag_other) & 0xffffffffu);
  }
  static std::uint64_t wall_key(long long tag, int mesh) {
    return (static_cast<std::uint64_t>(tag) << 32) | static_cast<std::uint32_t>(mesh);
  }

private:
  // On cache lines of its own: entry() reads the key and step, and the host then the cache's
  // travel proof (candidate_cache.h), all on the first line.
  struct alignas(64) Entry {
    std::uint64_t key = 0;
    long long step = 0; // the last step it was asked for
    bool live = false;  // in the index; false: on the free list
    tri::CandidateCache cache;
  };
  struct Slot {
    std::uint64_t key = 0;
    Entry *entry = nullptr; // null: empty
  };
  static constexpr std::size_t kChunk = 64; // entries allocated at a time
  static constexpr std::size_t kHintAhead = 8; // entry(): the hint fetched this many slots ahead

  Entry *find_or_add(std::uint64_t key);
  [[gnu::noinline]] Entry *add(std::uint64_t key, std::size_t empty_slot);
  std::size_t home(std::uint64_t key) const; // the slot a key's probe starts at
  void grow_index();
  void remove_from_index(const Entry *e);

  std::vector<std::unique_ptr<Entry[]>> chunks_; // every entry, live or free
  std::vector<Entry *> free_;                    // entries to reuse
  std::vector<Slot> index_;                      // the live entries; size a power of two
  int index_shift_ = 64;                         // 64 - log2(index_.size())
  std::size_t live_ = 0;                         // entries in the index
  std::vector<Entry *> hints_, next_hints_;      // by slot: last step's entries, this step's
  struct alignas(64) Lane {                      // one per asking thread, on lines of its own
    std::size_t touched = 0;                     // entries it was handed this step
  };
  std::vector<Lane> lanes_{1};
  std::mutex index_mutex_;                       // index_, chunks_ and free_ (entry's miss path)
  long long step_ = 0;
};

} // namespace tri_liggghts
