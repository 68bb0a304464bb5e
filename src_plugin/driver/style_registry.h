// The one place where liggghts-tri's styles are made known to LIGGGHTS.
#pragma once

#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_driver {

struct StyleName {
  const char *kind; // "pair", "fix" or "compute"
  const char *name; // as written in a deck, e.g. "tri/gran"
};

// Inserts every style into the maps of a freshly constructed LAMMPS instance.
void register_styles(LAMMPS_NS::LAMMPS &lmp);

// The styles register_styles adds, in table order (for -h).
std::vector<StyleName> registered_styles();

} // namespace tri_driver
