// LIGGGHTS's fatal-error paths, each printing its ERROR line once.
//
// Why this file exists: Debian's libliggghts 3.8 follows the ERROR line of Error::all, one,
// universe_all, universe_one, fix_error and compute_error, two times in ten (rand() % 10, seeded
// by the time), with a "Tip of the day" or a "Comment from the off" that it formats into a
// std::string temporary, frees, and then prints: a second line of freed heap bytes and the same
// (file:line), on the screen and in the log, in plain liggghts too. A log with such a line is
// not text, and scripts reading ERROR lines choke on it.
//
// The library calls these functions through its procedure linkage table, so the definitions
// below, exported by the liggghts-tri executable (CMakeLists.txt), take their place for every
// caller: the library's own styles and ours. They do what the library's do -- the same
// messages, the same closing of the output, the same MPI ending and exit code -- without the
// tip. A new LIGGGHTS whose Error changes would need this file to follow; test_bad_input's
// repeated erroring deck (tests/decks) sees the garbage line again if it is dropped.
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "output.h"
#include "universe.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace LAMMPS_NS {

namespace {

void print_both(FILE *screen, FILE *log, const char *text) {
  if (screen)
    std::fputs(text, screen);
  if (log)
    std::fputs(text, log);
}

// "Fix STYLE (id ID): MESSAGE" or, for a message of two characters or fewer (LIGGGHTS's
// convention for "the arguments are wrong"), "Illegal fix STYLE (id ID) command".
void style_error_text(char *out, std::size_t size, const char *kind, const char *illegal_kind,
                      const char *style, const char *id, const char *message, const char *file,
                      int line) {
  if (std::strlen(message) > 2)
    std::snprintf(out, size, "ERROR: %s %s (id %s): %s (%s:%d)\n", kind, style, id, message, file,
                  line);
  else
    std::snprintf(out, size, "ERROR: Illegal %s %s (id %s) command (%s:%d)\n", illegal_kind,
                  style, id, file, line);
}

// The end of a world after its ERROR line: the output closed as LIGGGHTS closes it, the other
// partitions aborted, exit code 1.
[[noreturn]] void end_world(Output *&output, FILE *screen, FILE *logfile, Universe *universe) {
  delete output;
  output = nullptr;
  if (screen && screen != stdout)
    std::fclose(screen);
  if (logfile)
    std::fclose(logfile);
  if (universe->nworlds > 1)
    MPI_Abort(universe->uworld, 1);
  MPI_Finalize();
  std::exit(1);
}

} // namespace

// Called by every process of one world: the message from its first, then the world ends.
void Error::all(const char *file, int line, const char *str) {
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    if (screen)
      std::fprintf(screen, "ERROR: %s (%s:%d)\n", str, file, line);
    if (logfile)
      std::fprintf(logfile, "ERROR: %s (%s:%d)\n", str, file, line);
  }
  end_world(output, screen, logfile, universe);
}

void Error::fix_error(const char *file, int line, Fix *fix, const char *str) {
  fix_error(file, line, fix, fix->style, str);
}

void Error::fix_error(const char *file, int line, Fix *fix, const char *style, const char *str) {
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    char text[2048];
    style_error_text(text, sizeof text, "Fix", "fix", style, fix->id, str, file, line);
    print_both(screen, logfile, text);
  }
  end_world(output, screen, logfile, universe);
}

void Error::compute_error(const char *file, int line, Compute *compute, const char *str) {
  MPI_Barrier(world);
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (me == 0) {
    char text[2048];
    style_error_text(text, sizeof text, "Compute", "compute", compute->style, compute->id, str,
                     file, line);
    print_both(screen, logfile, text);
  }
  end_world(output, screen, logfile, universe);
}

// Called by one process of a world: its message, then the whole world is aborted.
void Error::one(const char *file, int line, const char *str) {
  int me = 0;
  MPI_Comm_rank(world, &me);
  if (screen)
    std::fprintf(screen, "ERROR on proc %d: %s (%s:%d)\n", me, str, file, line);
  if (universe->nworlds > 1 && universe->uscreen)
    std::fprintf(universe->uscreen, "ERROR on proc %d: %s (%s:%d)\n", universe->me, str, file,
                 line);
  if (screen)
    std::fflush(screen);
  MPI_Abort(world, 1);
  std::exit(1); // not reached
}

// Called by every process of the universe (all partitions).
void Error::universe_all(const char *file, int line, const char *str) {
  MPI_Barrier(universe->uworld);
  if (universe->me == 0) {
    if (universe->uscreen)
      std::fprintf(universe->uscreen, "ERROR: %s (%s:%d)\n", str, file, line);
    if (universe->ulogfile)
      std::fprintf(universe->ulogfile, "ERROR: %s (%s:%d)\n", str, file, line);
  }
  if (output)
    delete output;
  if (universe->nworlds > 1) {
    if (screen && screen != stdout)
      std::fclose(screen);
    if (logfile)
      std::fclose(logfile);
  }
  if (universe->ulogfile)
    std::fclose(universe->ulogfile);
  MPI_Finalize();
  std::exit(1);
}

// Called by one process of the universe.
void Error::universe_one(const char *file, int line, const char *str) {
  if (universe->uscreen)
    std::fprintf(universe->uscreen, "ERROR on proc %d: %s (%s:%d)\n", universe->me, str, file,
                 line);
  MPI_Abort(universe->uworld, 1);
  std::exit(1); // not reached
}

} // namespace LAMMPS_NS
