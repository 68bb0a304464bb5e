// To add a style: write its class in src_plugin/liggghts/, include its header here and add
// one row to the matching table below. Nothing else in the project lists styles.
#include "style_registry.h"

#include "private_map_access.h"

#include "fix_tri_nve.h"
#include "fix_tri_particles.h"
#include "fix_tri_vtk.h"

#include "force.h"
#include "lammps.h"
#include "modify.h"

namespace tri_driver {
namespace {

template <typename T> LAMMPS_NS::Fix *make_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) {
  return new T(lmp, narg, arg);
}

struct FixRow {
  const char *name;
  FixCreator create;
};

const FixRow fix_table[] = {
    {"tri/particles", &make_fix<LAMMPS_NS::FixTriParticles>},
    {"tri/nve", &make_fix<LAMMPS_NS::FixTriNVE>},
    {"tri/vtk", &make_fix<LAMMPS_NS::FixTriVTK>},
};

} // namespace

void register_styles(LAMMPS_NS::LAMMPS &lmp) {
  FixMap &fixes = fix_map(*lmp.modify);
  for (const FixRow &row : fix_table)
    fixes[row.name] = row.create;
}

std::vector<StyleName> registered_styles() {
  std::vector<StyleName> names;
  for (const FixRow &row : fix_table)
    names.push_back({"fix", row.name});
  return names;
}

} // namespace tri_driver
