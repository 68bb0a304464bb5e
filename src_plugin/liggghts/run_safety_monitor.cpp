#include "run_safety_monitor.h"

#include "approach_speed.h"
#include "step_tally.h"

#include "contact/penetration_depth.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <cstdio>

namespace tri_liggghts {

// A pair within reach that this step brought more than epsilon closer, while there are
// contacts on this rank (it is in contact, or about to be), cannot be resolved by the soft
// layer. Local: with newton off every pair is seen whole on each rank that owns one of its
// particles. Reported in end_of_step.
void RunSafetyMonitor::after_pair_forces(const ContactBoard &board) {
  unresolved_ = Unresolved{};
  if (board.sources(SourceKind::particle_pairs) == 0 ||
      board.local(TallySource::pair).contacts_after == 0)
    return;
  const FastestPair &p = board.fastest_pair();
  unresolved_.step = p.normal_speed * lmp_->update->dt;
  unresolved_.speed = p.normal_speed;
  unresolved_.tag_i = p.tag_i;
  unresolved_.tag_j = p.tag_j;
}

void RunSafetyMonitor::end_of_step(const ContactBoard &board) {
  const LAMMPS_NS::Update *update = lmp_->update;
  if (!initial_checked_ && update->ntimestep == update->firststep + 1) {
    initial_checked_ = true;
    check_initial_overlaps(board);
  }
  find_unresolved_wall_contact(board);
  report_unresolved_contacts();
  if (!warned_)
    warn_first_penetration(board);
  check_deep_contacts(board);
}

// A contact deeper than the depth through the intersection can resolve (past it a sunk vertex
// may leave through the far side and the force would collapse). All ranks agree on the deepest
// (MPI_MAXLOC), then stop together, naming it.
void RunSafetyMonitor::check_deep_contacts(const ContactBoard &board) {
  const DeepestContact mine_d = board.deepest();
  struct {
    double ratio;
    int rank;
  } mine{mine_d.depth_of_limit, lmp_->comm->me}, worst;
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, lmp_->world);
  if (!(worst.ratio > 1.0))
    return;
  double info[5] = {mine_d.overlap, mine_d.layer, mine_d.limit, double(mine_d.tag_a),
                    double(mine_d.tag_b)};
  char wall[64] = "";
  std::snprintf(wall, sizeof wall, "%s", mine_d.wall.c_str());
  MPI_Bcast(info, 5, MPI_DOUBLE, worst.rank, lmp_->world);
  MPI_Bcast(wall, sizeof wall, MPI_CHAR, worst.rank, lmp_->world);
  char who[120];
  if (info[4] > 0.0)
    std::snprintf(who, sizeof who, "particles %.0f and %.0f", info[3], info[4]);
  else
    std::snprintf(who, sizeof who, "particle %.0f and wall mesh '%s'", info[3], wall);
  const double depth = info[0] - info[1];
  char msg[900];
  std::snprintf(msg, sizeof msg,
                "Fix tri/particles: step " BIGINT_FORMAT ": the real surfaces of %s intersect "
                "%g m deep past their soft layers (overlap %g m = %.3g x the combined layer %g m), "
                "deeper than the contact model resolves, %g m (%g of the thinner body's thinnest "
                "extent): the repulsion would collapse as the surfaces pass through each other; "
                "use a stiffer kn (a linear spring stops an impact at v sqrt(m_eff / kn)), slower "
                "impacts, a wider epsilon (more of the contact inside the soft layer) or a smaller "
                "dt (if one step carries the bodies that far)",
                lmp_->update->ntimestep, who, depth, info[0], info[0] / info[1], info[1], info[2],
                tri::kDeepContactLimitFraction);
  lmp_->error->all(FLERR, msg);
}

// One reduction of one count per step until the first intersection of the run.
void RunSafetyMonitor::warn_first_penetration(const ContactBoard &board) {
  long long mine = board.local(TallySource::all).penetrations, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, lmp_->world);
  if (all == 0)
    return;
  warned_ = true;
  const tri::InteractionTally t = global_tally(board, lmp_->world);
  IntersectingPair p = board.first_intersecting(SourceKind::particle_pairs);
  if (!p.found())
    p = board.first_intersecting(SourceKind::walls);
  double tags[2] = {double(p.tag_a), double(p.tag_b)}, found[2];
  MPI_Allreduce(tags, found, 2, MPI_DOUBLE, MPI_MAX, lmp_->world);
  char who[100];
  if (found[1] > 0.0)
    std::snprintf(who, sizeof who, "e.g. particles %.0f and %.0f", found[0], found[1]);
  else
    std::snprintf(who, sizeof who, "e.g. particle %.0f and a wall", found[0]);
  char msg[600];
  std::snprintf(msg, sizeof msg,
                "tri/particles: step " BIGINT_FORMAT ": real surfaces intersect for the first "
                "time in this run (%lld interaction(s), %s; deepest overlap %g m = %.3g x the "
                "combined soft layer 2 epsilon): the soft layer is overrun; a stiffer kn, a wider "
                "epsilon or a smaller dt keeps contacts within it (compute tri/stats counts them "
                "as penetrations)",
                lmp_->update->ntimestep, all, who, t.max_overlap, t.max_overlap / (2.0 * epsilon_));
  if (lmp_->comm->me == 0)
    lmp_->error->warning(FLERR, msg);
}

// Particles created inside each other or a wall. A shallow intersection is pushed apart, but
// past about the soft-layer width the triangle contacts of a deep one point every way and
// their forces can cancel, leaving the particles stuck inside each other, so the first step
// of the first run stops instead, naming one pair.
void RunSafetyMonitor::check_initial_overlaps(const ContactBoard &board) {
  const tri::InteractionTally pair = global_tally(board, lmp_->world, TallySource::pair);
  const tri::InteractionTally wall = global_tally(board, lmp_->world, TallySource::wall);
  if (pair.penetrations + wall.penetrations == 0)
    return;
  const IntersectingPair mine = board.first_intersecting(SourceKind::particle_pairs);
  double tags[2] = {double(mine.tag_a), double(mine.tag_b)}, found[2];
  MPI_Allreduce(tags, found, 2, MPI_DOUBLE, MPI_MAX, lmp_->world);
  char example[80] = "";
  if (found[0] > 0.0)
    std::snprintf(example, sizeof example, ", e.g. particles %.0f and %.0f", found[0], found[1]);
  char msg[600];
  std::snprintf(msg, sizeof msg,
                "Fix tri/particles: the run starts with intersecting surfaces (%lld particle "
                "pair(s)%s; %lld particle-wall contact(s)): particles created inside each other "
                "or inside a wall cannot be pushed apart reliably (the contact force acts in "
                "the soft layers); create them with their meshes apart (with 'layer outside': at "
                "least 2 x epsilon apart)",
                pair.penetrations, example, wall.penetrations);
  lmp_->error->all(FLERR, msg);
}

// Walls: a wall's direction is not known here, so only once real surfaces intersect, and only
// a particle that moves against its force (approaching; one pushed out of a wall moves with
// it). Kept only if it moves farther per step than the pair found in after_pair_forces.
void RunSafetyMonitor::find_unresolved_wall_contact(const ContactBoard &board) {
  if (board.local(TallySource::wall).penetrations == 0)
    return;
  const LAMMPS_NS::Atom *atom = lmp_->atom;
  const double dt = lmp_->update->dt;
  double **v = atom->v, **f = atom->f;
  for (int i = 0; i < atom->nlocal; ++i) {
    const double speed = std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    const double along_force = v[i][0] * f[i][0] + v[i][1] * f[i][1] + v[i][2] * f[i][2];
    if (along_force < 0.0 && speed * dt > unresolved_.step) {
      unresolved_.step = speed * dt;
      unresolved_.speed = speed;
      unresolved_.tag_i = atom->tag[i];
      unresolved_.tag_j = 0;
    }
  }
}

// error->one would abort without flushing the screen (the message is lost in a pipe), so the
// ranks agree first and stop together with error->all.
void RunSafetyMonitor::report_unresolved_contacts() {
  struct {
    double step;
    int rank;
  } mine{unresolved_.step, lmp_->comm->me}, worst;
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, lmp_->world);
  if (!(worst.step > epsilon_))
    return;
  double info[3] = {unresolved_.speed, double(unresolved_.tag_i), double(unresolved_.tag_j)};
  MPI_Bcast(info, 3, MPI_DOUBLE, worst.rank, lmp_->world);
  const double dt = lmp_->update->dt;
  const char *advice = lmp_->modify->find_fix_style("tri/adapt_dt", 0)
                           ? "lower dtmin of fix tri/adapt_dt"
                           : "use a smaller timestep or fix tri/adapt_dt";
  char msg[600];
  if (info[2] > 0.0)
    std::snprintf(msg, sizeof msg,
                  "Fix tri/particles: step " BIGINT_FORMAT ": particles %.0f and %.0f meet at "
                  "%g m/s, %g m per time step of %g s, more than epsilon (%g m): the soft layer "
                  "cannot resolve such a contact and particles may pass through each other; %s",
                  lmp_->update->ntimestep, info[1], info[2], info[0], info[0] * dt, dt, epsilon_,
                  advice);
  else
    std::snprintf(msg, sizeof msg,
                  "Fix tri/particles: step " BIGINT_FORMAT ": particle %.0f moves at %g m/s "
                  "against its contact force, %g m per time step of %g s, more than epsilon "
                  "(%g m), and a particle-wall contact has intersecting surfaces: the soft layer "
                  "cannot resolve such a contact and particles may pass through walls; %s",
                  lmp_->update->ntimestep, info[1], info[0], info[0] * dt, dt, epsilon_, advice);
  lmp_->error->all(FLERR, msg);
}

} // namespace tri_liggghts
