// How many OpenMP threads each MPI rank runs when the user did not say (OMP_NUM_THREADS unset).
#pragma once

#include <mpi.h>

namespace tri_driver {

// OpenMP's own default is every core the process may run on, per process: with several MPI
// ranks on one node each would start that many threads and the node would run ranks x cores
// threads, spinning at every barrier. Unset, the cores a rank may use are shared out among
// the ranks of its node instead (at least one thread each); set, OMP_NUM_THREADS is obeyed.
// Results do not depend on the thread count (bitwise), so this changes speed only.
void default_openmp_threads(MPI_Comm world);

} // namespace tri_driver
