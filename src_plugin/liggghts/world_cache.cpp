// A thread's recently used particles; the design is in the header.
#include "world_cache.h"

namespace tri_liggghts {

namespace {
std::size_t power_of_two_at_least(int n) {
  std::size_t p = 1;
  while (p < static_cast<std::size_t>(n > 1 ? n : 1))
    p *= 2;
  return p;
}
} // namespace

WorldCache::WorldCache(int slots)
    : meta_(power_of_two_at_least(slots)), mask_(static_cast<unsigned>(meta_.size() - 1)),
      bodies_(meta_.size()), world_(meta_.size()) {}

WorldCache::Found WorldCache::find(int atom, long long evaluation, long long pin) {
  const int n = size();
  int free_slot = -1;
  for (int p = 0; p < kProbes && p < n; ++p) {
    const int s = static_cast<int>((static_cast<unsigned>(atom) + p) & mask_);
    Meta &m = meta_[static_cast<std::size_t>(s)];
    if (m.atom == atom && m.evaluation == evaluation) {
      m.pin = pin;
      return {s, false};
    }
    if (free_slot < 0 && m.pin != pin)
      free_slot = s;
  }
  if (free_slot < 0)
    return {};
  meta_[static_cast<std::size_t>(free_slot)] = {atom, evaluation, pin};
  return {free_slot, true};
}

std::size_t WorldCache::bytes() const {
  std::size_t b = meta_.capacity() * sizeof(Meta) + bodies_.capacity() * sizeof(tri::Body) +
                  world_.capacity() * sizeof(tri::TriangleSoA);
  for (const tri::TriangleSoA &w : world_)
    b += 3 * w.x.capacity() * sizeof(double) + w.distinct.capacity() * sizeof(int);
  return b;
}

} // namespace tri_liggghts
