// Insertion of triangulated particles by LIGGGHTS's own fix insert/stream, insert/pack and
// insert/rate/region from particletemplate/sphere templates and particledistribution/discrete.
//
// Every particletemplate/sphere template (fix_tri_template_sphere.h) gets one shape:
//   1. the one named by fix tri/particles's `template TEMPLATE_ID SHAPE_NAME`, else
//   2. with `assign type`, shape k for the template's atom_type k, else
//   3. the only shape, if there is one; otherwise an error names the template.
// It is bound when both exist: by fix tri/particles's constructor for templates defined before
// it, by the template's constructor for those defined after. The template then emits the
// shape's reach as its radius and the shape's mass, and its particles are handed to fix
// tri/particles with that shape.
//
// Order: particledistribution/discrete turns mass fractions into particle numbers with its
// templates' masses when it is defined, so fix tri/particles must be defined before it (the
// templates may come before or after fix tri/particles); an error says so otherwise.
#pragma once

namespace LAMMPS_NS {
class LAMMPS;
class FixTriParticles;
class FixTriTemplateSphere;
} // namespace LAMMPS_NS

namespace tri_liggghts {

// Binds one template; every problem ends in error->all naming the template.
void bind_template(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles,
                   LAMMPS_NS::FixTriTemplateSphere &templ);
// Binds every template defined so far and refuses a distribution defined before fix
// tri/particles. From fix tri/particles's constructor.
void bind_templates(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles);
// Before a run (fix tri/particles's init): every `template ID` names a particletemplate/sphere,
// and every distribution inserts from particletemplate/sphere templates only.
void check_insertion(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::FixTriParticles &particles);

} // namespace tri_liggghts
