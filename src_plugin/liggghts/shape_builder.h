// The shapes of `fix tri/particles`, built from its parsed keywords (particle_options.h): mesh
// files read and scaled, random rocks generated, each validated and moved into its principal
// frame (tri::make_shape), then checked against the run: every shape fits in the box, and no
// mesh is finer than the soft layer. Every problem ends in error->all naming the shape (and
// the file).
#pragma once

#include "body/shape.h"
#include "particle_options.h"

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

// With `epsilon auto` (options.epsilon 0) the checks against epsilon wait for
// check_shapes_against_epsilon, once the value is known.
std::vector<tri::Shape> build_shapes(LAMMPS_NS::LAMMPS *lmp, const ParticleOptions &options);

// Every shape fits in the box with its soft layer, and no mesh is finer than the layer.
void check_shapes_against_epsilon(LAMMPS_NS::LAMMPS *lmp, const std::vector<tri::Shape> &shapes,
                                  double epsilon);

} // namespace tri_liggghts
