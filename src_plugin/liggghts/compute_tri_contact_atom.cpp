#include "compute_tri_contact_atom.h"

#include "fix_tri_particles.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <string>

using namespace LAMMPS_NS;

ComputeTriContactAtom::ComputeTriContactAtom(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg) {
  bool pair = false, wall = false;
  for (; iarg < narg; ++iarg) {
    const std::string key = arg[iarg];
    if (key == "pair")
      pair = true;
    else if (key == "wall")
      wall = true;
    else {
      const std::string msg = "Compute tri/contact/atom: unknown keyword '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  source_ = pair == wall ? tri_liggghts::TallySource::all
            : pair       ? tri_liggghts::TallySource::pair
                         : tri_liggghts::TallySource::wall;
  peratom_flag = 1;
  size_peratom_cols = 0;
  vector_atom = nullptr; // count_, once grown
}

ComputeTriContactAtom::~ComputeTriContactAtom() { memory->destroy(count_); }

void ComputeTriContactAtom::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Compute tri/contact/atom requires fix tri/particles");
  particles_->board().want_contacts();
}

void ComputeTriContactAtom::compute_peratom() {
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax_) {
    nmax_ = atom->nmax;
    memory->destroy(count_);
    memory->create(count_, nmax_, "tri/contact/atom:count");
    vector_atom = count_;
  }
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i)
    count_[i] = 0.0;
  // Each body pair once (its first row), for each of its atoms this rank owns: a pair across
  // ranks counts on both, each for its own atom.
  for (const tri_liggghts::PublishedContact *c : particles_->published().contacts(source_)) {
    if (!c->first_of_pair)
      continue;
    if (c->atom_a < nlocal)
      count_[c->atom_a] += 1.0;
    if (c->atom_b >= 0 && c->atom_b < nlocal)
      count_[c->atom_b] += 1.0;
  }
  const int *mask = atom->mask;
  for (int i = 0; i < nlocal; ++i)
    if (!(mask[i] & groupbit))
      count_[i] = 0.0;
}

double ComputeTriContactAtom::memory_usage() { return static_cast<double>(nmax_) * sizeof(double); }
