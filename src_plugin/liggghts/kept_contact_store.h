// The kept contact points of pair tri/gran's particle pairs (tri::kept_contacts.h), one record
// of tri::kKeptContactDoubles values per pair, and how they follow the atoms between ranks and
// into restart files (fix tri/kept_contacts does the moving).
//
// Keys. A record is the kernel's view of the pair (a, b in tag order), so a task of either atom
// may use it, whichever atom's neighbour list holds the pair: the key is (tag a, tag b). Only a
// pair that meets across a periodic boundary is different: its two tasks (one in each atom's
// list, the other atom a periodic image) see the contact from coordinates that differ by the
// box length, so each keeps its own record, named by which atom is the image. On any rank count
// the same task keeps the same record, which is why the forces do not depend on the split.
//
// Lifetime. A record counts only if its task asked for it the step before: a pair that left
// reach, or was not evaluated, starts afresh (its record is treated as empty), so what is kept
// never depends on which rank held the pair in between. At a neighbour-list rebuild the records
// leave the store with the atoms (to_parcels: each record goes with the atoms that may evaluate
// it next) and come back after the exchange (from_parcels), so migration loses none.
#pragma once

#include "interaction/kept_contacts.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace tri_liggghts {

class KeptContactStore {
public:
  enum class Image : std::uint64_t { none = 0, a = 1, b = 2 }; // which atom is a periodic image
  // tag_a < tag_b; LIGGGHTS 3.8 tags are positive ints (below 2^31).
  static std::uint64_t key(long long tag_a, long long tag_b, Image image) {
    return (static_cast<std::uint64_t>(tag_a) << 33) | (static_cast<std::uint64_t>(tag_b) << 2) |
           static_cast<std::uint64_t>(image);
  }
  static long long tag_a_of(std::uint64_t key) { return static_cast<long long>(key >> 33); }
  static long long tag_b_of(std::uint64_t key) {
    return static_cast<long long>((key >> 2) & 0x7fffffffu);
  }
  static Image image_of(std::uint64_t key) { return static_cast<Image>(key & 3u); }

  // Once per force evaluation, before the tasks ask; `slots` as CandidateStore::begin_step.
  void begin_step(std::size_t slots);
  // The record of `key` for the task in `slot` (tri::kKeptContactDoubles values, all zero where
  // none is kept); null if another task asked for it this step. Several threads may ask at once
  // as they may of a CandidateStore (candidate_store.h): every slot sized by begin_step, all the
  // asks for one key from one thread; a key not hinted is looked up under the lock.
  double *entry(std::size_t slot, std::uint64_t key);

  // A record as it travels with an atom: its key (as the bits of a double), then its values.
  static constexpr int kParcelDoubles = 1 + tri::kKeptContactDoubles;
  // Appends each live record to the parcels of the local atoms that may evaluate it next
  // (`local_of(tag)`: the atom's local index, or -1 where it is not owned here). With `drain`,
  // the store is emptied (the atoms are about to move); else it is kept (a restart's copy).
  template <class LocalOf>
  void to_parcels(LocalOf local_of, std::vector<std::vector<double>> &parcels, bool drain);
  // Takes the records of `parcels` back (a key already held is not replaced: its copies are
  // equal), as asked for the step before, and empties the parcels.
  void from_parcels(std::vector<std::vector<double>> &parcels, std::size_t count);

  std::size_t size() const { return records_.size(); }
  std::size_t bytes() const;

private:
  struct Record {
    long long step = 0; // the last step a task asked for it
    std::array<double, tri::kKeptContactDoubles> values{};
  };
  bool live(const Record &r) const {
    return r.step >= step_ - 1 && tri::kept_state(r.values.data());
  }
  static void append(std::uint64_t key, const Record &r, std::vector<double> &parcel);

  std::unordered_map<std::uint64_t, Record> records_; // references stay valid as it grows
  std::mutex records_mutex_;                          // records_ (entry's miss path)
  static constexpr std::size_t kHintAhead = 8;        // entry(): the hint fetched this far ahead
  std::vector<std::pair<std::uint64_t, Record *>> hints_, next_hints_; // by slot
  long long step_ = 1;
};

template <class LocalOf>
void KeptContactStore::to_parcels(LocalOf local_of, std::vector<std::vector<double>> &parcels,
                                  bool drain) {
  for (const auto &[key, record] : records_) {
    if (!live(record))
      continue;
    const Image image = image_of(key);
    // A shared record goes with both atoms; an image's own record with the atom whose task
    // keeps it (the one that is not the image).
    const int a = image == Image::a ? -1 : local_of(tag_a_of(key));
    const int b = image == Image::b ? -1 : local_of(tag_b_of(key));
    for (int atom : {a, b})
      if (atom >= 0)
        append(key, record, parcels[static_cast<std::size_t>(atom)]);
  }
  if (drain) {
    records_.clear();
    hints_.clear();
    next_hints_.clear();
  }
}

} // namespace tri_liggghts
