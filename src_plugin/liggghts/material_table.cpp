#include "material_table.h"

#include "error.h"
#include "fix_property_global.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"

namespace tri_liggghts {

void MaterialTable::load(LAMMPS_NS::LAMMPS *lmp, int ntypes, const tri::ContactCoefficients &sw,
                         const std::string &caller) {
  using LAMMPS_NS::FixPropertyGlobal;
  auto property = [&](const char *name) {
    // find_fix_property ends the run with LIGGGHTS's own message naming the property.
    return static_cast<FixPropertyGlobal *>(lmp->modify->find_fix_property(
        name, "property/global", "peratomtypepair", ntypes, ntypes, caller.c_str()));
  };
  FixPropertyGlobal *kn = property("kn");
  FixPropertyGlobal *kt = property("kt");
  FixPropertyGlobal *gn = property(sw.absolute_damping ? "gamman_abs" : "gamman");
  FixPropertyGlobal *gt = property(sw.absolute_damping ? "gammat_abs" : "gammat");
  FixPropertyGlobal *mu = property("coefficientFriction");

  ntypes_ = ntypes;
  table_.assign(static_cast<std::size_t>(ntypes + 1) * (ntypes + 1), sw);
  for (int i = 1; i <= ntypes; ++i)
    for (int j = 1; j <= ntypes; ++j) {
      tri::ContactCoefficients c = sw;
      // hooke/stiffness gives kn and kt in pressure units when nktv2p != 1 (not in si/cgs).
      c.kn = kn->compute_array(i - 1, j - 1) / lmp->force->nktv2p;
      c.kt = kt->compute_array(i - 1, j - 1) / lmp->force->nktv2p;
      c.gamman = gn->compute_array(i - 1, j - 1);
      c.gammat = gt->compute_array(i - 1, j - 1);
      c.mu = mu->compute_array(i - 1, j - 1);
      const std::string problem = tri::coefficient_error(c);
      if (!problem.empty()) {
        const std::string msg = caller + ": material of types " + std::to_string(i) + " and " +
                                std::to_string(j) + ": " + problem;
        lmp->error->all(FLERR, msg.c_str());
      }
      table_[static_cast<std::size_t>(i) * (ntypes + 1) + j] = c;
    }
}

} // namespace tri_liggghts
