#include "fix_tri_vtk.h"

#include "fix_tri_particles.h"

#include "surface_writer.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "modify.h"
#include "tri_mesh.h"
#include "update.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <filesystem>

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriVTK::FixTriVTK(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  nevery = 0;
  auto is_keyword = [](const std::string &w) {
    return w == "every" || w == "file" || w == "walls";
  };
  for (int i = 3; i < narg;) {
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
            std::string("Fix tri/vtk: 'every' must be a positive integer, got '") + arg[i + 1] +
            "'";
        error->all(FLERR, msg.c_str());
      }
      nevery = static_cast<int>(n);
      i += 2;
    } else if (key == "file") {
      base_ = arg[i + 1];
      i += 2;
    } else if (key == "walls") {
      const std::string value = arg[i + 1];
      wall_ids_.clear();
      if (value == "yes") {
        walls_ = Walls::all;
        i += 2;
      } else if (value == "no") {
        walls_ = Walls::none;
        i += 2;
      } else { // mesh IDs up to the next keyword; checked at init (meshes may come later)
        walls_ = Walls::listed;
        for (++i; i < narg && !is_keyword(arg[i]); ++i)
          wall_ids_.push_back(arg[i]);
        if (wall_ids_.empty())
          error->all(FLERR, "Fix tri/vtk: 'walls' expects yes, no or IDs of fix mesh/surface");
      }
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
  walls_found_.clear();
  if (walls_ == Walls::all) {
    wall_ids_.clear();
    for (int k = 0; k < modify->nfix; ++k)
      if (auto *mesh = dynamic_cast<FixMeshSurface *>(modify->fix[k])) {
        wall_ids_.push_back(mesh->id);
        walls_found_.push_back(mesh);
      }
  } else if (walls_ == Walls::listed) {
    for (const std::string &id : wall_ids_) {
      auto *mesh = dynamic_cast<FixMeshSurface *>(modify->find_fix_id(id.c_str()));
      if (!mesh) {
        const std::string msg =
            "Fix tri/vtk: 'walls' expects yes, no or IDs of fix mesh/surface, got '" + id + "'";
        error->all(FLERR, msg.c_str());
      }
      walls_found_.push_back(mesh);
    }
  }
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
  tri::SurfaceCells cells;
  tri::TriangleSoA surface;
  for (int i = 0; i < nlocal; ++i) {
    if (!(atom->mask[i] & groupbit) || particles_->shape_index(i) < 0)
      continue;
    tri::ParticleValues values;
    values.id = atom->tag[i];
    values.shape = particles_->shape_index(i);
    values.type = atom->type[i];
    const Eigen::Quaterniond q = particles_->orientation(i);
    const double wxyz[4] = {q.w(), q.x(), q.y(), q.z()};
    std::copy(wxyz, wxyz + 4, values.orientation);
    for (int k = 0; k < 3; ++k) {
      values.velocity[k] = atom->v[i][k];
      values.omega[k] = atom->omega[i][k];
      values.force[k] = atom->f[i][k];
      values.torque[k] = atom->torque[i][k];
    }
    particles_->given_surface(i, surface);
    cells.append_particle(surface, values);
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
  // Every rank takes part in each wall's gather, whatever happened above; only rank 0 writes.
  const double now = update->get_cur_time();
  for (std::size_t k = 0; k < walls_found_.size(); ++k) {
    std::string file;
    try {
      file = write_wall(k, step);
    } catch (const std::exception &e) {
      if (ok)
        what = e.what();
      ok = 0;
    }
    if (comm->me == 0 && ok)
      wall_frames_.push_back(tri::PvdEntry{now, file, static_cast<int>(k), wall_ids_[k]});
  }
  if (comm->me == 0 && ok && !walls_found_.empty()) {
    try {
      tri::write_pvd_parts(base_ + "_walls.pvd", wall_frames_);
    } catch (const std::exception &e) {
      ok = 0;
      what = e.what();
    }
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

std::string FixTriVTK::write_wall(std::size_t k, const std::string &step) {
  // Per owned triangle: its ID, 9 corner coordinates, the mean node velocity.
  constexpr int kPer = 13;
  TriMesh *mesh = walls_found_[k]->triMesh();
  auto *vnodes = mesh->prop().getElementProperty<MultiVectorContainer<double, 3, 3>>("v");
  const int nlocal = mesh->sizeLocal();
  std::vector<double> mine(static_cast<std::size_t>(kPer) * nlocal);
  for (int t = 0; t < nlocal; ++t) {
    double *r = &mine[static_cast<std::size_t>(kPer) * t];
    r[0] = mesh->id(t);
    for (int c = 0; c < 3; ++c) {
      mesh->node(t, c, r + 1 + 3 * c);
      for (int d = 0; d < 3; ++d)
        r[10 + d] += vnodes ? vnodes->begin()[t][c][d] / 3.0 : 0.0;
    }
  }
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(comm->nprocs), offsets(comm->nprocs, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  std::vector<double> all;
  if (comm->me == 0) {
    for (int r = 1; r < comm->nprocs; ++r)
      offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(offsets.back()) + counts.back());
  }
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
              0, world);
  if (comm->me != 0)
    return "";

  const std::size_t n = all.size() / kPer;
  std::vector<std::size_t> order(n);
  for (std::size_t t = 0; t < n; ++t)
    order[t] = t;
  std::sort(order.begin(), order.end(),
            [&all](std::size_t a, std::size_t b) { return all[kPer * a] < all[kPer * b]; });
  tri::WallCells cells;
  for (std::size_t t : order) {
    const double *r = &all[kPer * t];
    cells.append_triangle(static_cast<long long>(r[0]), r + 1, r + 10);
  }
  const std::string name = std::filesystem::path(base_).filename().string() + "_walls_" +
                           wall_ids_[k] + "_" + step + ".vtp";
  tri::write_wall_vtp((std::filesystem::path(base_).parent_path() / name).string(), cells);
  return name;
}
