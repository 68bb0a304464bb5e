// LIGGGHTS styles that cannot work with triangulated particles, and what to use instead.
//
// A LIGGGHTS sphere deck turned into a mesh-particle deck keeps most of its lines (gravity,
// materials, mesh/surface walls, move/mesh, insertion, thermo, dumps), but the styles that
// treat each atom as a sphere of its radius would silently compute nonsense on triangulated
// particles: radius is the contact reach (the mesh's bounding radius), orientation and angular
// momentum live in fix tri/particles, and contacts are between triangles. fix tri/particles calls
// refuse_incompatible_styles() from its init(), so every run of such a deck stops before its
// first step with an ERROR that names the style, its ID, why it cannot work, and its tri/
// replacement.
//
// Refused: the fixes, computes, pair styles and dumps of class refused in the compatibility
// matrix (style_matrix.h), `minimize` and run_style respa (seen at the init they run), every
// fix that integrates the atoms' motion (LIGGGHTS's time_integrate flag) other than tri/nve, and
// every pair style other than tri/gran (hybrid and hybrid/overlay too, even with tri/gran among
// their sub-styles: its checks and statistics read the one pair style).
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

// The message for the first incompatible style of the deck (fixes, then computes, dumps, a
// minimisation, respa, then the pair style, each in the order they were defined), or "" if
// there is none. `particles_id` is the ID of the fix tri/particles (messages name its per-atom
// columns).
std::string incompatible_style_message(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id);

// The message for pair gran's sub-model keyword `keyword` (cohesion, rolling_friction,
// surface) with its value (or nullptr) given to `style` ("Pair tri/gran", "Fix tri/wall"), or ""
// for any other keyword.
std::string gran_submodel_message(const std::string &style, const char *keyword,
                                  const char *value);

// LIGGGHTS 3.8's constant fixes (property/global and its aliases, diam/max) offer a global
// value but leave its output frequency 0, and thermo and variables divide the step by it: a
// deck that prints one ends in SIGFPE, with spheres too. Their value holds at every step, so
// the frequency is set to 1. Called from FixTriParticles::init, before LIGGGHTS's output init.
void mend_output_frequencies(LAMMPS_NS::LAMMPS *lmp);

// error->all with that message if there is one. Called from FixTriParticles::init.
void refuse_incompatible_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id);

} // namespace tri_liggghts
