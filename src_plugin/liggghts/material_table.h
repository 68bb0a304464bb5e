// Contact coefficients per pair of types, read from the same `fix property/global` values that
// LIGGGHTS's own granular models read, so a deck switches between spheres and triangulated
// particles without touching its material fixes:
// - model hooke/stiffness (the default): kn, kt, gamman, gammat (gamman_abs, gammat_abs with
//   absolute_damping), coefficientFriction, all peratomtypepair, taken as they are;
// - model hooke, hertz: youngsModulus, poissonsRatio (peratomtype), coefficientRestitution,
//   coefficientFriction (peratomtypepair), characteristicVelocity (scalar), mapped onto our
//   linear contact by tri::map_material (material_mapping.h) between the volume-equivalent
//   spheres of the two types' shapes (a wall: a sphere of infinite radius and mass).
// characteristicVelocity is also read, where the deck defines it, for hooke/stiffness (for
// `epsilon auto` and the time-step check).
#pragma once

#include "contact_board.h"
#include "interaction/body_interaction.h" // InteractionSettings
#include "model/contact_model.h"
#include "model/material_mapping.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

class MaterialTable {
public:
  // Reads the properties for types 1..ntypes; `base` is the style's settings, whose
  // coefficients supply the model flags. `spheres` (index = atom type, [0] unused) are the
  // types' equivalent spheres, needed by hooke and hertz; with `walls` the table's second type
  // is a wall's (the mesh type). A missing property or a bad value ends in error->all naming it
  // and `caller`.
  void load(LAMMPS_NS::LAMMPS *lmp, int ntypes, const tri::InteractionSettings &base,
            tri::MaterialModel model, const std::vector<tri::EquivalentSphere> &spheres, bool walls,
            const std::string &caller);
  const tri::ContactCoefficients &get(int itype, int jtype) const {
    return settings(itype, jtype).coefficients;
  }
  // The style's settings with the coefficients of (itype, jtype): what body_interaction takes,
  // read in place (a copy per pair and evaluation was a memmove of its whole size, every step).
  const tri::InteractionSettings &settings(int itype, int jtype) const {
    return table_[static_cast<std::size_t>(itype) * (ntypes_ + 1) + jtype];
  }
  // m/s; 0 where the deck defines no characteristicVelocity (hooke/stiffness only).
  double characteristic_velocity() const { return v_char_; }
  // For the contact board: kn of every (i, j) with i in 1..first_types and j in second_types.
  MaterialHint hint(int first_types, const std::vector<int> &second_types) const;

private:
  int ntypes_ = 0;
  double v_char_ = 0.0;
  std::vector<tri::InteractionSettings> table_;
};

} // namespace tri_liggghts
