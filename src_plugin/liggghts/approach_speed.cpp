#include "approach_speed.h"

#include "contact_board.h"

#include "atom.h"
#include "lammps.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <cmath>
#include <limits>

namespace tri_liggghts {
namespace {

// Calls f(i, j) for every pair of the list published on the board; false if there is none.
template <class F> bool for_each_listed_pair(const ContactBoard &board, F f) {
  const LAMMPS_NS::NeighList *list = board.particle_pairs();
  if (!list || !list->ilist)
    return false;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj)
      f(i, jlist[jj] & NEIGHMASK);
  }
  return true;
}

} // namespace

PairGeometry pair_approach(const double *xi, const double *vi, double radius_i,
                           const double *xj, const double *vj, double radius_j) {
  const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
  const double dv[3] = {vj[0] - vi[0], vj[1] - vi[1], vj[2] - vi[2]};
  const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  PairGeometry g;
  g.gap = r - radius_i - radius_j;
  // Coincident centres: no direction to approach along; count the whole relative speed.
  g.normal_speed = r > 0.0 ? -(dv[0] * d[0] + dv[1] * d[1] + dv[2] * d[2]) / r
                           : std::sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
  g.spin_speed = 0.0;
  return g;
}

PairGeometry pair_geometry(const LAMMPS_NS::Atom *atom, int i, int j) {
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const double *radius = atom->radius;
  PairGeometry g = pair_approach(x[i], v[i], radius[i], x[j], v[j], radius[j]);
  auto norm = [](const double *w) { return std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]); };
  g.spin_speed = norm(omega[i]) * radius[i] + norm(omega[j]) * radius[j];
  return g;
}

PairApproach pair_dt_limit(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board, double depth) {
  PairApproach out;
  out.dt_limit = std::numeric_limits<double>::infinity();
  const LAMMPS_NS::Atom *atom = lmp->atom;
  for_each_listed_pair(board, [&](int i, int j) {
    const PairGeometry g = pair_geometry(atom, i, j);
    const double closing = std::max(g.normal_speed, 0.0) + g.spin_speed;
    if (!(closing > 0.0))
      return;
    double limit;
    if (g.gap <= 0.0)
      limit = depth / closing;
    else if (g.normal_speed > 0.0)
      limit = g.gap / g.normal_speed + depth / closing;
    else
      return; // apart and not approaching: rotation alone cannot close a bounding-sphere gap
    if (limit < out.dt_limit) {
      out.dt_limit = limit;
      out.speed = closing;
      out.tag_i = atom->tag[i];
      out.tag_j = atom->tag[j];
    }
  });
  return out;
}

void FastestPair::consider(const PairGeometry &g, long i, long j) {
  if (g.gap < 0.0 && g.normal_speed > normal_speed) {
    normal_speed = g.normal_speed;
    tag_i = i;
    tag_j = j;
  }
}

FastestParticle fastest_particle(LAMMPS_NS::LAMMPS *lmp) {
  FastestParticle out;
  const LAMMPS_NS::Atom *atom = lmp->atom;
  double **v = atom->v, **omega = atom->omega;
  for (int i = 0; i < atom->nlocal; ++i) {
    const double speed = std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]) +
                         std::sqrt(omega[i][0] * omega[i][0] + omega[i][1] * omega[i][1] +
                                   omega[i][2] * omega[i][2]) *
                             atom->radius[i];
    if (speed > out.speed) {
      out.speed = speed;
      out.tag = atom->tag[i];
    }
  }
  return out;
}

} // namespace tri_liggghts
