// Matching of contact patches to friction-history slots; the rule is in the header.
#include "model/contact_history.h"

#include <algorithm>
#include <cmath>

namespace tri {

void write_slot(double *history, int s, const Eigen::Vector3d &normal, const Eigen::Vector3d &shear,
                const Eigen::Vector3d &lever, double twist) {
  double *h = history + s * kHistorySlotDoubles;
  for (int k = 0; k < 3; ++k) {
    h[k] = normal[k];
    h[3 + k] = shear[k];
    h[6 + k] = lever[k];
  }
  h[9] = twist;
}

void match_history(const double *history, const ContactPoint *contacts, int n,
                   const Eigen::Vector3d &origin, int slot_of_contact[kHistorySlots]) {
  const int tracked = std::min(n, kHistorySlots);
  for (int i = 0; i < kHistorySlots; ++i)
    slot_of_contact[i] = -1;

  struct Candidate {
    double cost;
    int contact, slot;
  };
  Candidate candidates[kHistorySlots * kHistorySlots];
  int count = 0;
  const double cos_match = std::cos(kHistoryMatchAngle);
  const int occupied = occupied_slots(history);
  for (int i = 0; i < tracked; ++i) {
    const Eigen::Vector3d lever = contacts[i].point - origin;
    for (int s = 0; s < occupied; ++s) {
      if (contacts[i].normal.dot(slot_normal(history, s)) < cos_match)
        continue;
      candidates[count++] = {(lever - slot_lever(history, s)).norm(), i, s};
    }
  }
  std::sort(candidates, candidates + count, [](const Candidate &a, const Candidate &b) {
    if (a.cost != b.cost)
      return a.cost < b.cost;
    if (a.contact != b.contact)
      return a.contact < b.contact;
    return a.slot < b.slot;
  });
  bool slot_taken[kHistorySlots] = {false, false, false, false};
  for (int k = 0; k < count; ++k) {
    const Candidate &c = candidates[k];
    if (slot_of_contact[c.contact] >= 0 || slot_taken[c.slot])
      continue;
    slot_of_contact[c.contact] = c.slot;
    slot_taken[c.slot] = true;
  }
}

} // namespace tri
