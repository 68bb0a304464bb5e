#include "particle_insertion.h"

#include "fix_tri_particles.h"
#include "fix_tri_template_sphere.h"

#include "error.h"
#include "fix_particledistribution_discrete.h"
#include "lammps.h"
#include "modify.h"

#include <cstdlib>
#include <cstring>
#include <string>

namespace tri_liggghts {
namespace {

[[noreturn]] void fail(LAMMPS_NS::LAMMPS *lmp, const std::string &message) {
  const std::string text = "Fix tri/particles: " + message;
  lmp->error->all(FLERR, text.c_str());
  std::abort(); // error->all does not return
}

bool is_distribution(const LAMMPS_NS::Fix *fix) {
  return std::strncmp(fix->style, "particledistribution/discrete", 29) == 0;
}

int shape_of_template(LAMMPS_NS::LAMMPS *lmp, const LAMMPS_NS::FixTriParticles &particles,
                      const std::string &id, int type) {
  for (const auto &[name, shape] : particles.template_shapes())
    if (name == id)
      return shape;
  const int n = particles.num_shapes();
  if (particles.assigns_by_type()) {
    if (type >= 1 && type <= n)
      return type - 1;
    fail(lmp, "fix particletemplate/sphere " + id + " inserts atom type " + std::to_string(type) +
                  ", but 'assign type' has " + std::to_string(n) +
                  " shape(s) (shape k for atom type k); give it one with 'template " + id +
                  " SHAPE'");
  }
  if (n == 1)
    return 0;
  fail(lmp, "fix particletemplate/sphere " + id + " has no shape: with 'assign random' and " +
                std::to_string(n) + " shapes, give it one with 'template " + id +
                " SHAPE' (or use 'assign type': atom type k then picks shape k)");
}

} // namespace

void bind_template(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles,
                   LAMMPS_NS::FixTriTemplateSphere &templ) {
  const int s = shape_of_template(lmp, particles, templ.id, templ.inserted_type());
  const tri::Shape &shape = particles.shape(s);
  LAMMPS_NS::FixTriTemplateSphere::Binding b;
  b.shape = s;
  b.shape_name = shape.name;
  b.reach = particles.reach(s);
  b.volume = shape.volume;
  b.mass = particles.density() * shape.volume;
  templ.bind(b);
}

void bind_templates(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles) {
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int k = 0; k < modify->nfix; ++k)
    if (auto *t = dynamic_cast<LAMMPS_NS::FixTriTemplateSphere *>(modify->fix[k]))
      bind_template(lmp, particles, *t);
  for (int k = 0; k < modify->nfix; ++k)
    if (is_distribution(modify->fix[k]) && modify->fix[k] != &particles)
      fail(lmp, std::string("fix ") + modify->fix[k]->style + " " + modify->fix[k]->id +
                    " is defined before fix tri/particles: it has already turned its mass "
                    "fractions into particle numbers with the sphere masses of its templates; "
                    "define fix tri/particles before it (the particletemplate/sphere fixes may "
                    "come before or after fix tri/particles)");
}

void check_insertion(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles) {
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (const auto &entry : particles.template_shapes()) {
    const std::string &id = entry.first;
    const int k = modify->find_fix(id.c_str());
    if (k < 0)
      fail(lmp, "'template " + id + "': no fix has ID '" + id +
                    "' (expected a fix particletemplate/sphere)");
    if (!dynamic_cast<LAMMPS_NS::FixTriTemplateSphere *>(modify->fix[k]))
      fail(lmp, "'template " + id + "': fix " + id + " is a " + modify->fix[k]->style +
                    "; only particletemplate/sphere templates can be given a shape");
  }
  for (int k = 0; k < modify->nfix; ++k) {
    if (!is_distribution(modify->fix[k]))
      continue;
    auto *d = static_cast<LAMMPS_NS::FixParticledistributionDiscrete *>(modify->fix[k]);
    for (int t = 0; t < d->n_particletemplates(); ++t) {
      LAMMPS_NS::FixTemplateSphere *templ = d->get_template(t);
      auto *tri_templ = dynamic_cast<LAMMPS_NS::FixTriTemplateSphere *>(templ);
      if (!tri_templ || !tri_templ->bound())
        fail(lmp, std::string("fix ") + d->style + " " + d->id + " uses fix " + templ->id + " (" +
                      templ->style +
                      "): triangulated particles are inserted from "
                      "particletemplate/sphere templates only");
    }
  }
}

} // namespace tri_liggghts
