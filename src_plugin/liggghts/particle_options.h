// The keywords of `fix tri/particles`, parsed once, before any shape is built.
//
//   fix ID all tri/particles shape NAME random ntri N size D seed S [aspect B C] ...
//                            shape NAME file PATH [scale F] ...
//                            [assign random SEED | assign type]
//                            [template TEMPLATE_ID SHAPE_NAME] ...
//                            density RHO [epsilon EPS | epsilon auto]
//                            [orient random SEED | orient none | orient file]
//                            [check_timestep setup | check_timestep N | check_timestep off]
//                            [layer inside | layer outside]
// epsilon auto (the default): the soft layer from the contact material (material_scales.h).
// layer inside (the default): the soft layer lies inside the given mesh, which is the contact
// surface (kernel/body/inner_surface.h); layer outside: it lies outside, the particles touch with
// their meshes 2 epsilon apart (the convention of liggghts-tri before, for comparison).
// check_timestep: the time-step check (tri/timestep_rule.h) at the start of every run (setup,
// the default), also every N steps, or never.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {
class Error;
}

namespace tri_liggghts {

struct ShapeSpec {
  std::string name;
  bool from_file = false;
  // random rock
  int ntri = 0;
  double size = 0.0; // bounding diameter, m
  std::uint64_t seed = 0;
  double aspect_middle = 1.0, aspect_short = 1.0;
  // mesh file
  std::string path;
  double scale = 1.0;
};

struct ParticleOptions {
  std::vector<ShapeSpec> shapes;
  bool assign_by_type = false;    // else random by tag
  std::uint64_t assign_seed = 0;
  double density = 0.0;           // kg/m^3
  double epsilon = 0.0;           // soft-layer width, m (0 with epsilon_auto until resolved)
  bool epsilon_auto = false;      // `epsilon auto`, or no epsilon given
  bool layer_inside = true;       // `layer inside` (default) or `layer outside`
  int check_timestep_every = 0;   // -1: off, 0: at setup only, N > 0: also every N steps
  bool orient_random = false;
  std::uint64_t orient_seed = 0;
  bool orient_file = false;       // start in the input (file or generator) frame
  // `template ID SHAPE`: particles inserted from fix particletemplate/sphere ID get the shape
  // of that index (particle_insertion.h). In the order given; IDs and shapes checked here.
  std::vector<std::pair<std::string, int>> templates;
};

// Parses arg[first..narg) of the fix command. Every problem ends in error->all naming the
// keyword and value.
ParticleOptions parse_particle_options(int narg, char **arg, int first, LAMMPS_NS::Error *error);

} // namespace tri_liggghts
