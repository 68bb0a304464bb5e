#include "fix_tri_template_sphere.h"

#include "fix_tri_particles.h"
#include "particle_insertion.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "particleToInsert.h"

#include <cstdio>

using namespace LAMMPS_NS;

namespace {

// LIGGGHTS's particle of one sphere, which also tells its template what it inserted.
class TriParticleToInsert : public ParticleToInsert {
public:
  TriParticleToInsert(LAMMPS *lmp, FixPropertyAtom *fix_release, FixTriTemplateSphere *owner)
      : ParticleToInsert(lmp, 1, fix_release), owner_(owner) {}
  int insert() override {
    const int first = atom->nlocal;
    const int n = ParticleToInsert::insert();
    for (int m = first; m < atom->nlocal; ++m)
      owner_->inserted(m);
    return n;
  }

private:
  FixTriTemplateSphere *owner_;
};

} // namespace

FixTriTemplateSphere::FixTriTemplateSphere(LAMMPS *lmp, int narg, char **arg)
    : FixTemplateSphere(lmp, narg, arg) {
  delete pti; // the base made a plain one
  pti = new TriParticleToInsert(lmp, nullptr, this);
  // A fix tri/particles defined before this template gives it its shape now.
  if (auto *particles = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0)))
    tri_liggghts::bind_template(lmp, *particles, *this);
}

void FixTriTemplateSphere::inserted(int m) {
  if (!bound())
    return;
  if (auto *particles = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0)))
    particles->set_inserted_shape(m, binding_.shape);
}

// The base draws radius and density (same random numbers as without a shape), then the
// shape's values replace them.
void FixTriTemplateSphere::apply(ParticleToInsert *p) {
  if (!bound())
    return;
  p->radius_ins[0] = p->r_bound_ins = binding_.reach;
  p->volume_ins = binding_.volume;
  p->mass_ins = binding_.mass;
  p->density_ins = binding_.mass / binding_.volume;
}

void FixTriTemplateSphere::announce() {
  if (announced_ || !bound())
    return;
  announced_ = true;
  if (comm->me != 0)
    return;
  char line[600];
  std::snprintf(line, sizeof line,
                "tri/particles: template %s (radius %g m, mass %g kg) -> shape %s (reach "
                "%g m, mass %g kg): its particles get the shape's radius and mass\n",
                id, sphere_radius(), sphere_mass(), binding_.shape_name.c_str(), binding_.reach,
                binding_.mass);
  if (screen)
    std::fputs(line, screen);
  if (logfile)
    std::fputs(line, logfile);
}

void FixTriTemplateSphere::randomize_single() {
  announce();
  FixTemplateSphere::randomize_single();
  apply(pti);
}

// As the base, with particles that report their insertion.
void FixTriTemplateSphere::init_ptilist(int n_random_max, const bool,
                                        FixPropertyAtom *const fix_release) {
  if (pti_list)
    error->one(FLERR, "invalid FixTemplateSphere::init_list()");
  n_pti_max = n_random_max;
  pti_list = static_cast<ParticleToInsert **>(
      memory->smalloc(n_pti_max * sizeof(ParticleToInsert *), "pti_list"));
  for (int i = 0; i < n_pti_max; ++i)
    pti_list[i] = new TriParticleToInsert(lmp, fix_release, this);
}

void FixTriTemplateSphere::randomize_ptilist(int n_random, int distribution_groupbit,
                                             int distorder) {
  announce();
  FixTemplateSphere::randomize_ptilist(n_random, distribution_groupbit, distorder);
  for (int i = 0; i < n_random; ++i)
    apply(pti_list[i]);
}

void FixTriTemplateSphere::direct_set_ptlist(const int i, const void *const data,
                                             const int distribution_groupbit, const int distorder) {
  announce();
  FixTemplateSphere::direct_set_ptlist(i, data, distribution_groupbit, distorder);
  apply(pti_list[i]);
}

double FixTriTemplateSphere::volexpect() {
  if (!bound())
    return FixTemplateSphere::volexpect();
  if (binding_.volume < vol_limit) // the base's check, on the shape's volume
    error->fix_error(FLERR, this,
                     "Volume expectancy too small. Change 'volume_limit' "
                     "if you are sure you know what you're doing");
  return binding_.volume;
}

double FixTriTemplateSphere::massexpect() {
  return bound() ? binding_.mass : FixTemplateSphere::massexpect();
}

double FixTriTemplateSphere::min_rad() {
  return bound() ? binding_.reach : FixTemplateSphere::min_rad();
}

double FixTriTemplateSphere::max_rad() {
  return bound() ? binding_.reach : FixTemplateSphere::max_rad();
}

double FixTriTemplateSphere::max_r_bound() {
  return bound() ? binding_.reach : FixTemplateSphere::max_r_bound();
}
