#include "material_scales.h"

#include "model/timestep_rule.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tri_liggghts {
namespace {

std::string source_name(const ContactBoard::PublishedMaterial &m) {
  return m.kind == SourceKind::particle_pairs ? std::string("pair tri/gran")
                                              : "fix tri/wall " + *m.id;
}

// m_a m_b / (m_a + m_b); a wall (b < 0): m_a.
double pair_mass(double a, double b) { return b < 0.0 ? a : tri::effective_mass(a, b); }

// One published pair of types, with the masses that bound it.
struct Entry {
  const ContactBoard::PublishedMaterial *source;
  int itype, jtype;
  bool wall;
  double kn, meff_min, meff_max, v_char, layers_extra; // layers_extra: wall layer (< 0: eps)
};

// Whether a pair of types can touch now: two particles of the types exist (one for a wall);
// while there is no particle at all (particles inserted later), every pair can.
bool present(const TypeBodies &b, int i, int j, bool wall) {
  long total = 0;
  for (long c : b.count)
    total += c;
  if (total == 0)
    return true;
  if (wall)
    return b.count[i] > 0;
  return i == j ? b.count[i] > 1 : b.count[i] > 0 && b.count[j] > 0;
}

std::vector<Entry> entries(const std::vector<ContactBoard::PublishedMaterial> &mats,
                           const TypeBodies &b) {
  std::vector<Entry> out;
  const int ntypes = static_cast<int>(b.min_mass.size()) - 1;
  for (const ContactBoard::PublishedMaterial &m : mats) {
    const bool wall = m.kind == SourceKind::walls;
    for (const MaterialHint::Stiffness &s : m.hint->stiffness) {
      if (s.itype < 1 || s.itype > ntypes || (!wall && (s.jtype < 1 || s.jtype > ntypes)) ||
          !(s.kn > 0.0) || !present(b, s.itype, s.jtype, wall))
        continue;
      const double jmin = wall ? -1.0 : b.min_mass[s.jtype];
      const double jmax = wall ? -1.0 : b.max_mass[s.jtype];
      out.push_back({&m, s.itype, s.jtype, wall, s.kn, pair_mass(b.min_mass[s.itype], jmin),
                     pair_mass(b.max_mass[s.itype], jmax), m.hint->characteristic_velocity,
                     wall ? m.hint->wall_epsilon : -1.0});
    }
  }
  return out;
}

std::string describe(const Entry &e, double meff) {
  char text[300];
  std::snprintf(text, sizeof text, "%s, types %d and %d%s: pi sqrt(meff %g kg / kn %g N/m)",
                source_name(*e.source).c_str(), e.itype, e.jtype, e.wall ? " (wall)" : "", meff,
                e.kn);
  return text;
}

// The fastest approach per pair of types (the largest rate at which the centres of a pair of the
// particle-pair neighbour list close in, 0 if none approaches) and per type (the fastest
// particle, for walls, whose direction is not known here), over all ranks. Without a published
// list a pair of types takes the sum of its types' fastest particles.
struct Speeds {
  int ntypes = 0;
  bool listed = false;
  std::vector<double> pair, type;
  double of(int i, int j, bool wall) const {
    if (wall)
      return type[i];
    return listed ? pair[static_cast<std::size_t>(i) * (ntypes + 1) + j] : type[i] + type[j];
  }
};

Speeds approach_speeds(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board) {
  const LAMMPS_NS::Atom *atom = lmp->atom;
  Speeds s;
  s.ntypes = atom->ntypes;
  const std::size_t n = static_cast<std::size_t>(s.ntypes + 1);
  std::vector<double> local(n * n + n + 1, 0.0); // pair speeds, type speeds, "listed"
  double **x = atom->x, **v = atom->v;
  const int *type = atom->type;
  for (int i = 0; i < atom->nlocal; ++i) {
    const double speed = std::sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    local[n * n + type[i]] = std::max(local[n * n + type[i]], speed);
  }
  const LAMMPS_NS::NeighList *list = board.particle_pairs();
  if (list && list->ilist) {
    local[n * n + n] = 1.0;
    for (int ii = 0; ii < list->inum; ++ii) {
      const int i = list->ilist[ii];
      for (int jj = 0; jj < list->numneigh[i]; ++jj) {
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(r > 0.0))
          continue;
        const double u = -((v[j][0] - v[i][0]) * d[0] + (v[j][1] - v[i][1]) * d[1] +
                           (v[j][2] - v[i][2]) * d[2]) /
                         r;
        double &a = local[type[i] * n + type[j]], &b = local[type[j] * n + type[i]];
        a = b = std::max(a, u);
      }
    }
  }
  std::vector<double> global(local.size());
  MPI_Allreduce(local.data(), global.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_MAX,
                lmp->world);
  s.pair.assign(global.begin(), global.begin() + n * n);
  s.type.assign(global.begin() + n * n, global.begin() + n * n + n);
  s.listed = global[n * n + n] > 0.0;
  return s;
}

void print(LAMMPS_NS::LAMMPS *lmp, const std::string &line) {
  if (lmp->comm->me != 0)
    return;
  if (lmp->screen)
    std::fprintf(lmp->screen, "%s\n", line.c_str());
  if (lmp->logfile)
    std::fprintf(lmp->logfile, "%s\n", line.c_str());
}

} // namespace

TypeBodies type_bodies(LAMMPS_NS::LAMMPS *lmp, const std::vector<tri::Shape> &shapes,
                       double density, bool by_type) {
  const int ntypes = lmp->atom->ntypes;
  TypeBodies b;
  std::vector<long> local(ntypes + 1, 0);
  for (int i = 0; i < lmp->atom->nlocal; ++i)
    ++local[lmp->atom->type[i]];
  b.count.assign(ntypes + 1, 0);
  MPI_Allreduce(local.data(), b.count.data(), ntypes + 1, MPI_LONG, MPI_SUM, lmp->world);
  b.sphere.assign(ntypes + 1, {});
  b.min_mass.assign(ntypes + 1, 0.0);
  b.max_mass.assign(ntypes + 1, 0.0);
  std::vector<double> volumes;
  for (int t = 1; t <= ntypes; ++t) {
    volumes.clear();
    if (by_type) {
      if (t - 1 < static_cast<int>(shapes.size()))
        volumes.push_back(shapes[t - 1].volume);
    } else {
      for (const tri::Shape &s : shapes)
        volumes.push_back(s.volume);
    }
    if (volumes.empty())
      continue;
    b.sphere[t] =
        tri::equivalent_sphere_of_mean(volumes.data(), static_cast<int>(volumes.size()), density);
    b.min_mass[t] = density * *std::min_element(volumes.begin(), volumes.end());
    b.max_mass[t] = density * *std::max_element(volumes.begin(), volumes.end());
  }
  return b;
}

AutoEpsilon choose_auto_epsilon(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board,
                                const TypeBodies &bodies) {
  AutoEpsilon best;
  const std::vector<ContactBoard::PublishedMaterial> mats = board.materials();
  for (const ContactBoard::PublishedMaterial &m : mats)
    if (!(m.hint->characteristic_velocity > 0.0)) {
      const std::string msg = "Fix tri/particles: 'epsilon auto' needs a characteristic "
                              "velocity, and the material of " + source_name(m) +
                              " has none: define fix ID all property/global "
                              "characteristicVelocity scalar V (m/s), or give epsilon";
      lmp->error->all(FLERR, msg.c_str());
    }
  // A wall with a layer of its own needs only the rest of overlap / f from the particles; if
  // every wall's layer covers it and there is no particle pair, the symmetric rule applies.
  AutoEpsilon best_symmetric;
  for (const Entry &e : entries(mats, bodies)) {
    AutoEpsilon c;
    c.found = true;
    c.overlap = tri::peak_overlap(e.kn, e.meff_max, e.v_char);
    c.epsilon = tri::auto_epsilon(e.kn, e.meff_max, e.v_char);
    c.speed = e.v_char;
    c.kn = e.kn;
    c.meff = e.meff_max;
    c.itype = e.itype;
    c.jtype = e.jtype;
    c.wall = e.wall;
    c.source = source_name(*e.source);
    if (c.epsilon > best_symmetric.epsilon)
      best_symmetric = c;
    if (e.layers_extra >= 0.0) // eps + wall layer = overlap / f
      c.epsilon = c.overlap / tri::kAutoEpsilonFraction - e.layers_extra;
    best.found = true;
    if (c.epsilon > best.epsilon)
      best = c;
  }
  if (best.found && !(best.epsilon > 0.0))
    return best_symmetric;
  return best;
}

double longest_contact_time(const ContactBoard &board, const TypeBodies &bodies) {
  const std::vector<ContactBoard::PublishedMaterial> mats = board.materials();
  double longest = 0.0;
  for (const Entry &e : entries(mats, bodies))
    longest = std::max(longest, tri::linear_contact_time(e.kn, e.meff_max));
  return longest;
}

namespace {

// The two contacts the check judges: the shortest (its contact time against dt) and the one
// whose peak overlap at its approach speed takes the largest share of its soft layers.
struct JudgedContacts {
  const Entry *shortest = nullptr, *deepest = nullptr;
  double t_shortest = std::numeric_limits<double>::infinity();
  double v_approach = 0.0; // m/s, the fastest approach of any contact
  double deepest_overlap = 0.0, deepest_layers = 0.0, deepest_speed = 0.0;
};

JudgedContacts judged_contacts(const std::vector<Entry> &all, const Speeds &speeds,
                               double epsilon, double wall_layer) {
  JudgedContacts j;
  double deepest_fraction = -1.0;
  for (const Entry &e : all) {
    const double t = tri::linear_contact_time(e.kn, e.meff_min);
    if (t < j.t_shortest) {
      j.t_shortest = t;
      j.shortest = &e;
    }
    const double v_ref = std::max(speeds.of(e.itype, e.jtype, e.wall), e.v_char);
    j.v_approach = std::max(j.v_approach, v_ref);
    const double overlap = tri::peak_overlap(e.kn, e.meff_max, v_ref);
    const double other = e.layers_extra >= 0.0 ? e.layers_extra : e.wall ? wall_layer : epsilon;
    const double layers = epsilon + other;
    if (overlap / layers > deepest_fraction) {
      deepest_fraction = overlap / layers;
      j.deepest = &e;
      j.deepest_overlap = overlap;
      j.deepest_layers = layers;
      j.deepest_speed = v_ref;
    }
  }
  return j;
}

void report_timestep(LAMMPS_NS::LAMMPS *lmp, const JudgedContacts &j, const tri::TimestepFigures &f,
                     const tri::TimestepVerdict &verdict, bool adaptive,
                     const std::string &contact) {
  char steps[300];
  if (adaptive)
    std::snprintf(steps, sizeof steps, "dt of fix tri/adapt_dt from %g s (%.3g%%) to %g s (%.3g%%)",
                  f.dt_error, 100.0 * verdict.error_fraction, f.dt_warn,
                  100.0 * verdict.contact_fraction);
  else
    std::snprintf(steps, sizeof steps, "dt %g s = %.3g%%", f.dt_warn,
                  100.0 * verdict.contact_fraction);
  char approach[120];
  if (adaptive)
    std::snprintf(approach, sizeof approach, "approach %g m/s (bounded by fix tri/adapt_dt)",
                  j.v_approach);
  else
    std::snprintf(approach, sizeof approach, "approach %g m/s: %.3g epsilon per step",
                  j.v_approach, verdict.approach_fraction);
  char line[1200];
  std::snprintf(line, sizeof line,
                "tri/particles: time-step check: %s of the shortest contact time %g s (%s); "
                "%s; peak overlap at that speed %.3g%% of the soft layers (%s, types %d and %d)",
                steps, j.t_shortest, contact.c_str(), approach, 100.0 * verdict.overlap_fraction,
                source_name(*j.deepest->source).c_str(), j.deepest->itype, j.deepest->jtype);
  print(lmp, line);
}

void stop_if_unresolved(LAMMPS_NS::LAMMPS *lmp, const JudgedContacts &j,
                        const tri::TimestepFigures &f, const tri::TimestepVerdict &verdict,
                        bool adaptive, const std::string &contact, double dt_good) {
  if (!verdict.error)
    return;
  char line[1200];
  if (adaptive)
    std::snprintf(line, sizeof line,
                  "Fix tri/particles: the smallest time step of fix tri/adapt_dt, dtmin %g s, "
                  "cannot resolve a contact: it is %.3g%% of the shortest contact time %g s "
                  "(%s), above %g%% (fewer than %g steps per contact); lower dtmin to %g s or "
                  "less, or use a softer kn or heavier particles",
                  f.dt_error, 100.0 * verdict.error_fraction, j.t_shortest, contact.c_str(),
                  100.0 * tri::kErrorFraction, 1.0 / tri::kErrorFraction, dt_good);
  else
    std::snprintf(line, sizeof line,
                  "Fix tri/particles: time step %g s cannot resolve a contact: it is %.3g%% "
                  "of the shortest contact time %g s (%s), above %g%% (fewer than %g steps "
                  "per contact; velocity Verlet is unstable beyond 64%%); use timestep %g or "
                  "smaller, a softer kn or heavier particles",
                  f.dt_error, 100.0 * verdict.error_fraction, j.t_shortest, contact.c_str(),
                  100.0 * tri::kErrorFraction, 1.0 / tri::kErrorFraction, dt_good);
  lmp->error->all(FLERR, line);
}

void warn_of_timestep(LAMMPS_NS::LAMMPS *lmp, const JudgedContacts &j,
                      const tri::TimestepFigures &f, const tri::TimestepVerdict &verdict,
                      bool adaptive, const std::string &contact, double dt_good) {
  char line[1200];
  if (verdict.warn_contact) {
    if (adaptive)
      std::snprintf(line, sizeof line,
                    "Fix tri/particles: fix tri/adapt_dt may raise the time step to dtmax %g s, "
                    "%.3g%% of the shortest contact time %g s (%s): a contact is resolved only "
                    "while its rules keep dt small; dtmax %g s or less resolves every contact",
                    f.dt_warn, 100.0 * verdict.contact_fraction, j.t_shortest, contact.c_str(),
                    dt_good);
    else
      std::snprintf(line, sizeof line,
                    "Fix tri/particles: time step %g s is %.3g%% of the shortest contact time "
                    "%g s (%s): fewer than %g steps per contact; %g s or less resolves it",
                    f.dt_warn, 100.0 * verdict.contact_fraction, j.t_shortest, contact.c_str(),
                    1.0 / tri::kWarnFraction, dt_good);
    lmp->error->warning(FLERR, line);
  }
  if (verdict.warn_approach) {
    std::snprintf(line, sizeof line,
                  "Fix tri/particles: at the fastest approach, %g m/s, a contact closes in by "
                  "%.3g epsilon per time step of %g s (more than %g): the soft layer resolves it "
                  "poorly, and at 1 epsilon per step the run stops; use a smaller timestep or "
                  "fix tri/adapt_dt",
                  j.v_approach, verdict.approach_fraction, f.dt_warn, tri::kApproachFraction);
    lmp->error->warning(FLERR, line);
  }
  if (verdict.warn_overlap) {
    const Entry &d = *j.deepest;
    std::snprintf(line, sizeof line,
                  "Fix tri/particles: at %g m/s the peak overlap v sqrt(meff / kn) = %g m of "
                  "%s, types %d and %d (meff %g kg, kn %g N/m) exceeds the soft layers (%g m): "
                  "the real surfaces would meet; use a larger epsilon (or epsilon auto) or a "
                  "stiffer material",
                  j.deepest_speed, j.deepest_overlap, source_name(*d.source).c_str(), d.itype,
                  d.jtype, d.meff_max, d.kn, j.deepest_layers);
    lmp->error->warning(FLERR, line);
  }
}

} // namespace

void check_timestep(LAMMPS_NS::LAMMPS *lmp, const ContactBoard &board, const TypeBodies &bodies,
                    double epsilon, double wall_layer, bool report) {
  const std::vector<ContactBoard::PublishedMaterial> mats = board.materials();
  const std::vector<Entry> all = entries(mats, bodies);
  if (all.empty())
    return;
  const JudgedContacts j = judged_contacts(all, approach_speeds(lmp, board), epsilon, wall_layer);

  const bool adaptive = board.adaptive_dt();
  tri::TimestepFigures f;
  f.dt_error = adaptive ? board.dtmin() : lmp->update->dt;
  f.dt_warn = adaptive ? board.dtmax() : lmp->update->dt;
  f.contact_time = j.t_shortest;
  f.approach_speed = adaptive ? 0.0 : j.v_approach; // fix tri/adapt_dt bounds the approach itself
  f.epsilon = epsilon;
  f.peak_overlap = j.deepest_overlap;
  f.layers = j.deepest_layers;
  const tri::TimestepVerdict verdict = tri::judge_timestep(f);
  const std::string contact = describe(*j.shortest, j.shortest->meff_min);
  const double dt_good = tri::kWarnFraction * j.t_shortest;

  if (report)
    report_timestep(lmp, j, f, verdict, adaptive, contact);
  stop_if_unresolved(lmp, j, f, verdict, adaptive, contact, dt_good);
  if (lmp->comm->me == 0)
    warn_of_timestep(lmp, j, f, verdict, adaptive, contact, dt_good);
}

} // namespace tri_liggghts
