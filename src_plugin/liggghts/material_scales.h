// What fix tri/particles derives from the contact material published on its board
// (contact_board.h, MaterialHint): the soft layer of `epsilon auto`, and the time-step check.
//
// epsilon auto. The contact styles publish their materials when they initialise: pair
// tri/gran in its init_style, before LIGGGHTS sizes the neighbour cutoffs from the particles'
// radii, and each fix tri/wall in its init. The first of them resolves epsilon (once, at the
// first run; later runs keep it): pair tri/gran when there is one, so the rule covers the
// particle pairs, else the first fix tri/wall, covering its particle-wall contacts. For every
// published pair of types the rule is tri::auto_epsilon (material_mapping.h): the peak
// overlap v sqrt(meff / kn) of an undamped head-on contact at the characteristic velocity v,
// with meff from the HEAVIEST shapes the two types can take (a wall: the particle's mass),
// is kept at half the two soft layers (a wall with a layer E of its own: epsilon + E = overlap /
// 0.5); epsilon is the largest over the pairs of types. With
// hooke/stiffness the deck's kn is used and a characteristicVelocity fix is then required;
// with hooke, kn is LIGGGHTS's, whose peak overlap is Hertz's, so epsilon = the Hertz peak
// overlap of the volume-equivalent spheres at v.
//
// The time-step check: tri::judge_timestep (timestep_rule.h) over every published pair of
// types that can touch now (two particles of the types exist, one for a wall; every pair while
// there are no particles yet), contact time pi sqrt(meff / kn) with meff of the LIGHTEST
// shapes, approach speed the fastest rate at which the centres of a listed pair of those types
// close in (walls: the fastest particle of the type), at least the characteristic velocity;
// with fix tri/adapt_dt the rule uses its dtmin (error) and dtmax (warning) and leaves the
// approach to it. The pair types that count for epsilon auto are chosen the same way.
#pragma once

#include "body/shape.h"
#include "contact_board.h"
#include "model/material_mapping.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

// The bodies an atom type can be: index = atom type ([0] unused).
struct TypeBodies {
  std::vector<tri::EquivalentSphere> sphere; // the material's sphere: of the mean shape volume
  std::vector<double> min_mass, max_mass;    // kg, the lightest and heaviest shape of the type
  std::vector<long> count;                   // particles of the type now, all ranks
};

// by_type: shape k - 1 for type k (assign type); else every shape for every type. Collective.
TypeBodies type_bodies(LAMMPS_NS::LAMMPS *lmp, const std::vector<tri::Shape> &shapes,
                       double density, bool by_type);

struct AutoEpsilon {
  bool found = false;                                      // some source has published a material
  double epsilon = 0.0;                                    // m
  double overlap = 0.0, speed = 0.0, kn = 0.0, meff = 0.0; // of the pair of types that set it
  int itype = 0, jtype = 0;
  bool wall = false;
  std::string source; // style ID of the source, "pair" for pair tri/gran
};

// The rule above over the materials published so far. Ends in error->all if one lacks a
// characteristic velocity.
AutoEpsilon choose_auto_epsilon(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board,
                                const TypeBodies &bodies);

// The check, on every rank (collective), after a force evaluation (the particle-pair list is
// published then). `report`: print the figures (at setup). WARNINGs and
// the ERROR go through LIGGGHTS's error class. Does nothing where no source has published a
// material (no contacts). `wall_layer`: the soft layer of a wall that gives none of its own.
void check_timestep(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board, const TypeBodies &bodies,
                    double epsilon, double wall_layer, bool report);

// The longest undamped contact time pi sqrt(meff / kn) over the published pairs of types that
// can touch, meff of the HEAVIEST shapes: how long one impact keeps two bodies together (fix
// tri/adapt_dt tells a bounce through the soft layers from bodies that stay intersected). 0
// where no source has published a material.
double longest_contact_time(const ContactBoard &board, const TypeBodies &bodies);

} // namespace tri_liggghts
