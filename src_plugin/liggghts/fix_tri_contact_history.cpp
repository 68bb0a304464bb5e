#include "fix_tri_contact_history.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "pair_gran.h"

#include <cstring>

using namespace LAMMPS_NS;

void FixTriContactHistory::init() {
  if (std::strcmp(style, "contacthistory") != 0 || !force->pair_match("tri/gran", 1)) {
    FixContactHistory::init();
    return;
  }
  if (atom->tag_enable == 0)
    error->all(FLERR, "Contact history requires atoms have IDs");
  auto *pair = static_cast<PairGran *>(force->pair_match("tri/gran", 1));
  if (dnum_ != pair->dnum())
    error->all(FLERR, "Fix contacthistory: its number of values differs from pair tri/gran's");
  pair_gran_ = pair;
  int dim = 0;
  computeflag_ = static_cast<int *>(pair->extract("computeflag", dim));
  allocate_pages();
}
