#include "material_table.h"

#include "error.h"
#include "fix_property_global.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tri_liggghts {
namespace {
std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}
} // namespace

void MaterialTable::load(LAMMPS_NS::LAMMPS *lmp, int ntypes, const tri::InteractionSettings &base,
                         tri::MaterialModel model,
                         const std::vector<tri::EquivalentSphere> &spheres, bool walls,
                         const std::string &caller) {
  const tri::ContactCoefficients &sw = base.coefficients;
  using LAMMPS_NS::FixPropertyGlobal;
  const std::string who = model == tri::MaterialModel::hooke_stiffness
                              ? caller
                              : caller + " (model " + tri::material_model_name(model) + ")";
  // find_fix_property ends the run with LIGGGHTS's own message naming the property.
  auto property = [&](const char *name, const char *kind, int n1, int n2, bool required) {
    return static_cast<FixPropertyGlobal *>(lmp->modify->find_fix_property(
        name, "property/global", kind, n1, n2, who.c_str(), required));
  };
  auto pairwise = [&](const char *name) {
    return property(name, "peratomtypepair", ntypes, ntypes, true);
  };
  auto fail = [&](int i, int j, const std::string &problem) {
    const std::string msg = caller + ": material of types " + std::to_string(i) + " and " +
                            std::to_string(j) + ": " + problem;
    lmp->error->all(FLERR, msg.c_str());
  };

  const bool mapped = model != tri::MaterialModel::hooke_stiffness;
  FixPropertyGlobal *v_char = property("characteristicVelocity", "scalar", 0, 0, mapped);
  v_char_ = v_char ? v_char->compute_scalar() : 0.0;
  if (v_char && !(v_char_ > 0.0)) {
    const std::string msg = who + ": characteristicVelocity must be > 0, got " + number(v_char_);
    lmp->error->all(FLERR, msg.c_str());
  }

  ntypes_ = ntypes;
  table_.assign(static_cast<std::size_t>(ntypes + 1) * (ntypes + 1), base);
  if (!mapped) {
    FixPropertyGlobal *kn = pairwise("kn");
    FixPropertyGlobal *kt = pairwise("kt");
    FixPropertyGlobal *gn = pairwise(sw.absolute_damping ? "gamman_abs" : "gamman");
    FixPropertyGlobal *gt = pairwise(sw.absolute_damping ? "gammat_abs" : "gammat");
    FixPropertyGlobal *mu = pairwise("coefficientFriction");
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
        if (!problem.empty())
          fail(i, j, problem);
        table_[static_cast<std::size_t>(i) * (ntypes + 1) + j].coefficients = c;
      }
    return;
  }

  FixPropertyGlobal *y = property("youngsModulus", "peratomtype", ntypes, 0, true);
  FixPropertyGlobal *nu = property("poissonsRatio", "peratomtype", ntypes, 0, true);
  FixPropertyGlobal *e = pairwise("coefficientRestitution");
  FixPropertyGlobal *mu = pairwise("coefficientFriction");
  for (int i = 1; i <= ntypes; ++i) {
    const double yi = y->compute_vector(i - 1), nui = nu->compute_vector(i - 1);
    if (!(yi > 0.0) || !std::isfinite(yi)) {
      const std::string msg =
          who + ": youngsModulus of type " + std::to_string(i) + " must be > 0, got " + number(yi);
      lmp->error->all(FLERR, msg.c_str());
    }
    if (!(nui >= 0.0 && nui <= 0.5)) {
      const std::string msg = who + ": poissonsRatio of type " + std::to_string(i) +
                              " must be in [0, 0.5], got " + number(nui);
      lmp->error->all(FLERR, msg.c_str());
    }
  }
  const int particle_types = static_cast<int>(spheres.size()) - 1;
  for (int i = 1; i <= ntypes; ++i)
    for (int j = 1; j <= ntypes; ++j) {
      // Rows of types that no particle has (a wall table sized by the wall types) stay unused.
      if (i > particle_types || (!walls && j > particle_types))
        continue;
      tri::MaterialProperties p;
      const double yi = y->compute_vector(i - 1), yj = y->compute_vector(j - 1);
      const double nui = nu->compute_vector(i - 1), nuj = nu->compute_vector(j - 1);
      p.y_eff = tri::effective_youngs_modulus(yi, nui, yj, nuj);
      p.g_eff = tri::effective_shear_modulus(yi, nui, yj, nuj);
      p.restitution = e->compute_array(i - 1, j - 1);
      p.friction = mu->compute_array(i - 1, j - 1);
      p.v_char = v_char_;
      try {
        tri::ContactCoefficients c =
            tri::map_material(model, p, spheres[i], walls ? tri::wall_sphere() : spheres[j], sw);
        c.kn /= lmp->force->nktv2p;
        c.kt /= lmp->force->nktv2p;
        const std::string problem = tri::coefficient_error(c);
        if (!problem.empty())
          fail(i, j, problem);
        table_[static_cast<std::size_t>(i) * (ntypes + 1) + j].coefficients = c;
      } catch (const std::invalid_argument &ex) {
        fail(i, j, ex.what());
      }
    }
}

MaterialHint MaterialTable::hint(int first_types, const std::vector<int> &second_types) const {
  MaterialHint h;
  h.characteristic_velocity = v_char_;
  for (int i = 1; i <= first_types && i <= ntypes_; ++i)
    for (int j : second_types)
      if (j >= 1 && j <= ntypes_)
        h.stiffness.push_back({i, j, get(i, j).kn});
  return h;
}

} // namespace tri_liggghts
