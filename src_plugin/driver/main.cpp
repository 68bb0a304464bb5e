// liggghts-tri: Debian's LIGGGHTS with the triangulated-particle styles registered.
// It takes exactly liggghts's command line and runs the input the same way; the differences
// are the styles, registered as LIGGGHTS builds its style maps (post_create.cpp, also after
// `clear`), LIGGGHTS's error paths (error_output.cpp), `-screen none` (below), and the OpenMP
// threads of a rank when OMP_NUM_THREADS is unset (thread_default.h).
#include "style_registry.h"
#include "thread_default.h"

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

bool asks_for_help(int argc, char **argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "-help") == 0)
      return true;
  return false;
}

// LIGGGHTS prints its help from inside the LAMMPS constructor and then exits through
// Error::done(), so our styles are appended by an exit handler, on rank 0 only.
int help_rank = -1;
void print_tri_styles() {
  if (help_rank != 0)
    return;
  std::printf("* Styles added by liggghts-tri (triangulated particles):\n");
  for (const tri_driver::StyleName &s : tri_driver::registered_styles())
    std::printf("  %-8s %s\n", s.kind, s.name);
  std::printf("\n");
  std::fflush(stdout);
}

void install_signal_handlers() {
  // Same handlers as liggghts: SIGINT/SIGTERM ask for a clean stop, SIGUSR1 for a restart.
  struct sigaction quit_action {}, restart_action {};
  quit_action.sa_handler = LAMMPS_NS::SignalHandler::int_handler;
  sigaction(SIGINT, &quit_action, nullptr);
  sigaction(SIGTERM, &quit_action, nullptr);
  restart_action.sa_handler = LAMMPS_NS::SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &restart_action, nullptr);
}

// LIGGGHTS 3.8 writes to the screen without checking that there is one while fix mesh/surface
// reads its mesh file (InputMeshTri::meshtrifile), so `-screen none` ended a deck with a wall
// in a segmentation fault, in plain liggghts too. Outside partitioned runs (whose screens are
// files named after the argument, one per partition) /dev/null is passed instead: nothing is
// printed, as asked.
std::vector<char *> screen_none_to_null(int argc, char **argv) {
  static char dev_null[] = "/dev/null";
  std::vector<char *> args(argv, argv + argc + 1); // with argv[argc], the null, as main's
  const auto is = [&](int i, const char *name, const char *abbreviation) {
    return std::strcmp(args[i], name) == 0 || std::strcmp(args[i], abbreviation) == 0;
  };
  bool partitioned = false;
  for (int i = 1; i < argc; ++i)
    partitioned = partitioned || is(i, "-partition", "-p");
  for (int i = 1; !partitioned && i + 1 < argc; ++i)
    if (is(i, "-screen", "-sc") && std::strcmp(args[i + 1], "none") == 0)
      args[i + 1] = dev_null;
  return args;
}

} // namespace

int main(int argc, char **argv) {
  install_signal_handlers();
  MPI_Init(&argc, &argv);
  tri_driver::default_openmp_threads(MPI_COMM_WORLD);

  if (asks_for_help(argc, argv)) {
    MPI_Comm_rank(MPI_COMM_WORLD, &help_rank);
    std::atexit(print_tri_styles);
  }

  std::vector<char *> args = screen_none_to_null(argc, argv);
  // The styles register themselves as the instance is built (post_create.cpp).
  auto *lammps = new LAMMPS_NS::LAMMPS(argc, args.data(), MPI_COMM_WORLD);
  lammps->input->file();
  delete lammps;

  MPI_Finalize();
  return 0;
}
