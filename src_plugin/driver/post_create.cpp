// LAMMPS::post_create, the library's last step of building an instance's styles: in its
// constructor and again after every `clear`, which throws away the Force, Modify and Output
// whose style maps hold ours. Defined here (exported by the executable, CMakeLists.txt), it
// takes the library's place for both callers, so the styles of liggghts-tri are registered
// wherever LIGGGHTS's own are: `clear` keeps them. What the library's does (the accelerator
// suffix packages) comes first, unchanged.
#include "style_registry.h"

#include "input.h"
#include "lammps.h"

#include <cstring>

namespace LAMMPS_NS {

void LAMMPS::post_create() {
  if (suffix && suffix_enable) {
    if (std::strcmp(suffix, "gpu") == 0)
      input->one("package gpu force/neigh 0 0 1");
    if (std::strcmp(suffix, "omp") == 0)
      input->one("package omp *");
  }
  tri_driver::register_styles(*this);
}

} // namespace LAMMPS_NS
