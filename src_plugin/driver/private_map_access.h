// LIGGGHTS 3.8 keeps the fix and compute style maps private in Modify and has no plugin
// command, so the only way to add styles without patching LIGGGHTS is to reach those maps.
// This is done here and nowhere else, with the standard-conforming member-pointer idiom:
// an explicit template instantiation may name a private member ([temp.explicit]/12), and a
// friend function defined in that instantiation hands the member pointer out. No macro
// tricks, no layout assumptions: if LIGGGHTS renames the members this stops compiling.
#pragma once

#include "modify.h"

#include <map>
#include <string>

namespace tri_driver {

using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using ComputeCreator = LAMMPS_NS::Compute *(*)(LAMMPS_NS::LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator>;
using ComputeMap = std::map<std::string, ComputeCreator>;

FixMap &fix_map(LAMMPS_NS::Modify &modify);
ComputeMap &compute_map(LAMMPS_NS::Modify &modify);

} // namespace tri_driver
