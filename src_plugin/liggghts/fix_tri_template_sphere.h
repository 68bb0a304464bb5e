// particletemplate/sphere for liggghts-tri: LIGGGHTS's own FixTemplateSphere, registered
// under the same name in place of it, and identical to it until fix tri/particles gives it a
// shape (particle_insertion.h). From then on, for every particle the template generates:
//   radius := the shape's contact reach, the mesh's bounding radius (tri::contact_reach;
//             LIGGGHTS's insertion overlap check and `all_in` region test use this radius, so
//             a particle inserted without overlap does not overlap another's mesh);
//   mass   := the shape's mass (fix tri/particles density x mesh volume);
// and the template's mass and volume expectation, min/max radius and bounding radius, which
// particledistribution/discrete and fix insert/* compute with (mass fractions into particle
// numbers, `mass`/`massrate` into counts, `volumefraction_region`), are the shape's. The
// template's own radius and density are replaced; the first insertion says so, one line per
// template. Each particle it inserts is handed to fix tri/particles with its shape.
#pragma once

#include "fix_template_sphere.h"

#include <string>

namespace LAMMPS_NS {

class FixTriTemplateSphere : public FixTemplateSphere {
public:
  FixTriTemplateSphere(class LAMMPS *, int, char **);

  // What fix tri/particles gives the template (particle_insertion.cpp).
  struct Binding {
    int shape = -1;
    std::string shape_name;
    double reach = 0.0;  // the shape's contact reach (tri::contact_reach), m
    double mass = 0.0;   // kg
    double volume = 0.0; // m^3
  };
  void bind(const Binding &b) { binding_ = b; }
  bool bound() const { return binding_.shape >= 0; }
  const Binding &binding() const { return binding_; }
  int inserted_type() const { return atom_type; }
  // The template's own values, as its keywords set them.
  double sphere_radius() { return FixTemplateSphere::max_rad(); }
  double sphere_mass() { return FixTemplateSphere::massexpect(); }

  // Called by the particles this template generates, right after atom m was inserted.
  void inserted(int m);

  void randomize_single() override;
  void init_ptilist(int n_random_max, const bool enforce_single = false,
                    FixPropertyAtom *const fix_release = nullptr) override;
  void randomize_ptilist(int n_random, int distribution_groupbit, int distorder) override;
  void direct_set_ptlist(const int i, const void *const data, const int distribution_groupbit,
                         const int distorder) override;
  double volexpect() override;
  double massexpect() override;
  double min_rad() override;
  double max_rad() override;
  double max_r_bound() override;

private:
  Binding binding_;
  bool announced_ = false;
  void apply(class ParticleToInsert *p);
  void announce();
};

} // namespace LAMMPS_NS
