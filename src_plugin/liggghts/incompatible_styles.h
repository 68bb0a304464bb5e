// LIGGGHTS styles that cannot work with triangulated particles, and what to use instead.
//
// A LIGGGHTS sphere deck turned into a mesh-particle deck keeps most of its lines (gravity,
// materials, mesh/surface walls, move/mesh, insertion, thermo, dumps), but the styles that
// treat each atom as a sphere of its radius would silently compute nonsense on triangulated
// particles: radius is the contact reach (the mesh's bounding radius), orientation and angular momentum live in
// fix tri/particles, and contacts are between triangles. fix tri/particles calls
// refuse_incompatible_styles() from its init(), so every run of such a deck stops before its
// first step with an ERROR that names the style, its ID, why it cannot work, and its tri/
// replacement.
//
// Refused (the table in incompatible_styles.cpp):
//   integrators: every fix that integrates the atoms' motion (LIGGGHTS's time_integrate flag)
//     except tri/nve: nve, nve/sphere, nve/limit, nve/noforce, nve/asphere..., rigid, move,
//     and the multisphere fixes;
//   sphere contacts: pair styles other than tri/gran (gran, hybrid and hybrid/overlay even
//     with tri/gran among their sub-styles, ...), fix wall/gran, wall/region, heat/gran,
//     check/timestep/gran, adapt (it changes the radius, which fix tri/particles owns);
//   sphere computes: erotate, erotate/sphere, erotate/sphere/atom (and the asphere,
//     superquadric, multisphere variants), contact/atom, contact/atom/gran, pair/gran/local,
//     wall/gran/local.
// Everything else is allowed; see README.md ("From a LIGGGHTS sphere deck").
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

// The message for the first incompatible style of the deck (fixes, then computes, then the
// pair style, each in the order they were defined), or "" if there is none. `particles_id` is
// the ID of the fix tri/particles (messages name its per-atom columns).
std::string incompatible_style_message(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id);

// error->all with that message if there is one. Called from FixTriParticles::init.
void refuse_incompatible_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id);

} // namespace tri_liggghts
