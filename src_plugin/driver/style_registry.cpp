// To add a style: write its class in src_plugin/liggghts/, include its header here and add
// one row to the matching table below. Nothing else in the project lists styles.
#include "style_registry.h"

#include "private_map_access.h"

#include "compute_tri_contact_atom.h"
#include "compute_tri_contact_local.h"
#include "compute_tri_erotate.h"
#include "compute_tri_stats.h"
#include "fix_tri_adapt_dt.h"
#include "fix_tri_contact_history.h"
#include "fix_tri_kept_contacts.h"
#include "fix_tri_nve.h"
#include "fix_tri_particles.h"
#include "fix_tri_template_sphere.h"
#include "fix_tri_vtk.h"
#include "fix_tri_wall.h"
#include "pair_tri_gran.h"

#include "force.h"
#include "lammps.h"
#include "modify.h"

#include <string>

namespace tri_driver {
namespace {

template <typename T> LAMMPS_NS::Fix *make_fix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) {
  return new T(lmp, narg, arg);
}
template <typename T>
LAMMPS_NS::Compute *make_compute(LAMMPS_NS::LAMMPS *lmp, int iarg, int narg, char **arg) {
  return new T(lmp, iarg, narg, arg); // LIGGGHTS computes take iarg by reference
}

struct ComputeRow {
  const char *name;
  ComputeCreator create;
};

const ComputeRow compute_table[] = {
    {"tri/stats", &make_compute<LAMMPS_NS::ComputeTriStats>},
    {"tri/erotate", &make_compute<LAMMPS_NS::ComputeTriERotate>},
    {"tri/contact/local", &make_compute<LAMMPS_NS::ComputeTriContactLocal>},
    {"tri/contact/atom", &make_compute<LAMMPS_NS::ComputeTriContactAtom>},
};

template <typename T> LAMMPS_NS::Pair *make_pair(LAMMPS_NS::LAMMPS *lmp) { return new T(lmp); }

struct PairRow {
  const char *name;
  LAMMPS_NS::Pair *(*create)(LAMMPS_NS::LAMMPS *);
};

const PairRow pair_table[] = {
    {"tri/gran", &make_pair<LAMMPS_NS::PairTriGran>},
};

struct FixRow {
  const char *name;
  FixCreator create;
};

const FixRow fix_table[] = {
    {"tri/particles", &make_fix<LAMMPS_NS::FixTriParticles>},
    {"tri/nve", &make_fix<LAMMPS_NS::FixTriNVE>},
    {"tri/vtk", &make_fix<LAMMPS_NS::FixTriVTK>},
    {"tri/wall", &make_fix<LAMMPS_NS::FixTriWall>},
    // pair tri/gran's kept contact points (fix_tri_kept_contacts.h), created by the pair
    {"tri/kept_contacts", &make_fix<LAMMPS_NS::FixTriKeptContacts>},
    {"tri/adapt_dt", &make_fix<LAMMPS_NS::FixTriAdaptDt>},
    // Replaces LIGGGHTS's own: same behaviour for pair gran, and it also serves tri/gran.
    {"contacthistory", &make_fix<LAMMPS_NS::FixTriContactHistory>},
    // Replaces LIGGGHTS's own: the same template, which also gives inserted particles a shape
    // once fix tri/particles exists (fix_tri_template_sphere.h).
    {"particletemplate/sphere", &make_fix<LAMMPS_NS::FixTriTemplateSphere>},
};

} // namespace

void register_styles(LAMMPS_NS::LAMMPS &lmp) {
  for (const PairRow &row : pair_table)
    (*lmp.force->pair_map)[row.name] = row.create; // Force keeps this map public
  ComputeMap &computes = compute_map(*lmp.modify);
  for (const ComputeRow &row : compute_table)
    computes[row.name] = row.create;
  FixMap &fixes = fix_map(*lmp.modify);
  for (const FixRow &row : fix_table)
    fixes[row.name] = row.create;
}

std::vector<StyleName> registered_styles() {
  std::vector<StyleName> names;
  for (const PairRow &row : pair_table)
    names.push_back({"pair", row.name});
  for (const FixRow &row : fix_table)
    if (std::string(row.name).rfind("tri/", 0) == 0) // not the replaced LIGGGHTS styles
      names.push_back({"fix", row.name});
  for (const ComputeRow &row : compute_table)
    names.push_back({"compute", row.name});
  return names;
}

} // namespace tri_driver
