#include "shape_builder.h"

#include "body/random_rock.h"
#include "body/shape_error.h"
#include "mesh_reader.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace tri_liggghts {
namespace {

tri::Shape build_shape(const ShapeSpec &spec) {
  if (spec.from_file) {
    tri::TriangleMesh mesh = tri::read_mesh_file(spec.path);
    if (spec.scale != 1.0)
      mesh = tri::scaled(std::move(mesh), spec.scale);
    try {
      return tri::make_shape(spec.name, std::move(mesh));
    } catch (const tri::ShapeError &e) {
      throw tri::ShapeError(spec.path + ": " + e.what());
    }
  }
  tri::RockParameters rock;
  rock.ntri = spec.ntri;
  rock.size = spec.size;
  rock.seed = spec.seed;
  rock.aspect_middle = spec.aspect_middle;
  rock.aspect_short = spec.aspect_short;
  return tri::make_shape(spec.name, tri::random_rock(rock));
}

// A particle wider than the box in a periodic direction would touch its own image.
void check_fits_in_box(LAMMPS_NS::LAMMPS *lmp, const tri::Shape &s, double epsilon) {
  const LAMMPS_NS::Domain *domain = lmp->domain;
  const double diameter = 2.0 * tri::contact_reach(s, epsilon);
  const double box_min = std::min({domain->xprd, domain->yprd, domain->zprd});
  if (domain->box_exist && diameter >= box_min) {
    const std::string msg = "Fix tri/particles: shape " + s.name + " (bounding diameter " +
                            std::to_string(diameter) + " m with epsilon) does not fit in the "
                            "simulation box (smallest side " + std::to_string(box_min) + " m)";
    lmp->error->all(FLERR, msg.c_str());
  }
}

// Triangles finer than the soft layer: a point of one surface is within the layers of
// ~30 (eps / edge)^2 triangles of the other, so the triangle pairs of one contact, and the
// work to reduce them, grow with (eps / edge)^4 (measured: two 4 mm cubes face to face,
// 0.45 s per step at edge = 2 epsilon, 16 s at edge = epsilon).
void check_resolution(LAMMPS_NS::LAMMPS *lmp, const tri::Shape &s, double epsilon) {
  const double mean_edge = s.mean_edge_length;
  if (!(mean_edge < epsilon))
    return;
  const int ntri = s.soa.num_triangles();
  const double fits = ntri * (mean_edge / epsilon) * (mean_edge / epsilon);
  char msg[500];
  std::snprintf(msg, sizeof msg,
                "Fix tri/particles: shape %s (%d triangles) has a mean edge length of %g m, "
                "shorter than epsilon (%g m): one contact would hold thousands of "
                "triangle pairs and cost seconds per step; use a coarser mesh (about %.0f "
                "triangles or fewer) or a smaller epsilon",
                s.name.c_str(), ntri, mean_edge, epsilon, std::floor(fits));
  lmp->error->all(FLERR, msg);
}

} // namespace

std::vector<tri::Shape> build_shapes(LAMMPS_NS::LAMMPS *lmp, const ParticleOptions &options) {
  std::vector<tri::Shape> shapes;
  for (const ShapeSpec &spec : options.shapes) {
    try {
      shapes.push_back(build_shape(spec));
    } catch (const tri::ShapeError &e) { // already names the shape (and the file)
      const std::string msg = std::string("Fix tri/particles: ") + e.what();
      lmp->error->all(FLERR, msg.c_str());
    } catch (const std::exception &e) { // a mesh file error names the file
      const std::string msg = "Fix tri/particles: shape '" + spec.name + "': " + e.what();
      lmp->error->all(FLERR, msg.c_str());
    }
  }
  if (options.assign_by_type && static_cast<int>(shapes.size()) < lmp->atom->ntypes) {
    const std::string msg = "Fix tri/particles: 'assign type' needs one shape per atom type (" +
                            std::to_string(lmp->atom->ntypes) + " types, " +
                            std::to_string(shapes.size()) + " shapes)";
    lmp->error->all(FLERR, msg.c_str());
  }
  for (const tri::Shape &s : shapes) // with epsilon once it is known and the layers are set
    check_fits_in_box(lmp, s, 0.0);
  return shapes;
}

void check_shapes_against_epsilon(LAMMPS_NS::LAMMPS *lmp, const std::vector<tri::Shape> &shapes,
                                  double epsilon) {
  for (const tri::Shape &s : shapes)
    check_fits_in_box(lmp, s, epsilon);
  for (const tri::Shape &s : shapes)
    check_resolution(lmp, s, epsilon);
}

} // namespace tri_liggghts
