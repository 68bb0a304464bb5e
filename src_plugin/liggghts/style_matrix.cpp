// The compatibility matrix; see style_matrix.h. To classify a style, add one row in its
// section: kind, name, class, the note (works: a remark or ""; meaning: what it computes for a
// mesh particle; refused: why, "it ..."; irrelevant: which model it belongs to) and, for a
// refused style, what to use instead. tests/decks/test_style_matrix.py runs every row.
#include "style_matrix.h"

#include <cstring>

namespace tri_liggghts {
namespace {

using K = StyleKind;
using C = StyleClass;

// The replacement of every pair style.
const char *kTriGran = "pair_style tri/gran model hooke|hertz|hooke/stiffness (the same fix "
                       "property/global materials as pair gran)";

// Texts that several rows share.
const char *kCentreInside = "a particle is inside when its centre is";
const char *kNoSphereAtoms = "it has no radius, per-atom mass or angular velocity";
const char *kSphereAtoms = "atom_style sphere (or granular)";
const char *kFluidWhy =
    "it exchanges spheres of the contact reach with a fluid solver: drag, void fraction and "
    "heat of the wrong body";
const char *kNoFluid = "none: fluid coupling of triangulated particles is not available";
const char *kTriModels = "pair tri/gran and fix tri/wall take hooke, hertz and hooke/stiffness";
const char *kTriModel = "model hooke, hertz or hooke/stiffness";
const char *kRollingWhy =
    "rolling resistance is the meshes' own: contacts spread over faces and edges resist rolling";
const char *kShapeRolls = "none: the shape resists rolling";
const char *kNoCohesion = "cohesion between triangulated particles is not modelled";
const char *kClumps = "it integrates clumps of spheres";
const char *kTriWall = "fix tri/wall mesh MESH_ID with a fix mesh/surface";

const StyleRow kRows[] = {
    {K::atom_style, "atomic", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "charge", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "ellipsoid", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "full", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "hybrid", C::works, "with sphere among its sub-styles", ""},
    {K::atom_style, "line", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "molecular", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "sph", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "sph/var", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::atom_style, "sphere", C::works, "", ""},
    {K::atom_style, "granular", C::works, "", ""},
    {K::atom_style, "tri", C::refused, kNoSphereAtoms, kSphereAtoms},
    {K::run_style, "verlet", C::works, "", ""},
    {K::run_style, "respa", C::refused,
     "its levels skip the per-step preparation of fix tri/particles and fix tri/wall",
     "run_style verlet with fix tri/adapt_dt"},
    {K::pair_style, "gran", C::refused,
     "it computes contacts of spheres of the contact reach (the atoms' radius), not of the "
     "particles' triangles",
     kTriGran},
    {K::pair_style, "bubble", C::refused, "it computes contacts of spheres of the contact reach (the atoms' radius)",
     kTriGran},
    {K::pair_style, "gran_bubble", C::refused,
     "it computes contacts of spheres of the contact reach (the atoms' radius)", kTriGran},
    {K::pair_style, "hybrid", C::refused,
     "pair tri/gran must be the one pair style (its checks and statistics read it)",
     "pair_style tri/gran alone"},
    {K::pair_style, "hybrid/overlay", C::refused,
     "pair tri/gran must be the one pair style (its checks and statistics read it)",
     "pair_style tri/gran alone"},
    {K::pair_style, "line/lj", C::irrelevant, "2d line segments", ""},
    {K::pair_style, "soft", C::refused, "it pushes centres apart", kTriGran},
    {K::pair_style, "sph/artVisc/tensCorr", C::irrelevant, "SPH", ""},
    {K::gran_model, "hooke", C::works, "pair tri/gran and fix tri/wall take it", ""},
    {K::gran_model, "hertz", C::works, "pair tri/gran and fix tri/wall take it", ""},
    {K::gran_model, "hooke/stiffness", C::works, "pair tri/gran and fix tri/wall take it", ""},
    {K::gran_model, "edinburgh", C::refused, kTriModels, kTriModel},
    {K::gran_model, "edinburgh/stiffness", C::refused, kTriModels, kTriModel},
    {K::gran_model, "hertz/stiffness", C::refused, kTriModels, kTriModel},
    {K::gran_model, "hooke/hysteresis", C::refused, kTriModels, kTriModel},
    {K::gran_model, "luding", C::refused, kTriModels, kTriModel},
    {K::gran_model, "thornton_ning", C::refused, kTriModels, kTriModel},
    {K::gran_tangential, "history", C::works, "", ""},
    {K::gran_tangential, "no_history", C::works, "", ""},
    {K::gran_tangential, "tan_luding", C::refused,
     "pair tri/gran and fix tri/wall take history and no_history", "tangential history"},
    {K::gran_cohesion, "easo/capillary/viscous", C::refused, kNoCohesion, "none"},
    {K::gran_cohesion, "sjkr", C::refused, kNoCohesion, "none"},
    {K::gran_cohesion, "sjkr2", C::refused, kNoCohesion, "none"},
    {K::gran_cohesion, "washino/capillary/viscous", C::refused, kNoCohesion, "none"},
    {K::gran_rolling, "cdt", C::refused, kRollingWhy, kShapeRolls},
    {K::gran_rolling, "epsd", C::refused, kRollingWhy, kShapeRolls},
    {K::gran_rolling, "epsd2", C::refused, kRollingWhy, kShapeRolls},
    {K::gran_rolling, "epsd3", C::refused, kRollingWhy, kShapeRolls},
    {K::gran_rolling, "luding", C::refused, kRollingWhy, kShapeRolls},
    {K::gran_surface, "default", C::refused,
     "pair gran's surface models are for spheres; a triangulated particle's surface is its "
     "mesh",
     "none"},
    {K::gran_surface, "multicontact", C::refused,
     "the surface of a triangulated particle is its mesh", "none"},
    {K::gran_surface, "superquadric", C::refused,
     "the surface of a triangulated particle is its mesh", "none"},
    {K::fix, "adapt", C::refused,
     "it changes the atoms' radius or pair coefficients, while fix tri/particles sets "
     "radius := the shape's contact reach and rmass := density x volume",
     "none: size a shape with 'scale' (file) or 'size' (random rock) of fix tri/particles"},
    {K::fix, "addforce", C::works, "", ""},
    {K::fix, "ave/atom", C::works, "", ""},
    {K::fix, "ave/correlate", C::works, "", ""},
    {K::fix, "ave/euler", C::meaning,
     "bins particle centres; its volume fraction counts spheres of the contact reach (too "
     "high); velocities and stress as for spheres",
     ""},
    {K::fix, "ave/euler/stress", C::meaning,
     "as ave/euler; the stress from the contact points' virial (compute stress/atom)", ""},
    {K::fix, "ave/histo", C::works, "", ""},
    {K::fix, "ave/spatial", C::meaning,
     "bins particle centres: a particle counts whole in the bin of its centre, with its "
     "mesh's mass",
     ""},
    {K::fix, "ave/time", C::works, "", ""},
    {K::fix, "aveforce", C::works, "", ""},
    {K::fix, "box/relax", C::irrelevant, "molecular box relaxation under minimize (refused)", ""},
    {K::fix, "buoyancy", C::refused,
     "it lifts the submerged part of a sphere of the contact reach, not of the mesh",
     "none: buoyancy of triangulated particles is not modelled"},
    {K::fix, "couple/cfd", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/convection", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/radiation", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/convectiveImpl", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/speciesConvection", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/force", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/dragforce", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "couple/cfd/force/implicit", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "check/timestep/gran", C::refused,
     "it estimates the Rayleigh and Hertz times of spheres from pair gran's material",
     "the time-step check of fix tri/particles (check_timestep setup|N, on at every run by "
     "default) and fix tri/adapt_dt"},
    {K::fix, "check/timestep/sph", C::irrelevant, "SPH", ""},
    {K::fix, "contacthistory", C::irrelevant,
     "pair gran's own contact history (tri/gran keeps its own)", ""},
    {K::fix, "contacthistory/mesh", C::irrelevant,
     "fix wall/gran's own contact history (tri/wall keeps its own)", ""},
    {K::fix, "contactproperty/atom", C::irrelevant,
     "pair gran's per-contact store (not filled by tri/gran)", ""},
    {K::fix, "contactproperty/atom/wall", C::irrelevant,
     "wall/gran's per-contact store (not filled by tri/wall)", ""},
    {K::fix, "continuum/weighted", C::refused,
     "it takes the contact stress from pair gran's sphere contacts, which pair tri/gran "
     "does not store: it would give the kinetic part only",
     "compute stress/atom (the contact points' virial) with fix ave/spatial or "
     "ave/euler/stress"},
    {K::fix, "deform", C::works, "remaps centres; orientations kept", ""},
    {K::fix, "deform/check", C::works, "", ""},
    {K::fix, "diam/max", C::meaning, "the largest bounding radius of the insertion templates", ""},
    {K::fix, "drag", C::works, "pulls centres towards a point (not a fluid drag)", ""},
    {K::fix, "dt/reset", C::meaning,
     "bounds the centres' travel per step, not the meshes' rotation: fix tri/adapt_dt "
     "bounds both",
     ""},
    {K::fix, "efield", C::irrelevant, "charges (atom attribute q)", ""},
    {K::fix, "enforce2d", C::irrelevant, "2d simulations (LIGGGHTS stops a 3d deck)", ""},
    {K::fix, "external", C::irrelevant, "coupling through the library interface", ""},
    {K::fix, "fiber/spring/simple", C::refused,
     "it ties particles whose bounding spheres overlap with springs between their centres",
     "none: bonded triangulated particles are not modelled"},
    {K::fix, "freeze", C::works, "", ""},
    {K::fix, "gravity", C::works, "", ""},
    {K::fix, "heat/gran/conduction", C::refused,
     "it conducts heat through the sphere contacts of pair gran",
     "none: heat transfer between triangulated particles is not modelled"},
    {K::fix, "heat/gran", C::refused, "it conducts heat through the sphere contacts of pair gran",
     "none: heat transfer between triangulated particles is not modelled"},
    {K::fix, "insert/pack", C::meaning,
     "inserts from particletemplate/sphere; each particle gets its shape, reach and mass; "
     "the overlap check uses bounding spheres",
     ""},
    {K::fix, "insert/rate/region", C::meaning, "as insert/pack", ""},
    {K::fix, "insert/stream", C::meaning, "as insert/pack", ""},
    {K::fix, "couple/lb/onetoone", C::refused, kFluidWhy, kNoFluid},
    {K::fix, "lineforce", C::works, "", ""},
    {K::fix, "massflow/mesh", C::meaning,
     "counts a particle when its centre crosses the mesh, with its mesh's mass", ""},
    {K::fix, "massflow/mesh/sieve", C::refused,
     "its passage probability and sieve force come from the bounding sphere's diameter",
     "fix massflow/mesh on a mesh/surface with holes, as a wall of fix tri/wall"},
    {K::fix, "mesh/surface", C::works,
     "a wall for fix tri/wall; its stress module (mesh/surface/stress) gets the loads of "
     "tri/wall's contacts",
     ""},
    {K::fix, "mesh/surface/planar", C::works, "a wall for fix tri/wall", ""},
    {K::fix, "momentum", C::works, "", ""},
    {K::fix, "move", C::refused,
     "it prescribes the atoms' positions and velocities, not the orientation of "
     "triangulated particles",
     "fix tri/nve for free particles; for a driven body, a fix mesh/surface moved by fix "
     "move/mesh, with fix tri/wall"},
    {K::fix, "move/mesh", C::works, "moves a wall of fix tri/wall", ""},
    {K::fix, "move/mesh/gran", C::works, "", ""},
    {K::fix, "move/mesh/file", C::works, "", ""},
    {K::fix, "multicontact/halfspace", C::refused,
     "it needs pair gran's multicontact surface model of spheres", "none"},
    {K::fix, "multisphere", C::refused, kClumps,
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl) and fix"
     " tri/nve"},
    {K::fix, "multisphere/nointegration", C::refused, "it handles clumps of spheres",
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl)"},
    {K::fix, "concave", C::refused, kClumps,
     "one fix tri/particles shape of the body's surface (shape NAME file MESH.stl) and fix "
     "tri/nve"},
    {K::fix, "multisphere/break", C::refused, kClumps,
     "one fix tri/particles shape of the clump's surface (shape NAME file MESH.stl) and fix"
     " tri/nve"},
    {K::fix, "neighlist/mesh", C::works,
     "made by fix mesh/surface for its walls; one a deck defines itself frees memory LIGGGHTS "
     "3.8 goes on using, with spheres too",
     ""},
    {K::fix, "nve", C::refused, "it integrates translation only: the particles would never turn",
     "fix tri/nve"},
    {K::fix, "nve/asphere", C::refused, "it integrates ellipsoids", "fix tri/nve"},
    {K::fix, "nve/asphere/noforce", C::refused, "it integrates ellipsoids", "fix tri/nve"},
    {K::fix, "nve/limit", C::refused,
     "it integrates translation only, with a capped displacement: the particles would never"
     " turn",
     "fix tri/nve, and fix tri/adapt_dt to bound the time step"},
    {K::fix, "nve/line", C::refused, "it integrates line segments", "fix tri/nve"},
    {K::fix, "nve/noforce", C::refused, "it moves the atoms at their velocity, without rotation",
     "fix tri/nve"},
    {K::fix, "nve/sph", C::irrelevant, "SPH", ""},
    {K::fix, "nve/sph/stationary", C::irrelevant, "SPH", ""},
    {K::fix, "nve/sphere", C::refused,
     "it integrates spheres: it turns LIGGGHTS's omega with the inertia of a sphere, not "
     "the particles' orientation and angular momentum",
     "fix tri/nve (translation, and rotation with the full inertia tensor of each mesh)"},
    {K::fix, "particledistribution/discrete", C::works, "", ""},
    {K::fix, "particledistribution/discrete/numberbased", C::works, "", ""},
    {K::fix, "particledistribution/discrete/massbased", C::works, "", ""},
    {K::fix, "planeforce", C::works, "", ""},
    {K::fix, "print", C::works, "", ""},
    {K::fix, "property/atom", C::works, "", ""},
    {K::fix, "property/atom/timetracer", C::irrelevant,
     "renamed in LIGGGHTS 3.8 (its ERROR names property/atom/regiontracer/time)", ""},
    {K::fix, "property/atom/regiontracer/time", C::meaning,
     "residence time of particle centres in regions", ""},
    {K::fix, "property/atom/tracer", C::meaning, "marks particles whose centre enters the region",
     ""},
    {K::fix, "property/atom/tracer/stream", C::works, "", ""},
    {K::fix, "property/global", C::works, "", ""},
    {K::fix, "custom_property/global", C::works, "", ""},
    {K::fix, "property/atomtype", C::works, "", ""},
    {K::fix, "property/atomtypepair", C::works, "", ""},
    {K::fix, "region/variable", C::works, "", ""},
    {K::fix, "rigid", C::refused,
     "it integrates rigid bodies of atoms with point or sphere inertia, not the particles' "
     "own orientation",
     "fix tri/nve: every triangulated particle already is a rigid body with its mesh's full"
     " inertia (for a clump, make one closed mesh of it)"},
    {K::fix, "transportequation/scalar", C::works,
     "its fluxes come from heat/gran or CFD coupling, both unavailable here", ""},
    {K::fix, "setforce", C::works, "", ""},
    {K::fix, "sph/density/continuity", C::irrelevant, "SPH", ""},
    {K::fix, "sph/density/corr", C::irrelevant, "SPH", ""},
    {K::fix, "sph/density/summation", C::irrelevant, "SPH", ""},
    {K::fix, "sph/pressure", C::irrelevant, "SPH", ""},
    {K::fix, "spring", C::works, "", ""},
    {K::fix, "spring/rg", C::refused,
     "it needs per-type masses, which granular atoms do not have (LIGGGHTS 3.8 crashes)",
     "fix spring on the group's centre of mass"},
    {K::fix, "spring/self", C::works, "", ""},
    {K::fix, "store/force", C::works, "", ""},
    {K::fix, "store/state", C::works, "", ""},
    {K::fix, "particletemplate/multiplespheres", C::refused, "it is a template of sphere clumps",
     "fix particletemplate/sphere: its particles get the shape of fix tri/particles"},
    {K::fix, "particletemplate/multisphere", C::refused, "it is a template of sphere clumps",
     "fix particletemplate/sphere: its particles get the shape of fix tri/particles"},
    {K::fix, "particletemplate/sphere", C::meaning,
     "the template of inserted particles; its radius and density give way to the shape's "
     "reach and mass",
     ""},
    {K::fix, "viscous", C::works, "", ""},
    {K::fix, "wall/gran", C::refused,
     "it computes contacts of the walls with spheres of the bounding radius (radius = the "
     "mesh's bounding radius), not with the particles' triangles",
     "fix tri/wall mesh MESH_ID with a fix mesh/surface (a primitive plane or cylinder: "
     "mesh it as an STL file)"},
    {K::fix, "wall/region", C::refused,
     "it pushes on the particles' centres, as on point or sphere particles", kTriWall},
    {K::fix, "wall/region/sph", C::refused, "it computes wall forces on SPH particles", kTriWall},
    {K::fix, "wall/sph", C::refused, "it computes wall forces on SPH particles", kTriWall},
    {K::compute, "atom/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "bond/local", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "centro/atom", C::meaning, "centrosymmetry of the neighbours' centres", ""},
    {K::compute, "cluster/atom", C::meaning,
     "clusters of centres closer than the cutoff, not of touching surfaces", ""},
    {K::compute, "cna/atom", C::meaning, "common-neighbour analysis of the centres", ""},
    {K::compute, "com", C::works, "", ""},
    {K::compute, "com/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "contact/atom", C::refused,
     "it counts overlaps of bounding spheres, not contacts of the triangle surfaces",
     "compute tri/contact/atom (the bodies each particle touches)"},
    {K::compute, "contact/atom/gran", C::refused,
     "it counts overlaps of bounding spheres, not contacts of the triangle surfaces",
     "compute tri/contact/atom (the bodies each particle touches)"},
    {K::compute, "coord/atom", C::meaning,
     "neighbours counted by centre distance, not by contact (compute tri/contact/atom "
     "counts contacts)",
     ""},
    {K::compute, "displace/atom", C::works, "", ""},
    {K::compute, "erotate", C::refused,
     "it sums compute erotate/sphere, the energy of spheres of the bounding radius",
     "compute tri/erotate (0.5 L . omega with each particle's full inertia)"},
    {K::compute, "erotate/asphere", C::refused, "it sums the rotational energy of ellipsoids",
     "compute tri/erotate"},
    {K::compute, "erotate/multisphere", C::refused,
     "it sums the rotational energy of clumps of spheres", "compute tri/erotate"},
    {K::compute, "erotate/sphere", C::refused,
     "it sums 0.5 I omega^2 with the inertia of a sphere of the bounding radius",
     "compute tri/erotate (0.5 L . omega with each particle's full inertia)"},
    {K::compute, "erotate/sphere/atom", C::refused,
     "it gives 0.5 I omega^2 with the inertia of a sphere of the bounding radius",
     "compute tri/erotate for a group's total, or per atom the variable "
     "0.5*(f_ID[6]*omegax+f_ID[7]*omegay+f_ID[8]*omegaz) (f_ID[6..8]: the angular momentum "
     "that fix tri/particles keeps)"},
    {K::compute, "group/group", C::refused,
     "it asks the pair style for the force of one sphere pair (Pair::single), which mesh "
     "contacts do not have",
     "compute tri/contact/local with compute reduce"},
    {K::compute, "gyration", C::works, "", ""},
    {K::compute, "gyration/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "inertia/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "ke", C::works, "translation only, as for spheres (rotation: compute tri/erotate)",
     ""},
    {K::compute, "ke/atom", C::works, "translation only", ""},
    {K::compute, "ke/multisphere", C::irrelevant, "multisphere clumps", ""},
    {K::compute, "msd", C::works, "", ""},
    {K::compute, "msd/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "nparticles/tracer/region", C::meaning, "counts particles by their centres", ""},
    {K::compute, "pair/gran/local", C::refused, "it lists the sphere contacts of pair gran",
     "compute tri/contact/local pair (one row per contact point, for dump local)"},
    {K::compute, "wall/gran/local", C::refused, "it lists the sphere contacts of fix wall/gran",
     "compute tri/contact/local wall (one row per contact point, for dump local)"},
    {K::compute, "pe", C::works, "no pair energy, as with pair gran", ""},
    {K::compute, "pe/atom", C::works, "no pair energy, as with pair gran", ""},
    {K::compute, "pressure", C::works,
     "the virial of every contact point of pair tri/gran and fix tri/wall", ""},
    {K::compute, "property/atom", C::meaning,
     "radius and diameter are the contact reach; mass the mesh's; orientation and angular "
     "momentum are f_ID[1..8] of fix tri/particles",
     ""},
    {K::compute, "property/local", C::refused,
     "it asks the pair style for the force of one sphere pair (Pair::single), which mesh "
     "contacts do not have",
     "compute tri/contact/local (one row per contact point)"},
    {K::compute, "property/molecule", C::irrelevant, "molecules and bonds", ""},
    {K::compute, "rdf", C::meaning, "distribution of centre distances", ""},
    {K::compute, "reduce", C::works, "", ""},
    {K::compute, "reduce/sph", C::irrelevant, "SPH", ""},
    {K::compute, "reduce/region", C::meaning, "counts a particle by its centre", ""},
    {K::compute, "rigid", C::irrelevant, "multisphere clumps", ""},
    {K::compute, "multisphere", C::irrelevant, "multisphere clumps", ""},
    {K::compute, "multisphere/single", C::irrelevant, "multisphere clumps", ""},
    {K::compute, "slice", C::works, "", ""},
    {K::compute, "stress/atom", C::works,
     "each particle's virial at its contact points (stress x volume, as LIGGGHTS gives it)", ""},
    {K::compute, "temp", C::works, "translation only, 3 degrees of freedom a particle", ""},
    {K::region, "block", C::meaning, kCentreInside, ""},
    {K::region, "cone", C::meaning, kCentreInside, ""},
    {K::region, "cylinder", C::meaning, kCentreInside, ""},
    {K::region, "intersect", C::meaning, kCentreInside, ""},
    {K::region, "mesh/tet", C::meaning, kCentreInside, ""},
    {K::region, "plane", C::meaning, kCentreInside, ""},
    {K::region, "prism", C::meaning, kCentreInside, ""},
    {K::region, "sphere", C::meaning, kCentreInside, ""},
    {K::region, "union", C::meaning, kCentreInside, ""},
    {K::region, "wedge", C::meaning, kCentreInside, ""},
    {K::dump, "atom/vtk", C::meaning,
     "points at the centres, radius the contact reach: fix tri/vtk writes the surfaces", ""},
    {K::dump, "custom", C::meaning,
     "radius is the contact reach; orientation and angular momentum are f_ID[1..8] of fix "
     "tri/particles",
     ""},
    {K::dump, "custom/vtk", C::meaning,
     "points at the centres, radius the contact reach: fix tri/vtk writes the surfaces", ""},
    {K::dump, "custom/vtm", C::meaning,
     "points at the centres, radius the contact reach; the wall meshes as they are", ""},
    {K::dump, "decomposition/vtk", C::works, "", ""},
    {K::dump, "euler/vtk", C::meaning,
     "the cells of fix ave/euler (its volume fraction from spheres of the reach)", ""},
    {K::dump, "image", C::meaning, "draws spheres of the contact reach, not the meshes", ""},
    {K::dump, "local", C::works, "", ""},
    {K::dump, "local/gran/vtk", C::refused,
     "it writes the sphere contacts of compute pair/gran/local",
     "dump local of compute tri/contact/local"},
    {K::dump, "mesh/stl", C::works, "", ""},
    {K::dump, "stl", C::works, "", ""},
    {K::dump, "mesh/vtk", C::works,
     "the wall meshes; with mesh/surface/stress the loads of fix tri/wall", ""},
    {K::dump, "mesh/gran/VTK", C::works, "as mesh/vtk", ""},
    {K::dump, "mesh/vtm", C::works, "as mesh/vtk", ""},
    {K::dump, "movie", C::irrelevant,
     "a movie needs FFmpeg, which Debian's LIGGGHTS is built without (dump image draws "
     "spheres of the reach)",
     ""},
    {K::dump, "xyz", C::works, "", ""},
    {K::command, "change_box", C::works, "", ""},
    {K::command, "create_atoms", C::works,
     "a new atom becomes a particle of fix tri/particles at the next run (shape by its "
     "rule, reach, mass)",
     ""},
    {K::command, "create_box", C::works, "", ""},
    {K::command, "delete_atoms", C::meaning,
     "by centre; 'overlap' by centre distance, not by mesh overlap", ""},
    {K::command, "delete_bonds", C::irrelevant, "molecules and bonds", ""},
    {K::command, "displace_atoms", C::meaning,
     "moves centres; 'rotate' turns the centres about the axis, not the particles' "
     "orientation",
     ""},
    {K::command, "info", C::works, "", ""},
    {K::command, "minimize", C::refused,
     "it minimises an energy mesh contacts do not have, over centres only: it moves "
     "particles out of the box",
     "fix tri/nve with damping (fix viscous) to settle a packing"},
    {K::command, "neigh_modify", C::works, "", ""},
    {K::command, "read_data", C::works,
     "as create_atoms; diameter and density of the file give way to the shape's", ""},
    {K::command, "read_dump", C::meaning,
     "reads centres and velocities; orientation and angular momentum stay as they are", ""},
    {K::command, "read_restart", C::works,
     "continues with the shapes, orientations, angular momenta and contact histories (the "
     "deck repeats fix tri/particles)",
     ""},
    {K::command, "replicate", C::works, "copies keep shape, orientation and angular momentum", ""},
    {K::command, "rotate", C::irrelevant, "does nothing in LIGGGHTS 3.8", ""},
    {K::command, "run", C::works, "also with pre no and upto", ""},
    {K::command, "run_time", C::works, "", ""},
    {K::command, "set", C::meaning,
     "diameter, mass and density give way to the shape's reach and mass at the next run, "
     "with a WARNING; other keywords as for spheres",
     ""},
    {K::command, "velocity", C::works, "", ""},
    {K::command, "write_data", C::meaning,
     "writes spheres of the contact reach: no shape, orientation or angular momentum "
     "(write_restart keeps them)",
     ""},
    {K::command, "write_dump", C::works, "", ""},
    {K::command, "write_restart", C::works, "", ""},
};

} // namespace

StyleTable style_matrix() { return {kRows, sizeof kRows / sizeof kRows[0]}; }

const StyleRow *find_style(StyleKind kind, const char *style) {
  for (const StyleRow &row : style_matrix())
    if (row.kind == kind && std::strcmp(row.style, style) == 0)
      return &row;
  return nullptr;
}

const char *kind_name(StyleKind kind) {
  switch (kind) {
  case K::atom_style:
    return "atom_style";
  case K::run_style:
    return "run_style";
  case K::pair_style:
    return "pair_style";
  case K::gran_model:
    return "pair gran model";
  case K::gran_tangential:
    return "pair gran tangential";
  case K::gran_cohesion:
    return "pair gran cohesion";
  case K::gran_rolling:
    return "pair gran rolling_friction";
  case K::gran_surface:
    return "pair gran surface";
  case K::fix:
    return "fix";
  case K::compute:
    return "compute";
  case K::region:
    return "region";
  case K::dump:
    return "dump";
  case K::command:
    return "command";
  }
  return "?";
}

const char *class_name(StyleClass cls) {
  switch (cls) {
  case C::works:
    return "works";
  case C::meaning:
    return "meaning";
  case C::refused:
    return "refused";
  case C::irrelevant:
    return "irrelevant";
  }
  return "?";
}

} // namespace tri_liggghts
