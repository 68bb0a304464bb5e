// One body pair's triangle contacts in one call, for tests and tools: the candidates
// (find_candidate_pairs) and the kernel run at once on them (distances_among_candidates), as
// TriangleContacts (contacts_from_results). The interaction layer runs the same steps on the
// kernel's results in place (body_interaction.h).
#pragma once

#include "distance/particle_contacts.h"

#include <cstdint>
#include <vector>

namespace tri_test {

// Appends to `out` the contacts among pairs[0, count) (particle_contacts.h); adds to `stats`.
inline void contacts_among_candidates(const tri::TriangleSoA &a, double eps_a,
                                      const tri::TriangleSoA &b, double eps_b,
                                      const tri::ContactOptions &opt,
                                      const tri::TrianglePairIndex *pairs, int count,
                                      std::vector<tri::TriangleContact> &out,
                                      tri::ContactStats &stats, tri::ContactWorkspace &ws) {
  tri::distances_among_candidates(a, eps_a, b, eps_b, opt, pairs, count, stats, ws);
  tri::contacts_from_results(pairs, ws.results.data(), count, eps_a + eps_b, out, stats);
}

// Appends to `out` every triangle pair of a and b closer than eps_a + eps_b, sorted by
// (tri_a, tri_b); adds to `stats`. `skip_b` as find_candidate_pairs'.
inline void find_triangle_contacts(const tri::TriangleSoA &a, double eps_a,
                                   const tri::TriangleSoA &b, double eps_b,
                                   const tri::ContactOptions &opt,
                                   std::vector<tri::TriangleContact> &out, tri::ContactStats &stats,
                                   tri::ContactWorkspace &ws,
                                   const std::uint8_t *skip_b = nullptr) {
  const int count = tri::find_candidate_pairs(a, b, eps_a + eps_b, opt, ws, skip_b);
  contacts_among_candidates(a, eps_a, b, eps_b, opt, ws.pairs.data(), count, out, stats, ws);
}

// The same with a workspace of its own (allocated on every call).
inline void find_triangle_contacts(const tri::TriangleSoA &a, double eps_a,
                                   const tri::TriangleSoA &b, double eps_b,
                                   const tri::ContactOptions &opt,
                                   std::vector<tri::TriangleContact> &out,
                                   tri::ContactStats &stats) {
  tri::ContactWorkspace ws;
  find_triangle_contacts(a, eps_a, b, eps_b, opt, out, stats, ws);
}

} // namespace tri_test
