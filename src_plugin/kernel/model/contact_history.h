// Friction history of one particle pair (tangential spring and twist spring): a fixed block of doubles that the host stores per
// pair (LIGGGHTS contact history, `dnum` = kHistoryDoubles), migrated between ranks and
// written to restarts as it is. Plain doubles, no pointers, no flags outside the array.
//
// Layout: kHistorySlots slots of kHistorySlotDoubles each, slot s at offset
// s * kHistorySlotDoubles:
//   [0..2] patch normal n (unit, from a towards b, world frame); all zero = empty slot
//   [3..5] shear displacement (m, world frame, in the tangent plane of n)
//   [6..8] lever p - o (m, world frame): where the patch was, relative to the pair's origin o
//          (midpoint of the two centres; a's centre against a wall)
//   [9]    twist angle (rad) of the twist spring (contact_model.h): rotation of b relative to a
//          about n, right-handed; 0 for a contact that is not face-like
// A zero-filled array (what LIGGGHTS gives a new pair) is "no patches".
//
// Matching rule, applied each step to the pair's reduced contacts (deepest first, only the
// first kHistorySlots of them are tracked; further ones start from zero shear every step):
// a contact i and an occupied slot s are compatible when n_i . n_s >= cos(kHistoryMatchAngle)
// (normals turn far less than that in one step, while reduction classes of one region differ
// by more); among compatible pairs, the ones whose levers are closest are matched first
// (greedy on |lever_i - lever_s|, ties by contact then slot index), each contact and slot at
// most once. The lever separates patches with the same normal (a non-convex particle on a
// flat wall in two places). A matched contact continues its slot's shear and twist; an unmatched
// one starts from zero; slots not matched are dropped (the patch ended). The new history is
// written compactly: slot k = tracked contact k, the rest zero. Deterministic.
#pragma once

#include "contact/contact_point.h"

#include <Eigen/Core>

#include <algorithm>

namespace tri {

constexpr int kHistorySlots = 4;
constexpr int kHistorySlotDoubles = 10;
constexpr int kHistoryDoubles = kHistorySlots * kHistorySlotDoubles; // 40
constexpr double kHistoryMatchAngle = 0.7853981633974483;            // rad, 45 degrees

// For each of the first min(n, kHistorySlots) contacts: the matched old slot, or -1 (new).
// `history` holds kHistoryDoubles values; `origin` is the pair's lever origin (m).
void match_history(const double *history, const ContactPoint *contacts, int n,
                   const Eigen::Vector3d &origin, int slot_of_contact[kHistorySlots]);

// Whether history value k changes sign when the host swaps the roles of a and b (LIGGGHTS
// keeps a pair's history on both atoms under newton off and negates such values for the
// partner): normals and shear displacements do; the lever, measured from the pair's
// reference point (the midpoint of the two centres for two particles), does not; nor does the
// twist angle: swapping a and b negates both the relative rotation and the normal, so the
// rotation about the normal, (omega_b - omega_a) . n, is the same seen from either body.
constexpr bool history_flips_sign(int k) { return k % kHistorySlotDoubles < 6; }

// Slot accessors (s in [0, kHistorySlots)).
inline bool slot_occupied(const double *history, int s) {
  const double *h = history + s * kHistorySlotDoubles;
  return h[0] != 0.0 || h[1] != 0.0 || h[2] != 0.0;
}
// The occupied slots, which come first (the history is written compactly): a step reads and
// writes only those, not the whole block, since the block of every neighbour pair of a large
// bed does not stay in cache from one step to the next.
inline int occupied_slots(const double *history) {
  int s = 0;
  while (s < kHistorySlots && slot_occupied(history, s))
    ++s;
  return s;
}
inline Eigen::Vector3d slot_normal(const double *history, int s) {
  return Eigen::Vector3d(history + s * kHistorySlotDoubles);
}
inline Eigen::Vector3d slot_shear(const double *history, int s) {
  return Eigen::Vector3d(history + s * kHistorySlotDoubles + 3);
}
inline Eigen::Vector3d slot_lever(const double *history, int s) {
  return Eigen::Vector3d(history + s * kHistorySlotDoubles + 6);
}
inline double slot_twist(const double *history, int s) {
  return history[s * kHistorySlotDoubles + 9];
}
void write_slot(double *history, int s, const Eigen::Vector3d &normal, const Eigen::Vector3d &shear,
                const Eigen::Vector3d &lever, double twist);

// The history of one pair as the kernel sees it. The host stores it as seen from its own
// (i, j); when the kernel evaluates the pair as (j, i) (`flip`), the values that change sign
// with the roles are negated, exactly, into a copy and back. During LIGGGHTS's setup, forces
// are computed without advancing the history (`update` false), so a restarted run continues
// bit for bit: the kernel then works on a copy that is dropped. `stored` null (no history
// kept): data() is null.
class HistoryView {
public:
  HistoryView(double *stored, bool flip, bool update) : stored_(stored), flip_(flip), update_(update) {
    if (!stored_ || (!flip_ && update_))
      return;
    // Only the occupied slots are copied; the rest reads as empty, as it is stored.
    slots_ = occupied_slots(stored_);
    const int n = slots_ * kHistorySlotDoubles;
    for (int v = 0; v < n; ++v)
      copy_[v] = flip_ && history_flips_sign(v) ? -stored_[v] : stored_[v];
    for (int v = n; v < kHistoryDoubles; ++v)
      copy_[v] = 0.0;
  }
  HistoryView(const HistoryView &) = delete;
  HistoryView &operator=(const HistoryView &) = delete;
  ~HistoryView() {
    if (!stored_ || !flip_ || !update_)
      return;
    // The slots occupied before or after: beyond both, stored and copy are empty alike.
    const int n = std::max(slots_, occupied_slots(copy_)) * kHistorySlotDoubles;
    for (int v = 0; v < n; ++v)
      stored_[v] = history_flips_sign(v) ? -copy_[v] : copy_[v];
  }
  double *data() { return !stored_ ? nullptr : (!flip_ && update_) ? stored_ : copy_; }

private:
  double *stored_;
  bool flip_, update_;
  int slots_ = 0;
  double copy_[kHistoryDoubles];
};

} // namespace tri
