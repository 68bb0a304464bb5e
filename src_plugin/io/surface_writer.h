// Particle surfaces out to ParaView: one .vtp per rank and frame, a .pvtp per frame that
// joins the ranks' pieces, and a .pvd collection that makes the frames one time series. Wall
// meshes out the same way: one .vtp per mesh and frame, and a .pvd with one part per mesh.
//
// What is written: every triangle of every particle, in the world frame (m), as a VTK
// triangle with its own 3 points (corners are replicated, as in TriangleSoA; ParaView does
// not mind and no index map is needed). Cell data, one tuple per triangle, all taken from
// the owning particle: "id" (Int64, atom tag), "shape" (Int32, shape index), "type"
// (Int32, atom type), "velocity" (m/s), "omega" (rad/s), "force" (N), "torque" (N m), all
// 3-component Float64 in the space frame, and "orientation" (4-component Float64, the unit
// quaternion w x y z that turns the body principal frame into the space frame, as f_ID[2..5]
// of fix tri/particles). Colour by "id" to see particles, by "velocity" etc.
//
// No MPI here: the caller (fix tri/vtk) has each rank write its own piece and rank 0 write
// the .pvtp and .pvd. No LIGGGHTS either; VTK stays private to this library's sources.
// Parent directories of every output path are created if missing. Failures throw
// std::runtime_error with the path in the message (the fix turns it into error->one).
#pragma once

#include "geometry/triangle_soa.h"

#include <string>
#include <utility>
#include <vector>

namespace tri {

// The per-particle values that every triangle of a particle carries (see above).
struct ParticleValues {
  long long id = 0;
  int shape = 0, type = 0;
  double velocity[3] = {0, 0, 0}, omega[3] = {0, 0, 0}, force[3] = {0, 0, 0};
  double torque[3] = {0, 0, 0};
  double orientation[4] = {1, 0, 0, 0}; // w x y z
};

// One rank's particles, flattened triangle by triangle. All vectors grow together:
// xyz 9 per triangle (corner 0 x,y,z, corner 1 x,y,z, corner 2 x,y,z), atom_id, shape_id and
// type 1 per triangle, velocity, omega, force and torque 3 per triangle, orientation 4.
struct SurfaceCells {
  std::vector<double> xyz;
  std::vector<long long> atom_id;
  std::vector<int> shape_id, type;
  std::vector<double> velocity, omega, force, torque, orientation;

  // Appends all triangles of one particle, `world` already in the world frame; `values` are
  // copied onto every one of its triangles.
  void append_particle(const TriangleSoA &world, const ParticleValues &values);
  // Empties the arrays, keeping their capacity (one SurfaceCells can serve every frame).
  void clear();
  int num_triangles() const { return static_cast<int>(atom_id.size()); }
};

// Writes one VTK XML PolyData file (vtkXMLPolyDataWriter, binary appended data, zlib, 64-bit
// headers). Throws std::runtime_error naming `path` if the arrays of `cells` disagree in
// size or the file cannot be written. Zero triangles is valid (an empty piece).
void write_vtp(const std::string &path, const SurfaceCells &cells);

// Writes the .pvtp summary of one frame: the same point and cell arrays as write_vtp
// declares for `schema_example` (only its array names and types are used, not its data),
// and one <Piece Source=...> per entry of `piece_files`, named relative to the .pvtp's
// directory (as ParaView resolves them). The pieces need not exist yet.
void write_pvtp(const std::string &path, const std::vector<std::string> &piece_files,
                const SurfaceCells &schema_example);

// Writes (or rewrites, atomically: a temporary file renamed over `path`) a ParaView .pvd
// collection with one DataSet per (time in s, file relative to the .pvd) entry, in the
// given order. Times are printed with 17 significant digits so distinct times stay distinct.
void write_pvd(const std::string &path, const std::vector<std::pair<double, std::string>> &frames);

// The triangles of one wall mesh (a LIGGGHTS fix mesh/surface), in the world frame as it is at
// the frame's step. Cell data: "id" (Int64, the mesh's triangle ID) and "velocity" (m/s,
// 3-component Float64, the mean of the triangle's node velocities; 0 for a mesh that does not
// move). All vectors grow together: xyz 9 per triangle, triangle_id 1, velocity 3.
struct WallCells {
  std::vector<double> xyz;
  std::vector<long long> triangle_id;
  std::vector<double> velocity;

  void append_triangle(long long id, const double corners[9], const double v[3]);
  void clear();
  int num_triangles() const { return static_cast<int>(triangle_id.size()); }
};

// As write_vtp, for a wall mesh.
void write_wall_vtp(const std::string &path, const WallCells &cells);

// One DataSet of a .pvd: a file (relative to the .pvd) at a time (s); `part` numbers the
// datasets of one time (ParaView reads them as the blocks of one multiblock data set) and
// `name`, if not empty, names the block.
struct PvdEntry {
  double time = 0.0;
  std::string file;
  int part = 0;
  std::string name;
};

// As write_pvd above, with parts and names (the walls: one part per mesh, named by its ID).
void write_pvd_parts(const std::string &path, const std::vector<PvdEntry> &entries);

} // namespace tri
