#include "private_map_access.h"

namespace tri_driver {
namespace {

template <typename Tag, typename Tag::type Member> struct Expose {
  friend typename Tag::type member_of(Tag) { return Member; }
};

struct ModifyFixMap {
  using type = FixMap *LAMMPS_NS::Modify::*;
  friend type member_of(ModifyFixMap);
};
struct ModifyComputeMap {
  using type = ComputeMap *LAMMPS_NS::Modify::*;
  friend type member_of(ModifyComputeMap);
};

template struct Expose<ModifyFixMap, &LAMMPS_NS::Modify::fix_map>;
template struct Expose<ModifyComputeMap, &LAMMPS_NS::Modify::compute_map>;

} // namespace

FixMap &fix_map(LAMMPS_NS::Modify &modify) { return *(modify.*member_of(ModifyFixMap{})); }
ComputeMap &compute_map(LAMMPS_NS::Modify &modify) {
  return *(modify.*member_of(ModifyComputeMap{}));
}

} // namespace tri_driver
