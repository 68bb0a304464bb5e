#include "fix_tri_vtk.h"

#include "fix_tri_particles.h"

#include "surface_writer.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include <cstdlib>
#include <exception>
#include <filesystem>

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriVTK::FixTriVTK(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  nevery = 0;
  for (int i = 3; i < narg; i += 2) {
    const std::string key = arg[i];
    if (i + 1 >= narg) {
      const std::string msg = "Fix tri/vtk: missing value after '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
    if (key == "every") {
      char *end = nullptr;
      const long n = std::strtol(arg[i + 1], &end, 10);
      if (*end != '\0' || n <= 0) {
        const std::string msg =
            std::string("Fix tri/vtk: 'every' must be a positive integer, got '") + arg[i + 1] + "'";
        error->all(FLERR, msg.c_str());
      }
      nevery = static_cast<int>(n);
    } else if (key == "file") {
      base_ = arg[i + 1];
    } else {
      const std::string msg = "Fix tri/vtk: unknown keyword '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (nevery <= 0 || base_.empty())
    error->all(FLERR, "Fix tri/vtk needs 'every N' and 'file NAME'");
}

int FixTriVTK::setmask() { return END_OF_STEP; }

void FixTriVTK::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Fix tri/vtk requires fix tri/particles (define it before the run)");
}

void FixTriVTK::setup(int) {
  if (update->ntimestep % nevery == 0)
    write_frame();
}

void FixTriVTK::end_of_step() { write_frame(); }

void FixTriVTK::write_frame() {
  if (last_written_ == update->ntimestep)
    return;
  last_written_ = update->ntimestep;

  const int nlocal = atom->nlocal;
  particles_->update_world_triangles(nlocal);
  tri::SurfaceCells cells;
  for (int i = 0; i < nlocal; ++i) {
    if (!(atom->mask[i] & groupbit) || particles_->shape_index(i) < 0)
      continue;
    cells.append_particle(particles_->world_triangles(i), atom->tag[i],
                          particles_->shape_index(i), atom->type[i], atom->v[i], atom->omega[i],
                          atom->f[i]);
  }

  const std::string step = std::to_string(update->ntimestep);
  const std::string stem = std::filesystem::path(base_).filename().string();
  std::string frame_file;
  int ok = 1;
  std::string what;
  try {
    if (comm->nprocs == 1) {
      frame_file = base_ + "_" + step + ".vtp";
      tri::write_vtp(frame_file, cells);
    } else {
      tri::write_vtp(base_ + "_" + step + "_" + std::to_string(comm->me) + ".vtp", cells);
      frame_file = base_ + "_" + step + ".pvtp";
      if (comm->me == 0) {
        std::vector<std::string> pieces;
        for (int r = 0; r < comm->nprocs; ++r)
          pieces.push_back(stem + "_" + step + "_" + std::to_string(r) + ".vtp");
        tri::write_pvtp(frame_file, pieces, cells);
      }
    }
    if (comm->me == 0) {
      const double time = update->get_cur_time();
      frames_.emplace_back(time, std::filesystem::path(frame_file).filename().string());
      tri::write_pvd(base_ + ".pvd", frames_);
    }
  } catch (const std::exception &e) {
    ok = 0;
    what = e.what();
  }
  int all_ok = 0;
  MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_MIN, world);
  if (!ok) {
    const std::string msg = "Fix tri/vtk: " + what;
    error->one(FLERR, msg.c_str());
  }
  if (!all_ok)
    error->all(FLERR, "Fix tri/vtk: writing the frame failed on another rank");
}
