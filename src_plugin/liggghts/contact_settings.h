// Keywords shared by `pair_style tri/gran` and `fix tri/wall`, parsed in one place:
//
//   kernel bf|penalty|hybrid|batched   distance kernel (default hybrid)
//   newton_iters N                     penalty iterations (default 4)
//   batch N                            batch size of the batched kernel (default 8)
//   parallel pairs|triangles|batches|none
//                                      OpenMP over particle pairs (default), over the triangle
//                                      pairs of one particle pair, over batches, or off
//   cull yes|boxes|no                  culling of triangle pairs: boxes in two frames and face
//                                      planes (yes, default), world-frame boxes only (boxes),
//                                      none (no); the contacts are the same
//   separation yes|no                  keep each body pair's last separating axis and verify it
//                                      before any triangle pair (default yes; no: search always)
//   coherence R|no                     keep each body pair's triangle-pair candidates, culled
//                                      with a margin of (1 + R) x the contact cutoff, and
//                                      reuse them while the bodies move less than R x the
//                                      cutoff (candidate_cache.h; default 0.05; no: cull every
//                                      step); the contacts are the same
//   keep_contacts T|no                 carry a contact's points while the bodies move less than
//                                      T times their layer relative to each other
//                                      (interaction/kept_contacts.h; default 1e-4; no: measure
//                                      every contact every step)
//   reduction clusters|paper|none      contact reduction (default clusters; see
//                                      contact_reduction.h)
//   tangential history|no_history      (default history)
//   absolute_damping on|off            as LIGGGHTS hooke/stiffness (default off)
//   limitForce on|off                  clamp attractive normal force (default on, as the paper)
//   tangential_damping on|off          (default on)
//   model hooke/stiffness|hooke|hertz  where the coefficients come from (default
//                                      hooke/stiffness: kn, kt, gamman, gammat as given;
//                                      hooke, hertz: from youngsModulus, poissonsRatio,
//                                      coefficientRestitution, characteristicVelocity;
//                                      material_mapping.h)
#pragma once

#include "interaction/body_interaction.h"
#include "model/material_mapping.h"

#include <cstddef>
#include <string>

namespace LAMMPS_NS {
class Error;
}

namespace tri_liggghts {

enum class PairLoop { particle_pairs, inside_pair };

struct ContactSettings {
  tri::InteractionSettings interaction; // coefficients: only the switches are set here
  PairLoop loop = PairLoop::particle_pairs;
  tri::MaterialModel model = tri::MaterialModel::hooke_stiffness;
  bool separation = true; // keep separating axes (body_interaction.h: SeparationCache)
};

// Consumes the keywords it knows from arg[*i..narg), advancing *i; returns false at the first
// word it does not know (the caller decides whether that is an error). Bad values are errors
// naming `style` and the keyword.
// Threads for the loop over particle pairs: one unless the loop is the parallel level and
// there are several pairs per thread (a parallel region costs microseconds, and on a busy
// machine a thread that was descheduled stalls the others at its barrier for milliseconds).
int pair_loop_threads(PairLoop loop, std::size_t num_pairs);

bool parse_contact_keyword(int narg, char **arg, int *i, ContactSettings &settings,
                           const std::string &style, LAMMPS_NS::Error *error);

} // namespace tri_liggghts
