#include "thread_default.h"

#include <omp.h>

#include <algorithm>
#include <cstdlib>

namespace tri_driver {

void default_openmp_threads(MPI_Comm world) {
  if (std::getenv("OMP_NUM_THREADS"))
    return;
  MPI_Comm node;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks_on_node = 1;
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
  // omp_get_num_procs: the cores this process may run on (its affinity mask), so a rank that
  // mpirun bound to one core gets one thread.
  omp_set_num_threads(std::max(1, omp_get_num_procs() / ranks_on_node));
}

} // namespace tri_driver
