// fix tri/vtk: every N steps, every particle's world-frame triangles as a VTK XML PolyData
// file for ParaView (FILE_<step>.vtp on one rank; FILE_<step>_<rank>.vtp pieces and a
// FILE_<step>.pvtp summary under MPI), plus FILE.pvd, the time series ParaView opens.
//
//   fix ID all tri/vtk every N file FILE
#pragma once

#include "fix.h"

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
  void write_frame();
};

} // namespace LAMMPS_NS
