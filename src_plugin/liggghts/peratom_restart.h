// LIGGGHTS hands a fix its per-atom restart values as the nth record of atom->extra[i], each
// record prefixed by its own length; this finds the values of record `nth` (after the prefix).
#pragma once

namespace tri_liggghts {

inline const double *restart_record(double *const *extra, int i, int nth) {
  int m = 0;
  for (int k = 0; k < nth; ++k)
    m += static_cast<int>(extra[i][m]);
  return &extra[i][m + 1];
}

} // namespace tri_liggghts
