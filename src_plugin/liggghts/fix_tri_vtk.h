// fix tri/vtk: every N steps, every particle's world-frame triangles as a VTK XML PolyData
// file for ParaView (FILE_<step>.vtp on one rank; FILE_<step>_<rank>.vtp pieces and a
// FILE_<step>.pvtp summary under MPI), plus FILE.pvd, the time series ParaView opens. Cell
// arrays per particle: id, shape, type, velocity, omega, force, torque and orientation (the
// quaternion w x y z, body principal frame to space; surface_writer.h).
//
// The wall meshes of the run (fix mesh/surface, where LIGGGHTS has moved them at that step)
// go with every frame: FILE_walls_<mesh ID>_<step>.vtp, one per mesh (gathered on rank 0,
// ordered by triangle ID, so the files do not depend on the number of ranks), and
// FILE_walls.pvd, the time series with one part per mesh (named by its ID).
//
//   fix ID all tri/vtk every N file FILE [walls yes|no|MESH_ID [MESH_ID ...]]
//
// walls: yes (default) writes every fix mesh/surface defined when the run starts (nothing when
// there is none), no writes none, a list of IDs writes those.
#pragma once

#include "fix.h"

#include "surface_writer.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixTriVTK : public Fix {
public:
  FixTriVTK(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;

private:
  class FixTriParticles *particles_ = nullptr;
  std::string base_;
  bigint last_written_ = -1;
  std::vector<std::pair<double, std::string>> frames_; // rank 0: the .pvd entries

  enum class Walls { all, none, listed } walls_ = Walls::all;
  std::vector<std::string> wall_ids_;               // listed, or (all) found at init
  std::vector<class FixMeshSurface *> walls_found_; // at init, in the order of wall_ids_
  std::vector<tri::PvdEntry> wall_frames_;          // rank 0: the walls' .pvd entries

  void write_frame();
  // Gathers mesh k's owned triangles on rank 0 and writes its .vtp there; returns the file
  // name (relative to the .pvd) on rank 0. Throws std::runtime_error on rank 0 only.
  std::string write_wall(std::size_t k, const std::string &step);
};

} // namespace LAMMPS_NS
