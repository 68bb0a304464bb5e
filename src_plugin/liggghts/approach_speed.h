// How fast particles close in on each other, from the particle-pair neighbour list that the
// contact board holds (contact_board.h: published by pair tri/gran; every pair
// whose bounding spheres, radius = the contact reach, are within the neighbour skin).
// Read by fix tri/adapt_dt (to bound dt before a step); pair tri/gran measures its own tasks
// (the pairs within reach) with pair_geometry as they run, on the threads, and publishes the
// fastest approaching one for fix tri/particles (to recognise a step that carried a pair
// through its soft layers). Local to this rank: with `newton off`, a pair that spans two ranks
// is seen whole on both.
//
//   gap    |x_j - x_i| - radius_i - radius_j: below 0 the soft layers may touch (m)
//   normal speed   -(v_j - v_i) . (x_j - x_i) / |x_j - x_i|: > 0 when the centres approach
//   closing speed  normal speed + |omega_i| R_i + |omega_j| R_j (R: bounding radius): what
//                  any pair of surface points can approach at, rotation included (m/s)
#pragma once

namespace LAMMPS_NS {
class Atom;
class LAMMPS;
}

namespace tri_liggghts {

class ContactBoard;

struct PairApproach {
  // Largest step (s) that keeps every listed pair from advancing more than `depth` (m) into
  // the region where its soft layers may touch: a pair at gap g > 0 closing at normal speed
  // u first needs g / u to get there. +infinity when nothing approaches.
  double dt_limit;
  double speed = 0.0; // closing speed of the pair that sets dt_limit (m/s)
  long tag_i = 0, tag_j = 0;
};

// Pairs of the board's particle-pair list on this rank (none before a list is published).
PairApproach pair_dt_limit(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board, double depth);

// One pair's figures, as defined above (symmetric in i and j).
struct PairGeometry {
  double gap, normal_speed, spin_speed;
};
PairGeometry pair_geometry(const LAMMPS_NS::Atom *atom, int i, int j);
// The gap and normal speed alone (spin_speed 0), from the centres' positions and velocities
// (pair_geometry's own formulas): pair tri/gran passes its bodies' copies, already in cache.
PairGeometry pair_approach(const double *xi, const double *vi, double radius_i,
                           const double *xj, const double *vj, double radius_j);

// The pair within reach (gap < 0) whose centres approach fastest (normal speed only: a
// spinning pair that is being pushed apart is not approaching). Pair tri/gran offers each of
// its tasks (the pairs within reach) in task order and publishes the result on the board.
struct FastestPair {
  double normal_speed = 0.0; // m/s, largest among pairs within reach (gap < 0)
  long tag_i = 0, tag_j = 0;
  // Keeps the pair if it is within reach and approaches strictly faster (ties: the first).
  void consider(const PairGeometry &g, long tag_i, long tag_j);
  // The same over the pairs considered by `later` after this one's (ties: this one's).
  void merge(const FastestPair &later) {
    if (later.normal_speed > normal_speed)
      *this = later;
  }
};

struct FastestParticle {
  double speed = 0.0; // |v| + |omega| * radius, m/s
  long tag = 0;
};

// The fastest owned particle on this rank, rotation included.
FastestParticle fastest_particle(LAMMPS_NS::LAMMPS *lmp);

} // namespace tri_liggghts
