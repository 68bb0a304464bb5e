// Contact coefficients per pair of types, read from the same `fix property/global` values that
// LIGGGHTS's `pair gran model hooke/stiffness` reads (kn, kt, gamman, gammat or gamman_abs,
// gammat_abs with absolute_damping, coefficientFriction; all peratomtypepair), so a deck
// switches between spheres and triangulated particles without touching its material fixes.
#pragma once

#include "contact_model.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

class MaterialTable {
public:
  // Reads the properties for types 1..ntypes; `switches` supplies the model flags. A missing
  // property or a bad value ends in error->all naming it and `caller`.
  void load(LAMMPS_NS::LAMMPS *lmp, int ntypes, const tri::ContactCoefficients &switches,
            const std::string &caller);
  const tri::ContactCoefficients &get(int itype, int jtype) const {
    return table_[static_cast<std::size_t>(itype) * (ntypes_ + 1) + jtype];
  }

private:
  int ntypes_ = 0;
  std::vector<tri::ContactCoefficients> table_;
};

} // namespace tri_liggghts
