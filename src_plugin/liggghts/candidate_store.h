// The kept triangle-pair candidates of one contact style's body pairs (tri::CandidateCache,
// candidate_cache.h), keyed by what names a body pair on every rank and across steps: two atom
// tags for pair tri/gran, an atom tag and a mesh for fix tri/wall. An entry lives while its body
// pair is evaluated every step; the first step a pair is not (apart, or gone to another rank),
// it is dropped, so memory follows the pairs within reach. Nothing here is written to restart
// files: a restarted run searches afresh, with the same contacts (candidate_cache.h).
//
// Use: begin_step(); for each task, serially, entry(slot, key) (pointers stay valid while the
// map grows: std::unordered_map never moves its elements); evaluate the tasks (threads may use
// their own entries); end_step() drops what was not asked for. An entry is handed to one task
// a step: a key asked for twice in one step (two images of one pair in a small periodic box)
// gets null the second time, so no two tasks, on two threads, ever write one entry.
//
// `slot` is the task's index in the step's task list. Between neighbour-list rebuilds the list
// is the same every step, so the entry a slot named last step is almost always the one it
// names now: it is tried first (its key compared), and the hash map is searched only when it
// differs. Such a hint is always valid: it was asked for last step, so last step's end_step
// kept it, and hints are renewed every step.
#pragma once

#include "candidate_cache.h"

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace tri_liggghts {

class CandidateStore {
public:
  void begin_step() {
    ++step_;
    touched_ = 0;
    hints_.swap(next_hints_);
    next_hints_.clear();
  }
  tri::CandidateCache *entry(std::size_t slot, std::uint64_t key) {
    Entry *e = slot < hints_.size() ? hints_[slot] : nullptr;
    if (!e || e->key != key) {
      e = &entries_[key];
      e->key = key;
    }
    if (next_hints_.size() <= slot)
      next_hints_.resize(slot + 1, nullptr);
    next_hints_[slot] = e;
    if (e->step == step_)
      return nullptr; // already another task's this step
    ++touched_;
    e->step = step_;
    return &e->cache;
  }
  void end_step();
  std::size_t bytes() const;

  // Keys: the tag of the atom whose neighbour list holds the pair, then the other's (with
  // newton off, a pair across a periodic boundary is in both atoms' lists, with the other as an
  // image: two tasks, two keys); a tag and a mesh index.
  static std::uint64_t pair_key(long long tag_owner, long long tag_other);
  static std::uint64_t wall_key(long long tag, int mesh);

private:
  struct Entry {
    tri::CandidateCache cache;
    long long step = 0;
    std::uint64_t key = 0;
  };
  std::unordered_map<std::uint64_t, Entry> entries_;
  std::vector<Entry *> hints_, next_hints_; // by slot: last step's entries, this step's
  std::size_t touched_ = 0;                 // entries asked for this step
  long long step_ = 0;
};

} // namespace tri_liggghts
