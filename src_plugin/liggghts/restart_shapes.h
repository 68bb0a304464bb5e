// The global restart record of fix tri/particles: what a deck must repeat for a restart file's
// particles to mean the same. A restart file holds, per atom, a shape index, an orientation
// and an angular momentum; the shapes themselves, epsilon and density are rebuilt from the
// deck that reads it. If those differ, every particle silently changes its surface, mass or
// soft layer, so read_restart stops and says exactly what differs.
//
// Record (written by rank 0, all values native-endian, no padding, read with memcpy):
//   8 bytes  "tri/rst3"                  magic and version
//   double   epsilon (m), density (kg/m^3)
//   int64    1 with the soft layer inside the meshes (`layer inside`), 0 outside
//   int64    number of shapes
//   per shape: int64 name length, the name's bytes, int64 triangle count, double volume (m^3),
//              double bounding radius (m), 3 x double principal moments per density (m^5)
// A "tri/rst2" record (the same without the layer field) was written when the soft layer always
// lay outside the meshes: it reads as `layer outside`, so a deck that wants to continue it
// says so, and one that does not is told why its particles would change.
// Restart files of liggghts-tri before this record (a fingerprint, density, epsilon: three
// doubles) are refused with a message that says so; they cannot be read.
#pragma once

#include "body/shape.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tri_liggghts {

struct ShapeRecord {
  std::string name;
  long long triangles = 0;
  double volume = 0.0, bounding_radius = 0.0;
  double inertia_per_density[3] = {0.0, 0.0, 0.0};
};

struct ParticlesRecord {
  double epsilon = 0.0, density = 0.0;
  bool layer_inside = true;
  std::vector<ShapeRecord> shapes;
};

ParticlesRecord make_record(const std::vector<tri::Shape> &shapes, double epsilon, double density,
                            bool layer_inside);

std::vector<char> encode(const ParticlesRecord &record);

// Throws std::runtime_error (a message for the user) when `buf` does not start with the
// magic: a restart file written by an older liggghts-tri.
ParticlesRecord decode(const char *buf);

// "" when the deck repeats the restart file's particles; otherwise every difference, joined by
// "; ", e.g. "epsilon 0.0001 in the restart file, 0.0002 in this deck" or "shape 2 'rock40':
// 40 triangles, volume 3.1e-09 m^3 in the restart file; 'rock40': 20 triangles, volume
// 2.9e-09 m^3 in this deck". Shapes are numbered from 1 in the order of the deck's `shape`
// keywords. Names and triangle counts must be equal; volumes, bounding radii and moments
// within 1e-9 relative (the same mesh on another build); epsilon and density exactly.
std::string differences(const ParticlesRecord &file, const ParticlesRecord &deck);

} // namespace tri_liggghts
