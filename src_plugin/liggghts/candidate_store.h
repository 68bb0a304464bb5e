// The kept triangle-pair candidates of one contact style's body pairs (tri::CandidateCache,
// candidate_cache.h), keyed by what names a body pair on every rank and across steps: two atom
// tags for pair tri/gran, an atom tag and a mesh for fix tri/wall. An entry lives while its body
// pair is evaluated every step; the first step a pair is not (apart, or gone to another rank),
// it is dropped, so memory follows the pairs within reach. Nothing here is written to restart
// files: a restarted run searches afresh, with the same contacts (candidate_cache.h).
//
// Use: begin_step(); for each task, serially, entry(key) (pointers stay valid while the map
// grows: std::unordered_map never moves its elements); evaluate the tasks (threads may use
// their own entries); end_step() drops what was not asked for.
#pragma once

#include "candidate_cache.h"

#include <cstddef>
#include <cstdint>
#include <unordered_map>

namespace tri_liggghts {

class CandidateStore {
public:
  void begin_step() { ++step_; }
  tri::CandidateCache *entry(std::uint64_t key) {
    Entry &e = entries_[key];
    e.step = step_;
    return &e.cache;
  }
  void end_step();
  std::size_t bytes() const;

  // Keys: the two tags in either order give the same key; a tag and a mesh index.
  static std::uint64_t pair_key(long long tag_i, long long tag_j);
  static std::uint64_t wall_key(long long tag, int mesh);

private:
  struct Entry {
    tri::CandidateCache cache;
    long long step = 0;
  };
  std::unordered_map<std::uint64_t, Entry> entries_;
  long long step_ = 0;
};

} // namespace tri_liggghts
