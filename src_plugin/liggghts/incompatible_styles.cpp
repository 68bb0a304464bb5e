// The styles refused next to fix tri/particles; see incompatible_styles.h. To refuse another
// style, add one row to the matching table: its name, why it cannot work, what to use instead.
#include "incompatible_styles.h"

#include "compute.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "pair.h"
#include "pair_hybrid.h"

#include <cstring>

namespace tri_liggghts {
namespace {

struct Row {
  const char *style;
  const char *why;     // "it ..."
  const char *instead; // what to use; "" where the message builds it
};

// Why the integrators cannot work, once: orientation and angular momentum of a triangulated
// particle are fix tri/particles' per-atom state, which only fix tri/nve advances.
const char *kTwice = " (and next to fix tri/nve the particles would move twice)";

const Row fix_table[] = {
    {"nve/sphere",
     "it integrates spheres: it turns LIGGGHTS's omega with the inertia of a sphere, not the "
     "particles' orientation and angular momentum",
     "fix tri/nve (translation, and rotation with the full inertia tensor of each mesh)"},
    {"nve", "it integrates translation only: the particles would never turn", "fix tri/nve"},
    {"nve/limit",
     "it integrates translation only, with a capped displacement: the particles "
     "would never turn",
     "fix tri/nve, and fix tri/adapt_dt to bound the time step"},
    {"nve/noforce", "it moves the atoms at their velocity, without rotation", "fix tri/nve"},
    {"nve/asphere", "it integrates ellipsoids", "fix tri/nve"},
    {"nve/asphere/noforce", "it integrates ellipsoids", "fix tri/nve"},
    {"nve/line", "it integrates line segments", "fix tri/nve"},
    {"nve/superquadric", "it integrates superquadrics", "fix tri/nve"},
    {"nve/sph", "it integrates SPH particles", "fix tri/nve"},
    {"nve/sph/stationary", "it integrates SPH particles", "fix tri/nve"},
    {"rigid",
     "it integrates rigid bodies of atoms with point or sphere inertia, not the "
     "particles' own orientation",
     "fix tri/nve: every triangulated particle already is a rigid body with its mesh's full "
     "inertia (for a clump, make one closed mesh of it)"},
    {"multisphere", "it integrates clumps of spheres",
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl) and fix "
     "tri/nve"},
    {"multisphere/nointegration", "it handles clumps of spheres",
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl)"},
    {"multisphere/break", "it integrates clumps of spheres",
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl) and fix "
     "tri/nve"},
    {"concave", "it integrates clumps of spheres",
     "one fix tri/particles shape of the body's surface (shape NAME file MESH.stl) and fix "
     "tri/nve"},
    {"move",
     "it prescribes the atoms' positions and velocities, not the orientation of "
     "triangulated particles",
     "fix tri/nve for free particles; for a driven body, a fix mesh/surface moved by fix "
     "move/mesh, with fix tri/wall"},
    {"wall/gran",
     "it computes contacts of the walls with spheres of the bounding radius "
     "(radius = the mesh's bounding radius), not with the particles' triangles",
     "fix tri/wall mesh MESH_ID with a fix mesh/surface (a primitive plane or cylinder: mesh it "
     "as an STL file)"},
    {"wall/region", "it pushes on the particles' centres, as on point or sphere particles",
     "fix tri/wall mesh MESH_ID with a fix mesh/surface"},
    {"wall/sph", "it computes wall forces on SPH particles",
     "fix tri/wall mesh MESH_ID with a fix mesh/surface"},
    {"wall/region/sph", "it computes wall forces on SPH particles",
     "fix tri/wall mesh MESH_ID with a fix mesh/surface"},
    {"heat/gran", "it conducts heat through the sphere contacts of pair gran",
     "none: heat transfer between triangulated particles is not modelled"},
    {"heat/gran/conduction", "it conducts heat through the sphere contacts of pair gran",
     "none: heat transfer between triangulated particles is not modelled"},
    {"check/timestep/gran",
     "it estimates the Rayleigh and Hertz times of spheres from pair "
     "gran's material",
     "the time-step check of fix tri/particles (check_timestep setup|N, on at every run by "
     "default) and fix tri/adapt_dt"},
    {"adapt",
     "it changes the atoms' radius or pair coefficients, while fix tri/particles sets "
     "radius := the shape's contact reach and rmass := density x volume",
     "none: size a shape with 'scale' (file) or 'size' (random rock) of fix tri/particles"},
};

const Row compute_table[] = {
    {"erotate/sphere",
     "it sums 0.5 I omega^2 with the inertia of a sphere of the bounding "
     "radius",
     "compute tri/erotate (0.5 L . omega with each particle's full inertia)"},
    {"erotate", "it sums compute erotate/sphere, the energy of spheres of the bounding radius",
     "compute tri/erotate (0.5 L . omega with each particle's full inertia)"},
    {"erotate/sphere/atom",
     "it gives 0.5 I omega^2 with the inertia of a sphere of the "
     "bounding radius",
     ""}, // the per-atom variable, built in the message
    {"erotate/asphere", "it sums the rotational energy of ellipsoids", "compute tri/erotate"},
    {"erotate/superquadric", "it sums the rotational energy of superquadrics",
     "compute tri/erotate"},
    {"erotate/multisphere", "it sums the rotational energy of clumps of spheres",
     "compute tri/erotate"},
    {"contact/atom",
     "it counts overlaps of bounding spheres, not contacts of the triangle "
     "surfaces",
     "compute tri/contact/atom (the bodies each particle touches)"},
    {"contact/atom/gran",
     "it counts overlaps of bounding spheres, not contacts of the triangle "
     "surfaces",
     "compute tri/contact/atom (the bodies each particle touches)"},
    {"pair/gran/local", "it lists the sphere contacts of pair gran",
     "compute tri/contact/local pair (one row per contact point, for dump local)"},
    {"wall/gran/local", "it lists the sphere contacts of fix wall/gran",
     "compute tri/contact/local wall (one row per contact point, for dump local)"},
};

const char *kPairReplacement =
    "pair_style tri/gran model hooke|hertz|hooke/stiffness (the same fix property/global "
    "materials as pair gran)";

const Row pair_table[] = {
    {"gran",
     "it computes contacts of spheres of the bounding radius (radius = bounding radius "
     "+ epsilon), not of the particles' triangles",
     kPairReplacement},
    {"bubble", "it computes contacts of spheres of the bounding radius", kPairReplacement},
    {"gran_bubble", "it computes contacts of spheres of the bounding radius", kPairReplacement},
};

const Row *find(const Row *table, std::size_t n, const char *style) {
  for (std::size_t k = 0; k < n; ++k)
    if (std::strcmp(table[k].style, style) == 0)
      return &table[k];
  return nullptr;
}

template <std::size_t N> const Row *find(const Row (&table)[N], const char *style) {
  return find(table, N, style);
}

std::string message(const std::string &what, const std::string &why, const std::string &use) {
  return "Fix tri/particles: " + what + " cannot work with triangulated particles: " + why +
         "; instead use " + use;
}

std::string fix_message(LAMMPS_NS::Fix *fix) {
  const std::string what = std::string("fix ") + fix->style + " (ID " + fix->id + ")";
  if (const Row *row = find(fix_table, fix->style)) {
    std::string why = row->why;
    if (fix->time_integrate)
      why += kTwice;
    return message(what, why, row->instead);
  }
  if (fix->time_integrate && std::strcmp(fix->style, "tri/nve") != 0)
    return message(what,
                   "it integrates the atoms' motion, which for triangulated particles fix "
                   "tri/nve alone does (it also turns their orientation)",
                   "fix tri/nve");
  return "";
}

std::string compute_message(LAMMPS_NS::Compute *compute, const std::string &particles_id) {
  const Row *row = find(compute_table, compute->style);
  if (!row)
    return "";
  const std::string what = std::string("compute ") + compute->style + " (ID " + compute->id + ")";
  std::string use = row->instead;
  if (use.empty()) {
    const std::string f = "f_" + particles_id;
    use = "compute tri/erotate for a group's total, or per atom the variable 0.5*(" + f +
          "[6]*omegax+" + f + "[7]*omegay+" + f + "[8]*omegaz) (" + f +
          "[6..8]: the angular momentum)";
  }
  return message(what, row->why, use);
}

std::string pair_message(LAMMPS_NS::LAMMPS *lmp) {
  LAMMPS_NS::Force *force = lmp->force;
  if (!force->pair || !force->pair_style)
    return "";
  const std::string style = force->pair_style;
  if (style == "tri/gran")
    return "";
  const std::string what = "pair_style " + style;
  if (auto *hybrid = dynamic_cast<LAMMPS_NS::PairHybrid *>(force->pair)) {
    std::string subs;
    for (int k = 0; k < hybrid->nstyles; ++k)
      subs += std::string(k ? ", " : "") + hybrid->keywords[k];
    return message(what + " (sub-styles " + subs + ")",
                   "the contacts of triangulated particles, their checks and statistics come "
                   "from pair tri/gran as the one pair style",
                   "pair_style tri/gran alone");
  }
  if (const Row *row = find(pair_table, style.c_str()))
    return message(what, row->why, row->instead);
  return message(what, "it does not compute contacts of triangulated particles", kPairReplacement);
}

} // namespace

std::string incompatible_style_message(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id) {
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int k = 0; k < modify->nfix; ++k) {
    const std::string m = fix_message(modify->fix[k]);
    if (!m.empty())
      return m;
  }
  for (int k = 0; k < modify->ncompute; ++k) {
    const std::string m = compute_message(modify->compute[k], particles_id);
    if (!m.empty())
      return m;
  }
  return pair_message(lmp);
}

void refuse_incompatible_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id) {
  const std::string m = incompatible_style_message(lmp, particles_id);
  if (!m.empty())
    lmp->error->all(FLERR, m.c_str());
}

} // namespace tri_liggghts
