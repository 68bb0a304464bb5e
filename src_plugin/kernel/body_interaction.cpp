#include "body_interaction.h"

#include "point_triangle.h"

#include <algorithm>
#include <limits>

namespace tri {

namespace {

// Where no normal is defined (coincident triangles), push along the line of centres, or for a
// wall along the direction from the particle's centre to the wall's closest point.
// O(patch triangles), small beside the triangle pairs of the same interaction.
Eigen::Vector3d reference_direction(const Body &a, const Body &b) {
  Eigen::Vector3d towards = b.state.x - a.state.x;
  if (b.is_wall()) {
    double best = std::numeric_limits<double>::infinity();
    const TriangleSoA &t = *b.triangles;
    for (int k = 0; k < t.num_triangles(); ++k) {
      const Eigen::Vector3d q = closest_point_on_triangle(a.state.x, t.vertex(k, 0),
                                                          t.vertex(k, 1), t.vertex(k, 2));
      const double d2 = (q - a.state.x).squaredNorm();
      if (d2 < best) {
        best = d2;
        towards = q - a.state.x;
      }
    }
  }
  const double length = towards.norm();
  return length > 0.0 ? Eigen::Vector3d(towards / length) : Eigen::Vector3d::UnitZ();
}

} // namespace

std::size_t InteractionScratch::bytes() const {
  const ReductionWorkspace &r = reduction;
  std::size_t ints = r.parent.capacity() + r.order.capacity() + r.label.capacity() +
                     r.cls.capacity() + r.absorbed.capacity() + r.seeds.capacity() +
                     r.alive.capacity() + r.group.capacity();
  return distance.bytes() + triangle_contacts.capacity() * sizeof(TriangleContact) +
         points.capacity() * sizeof(ContactPoint) +
         r.raw.capacity() * sizeof(ReductionWorkspace::Raw) +
         r.polygons.capacity() * sizeof(ContactPolygon) +
         (r.points.capacity() + nodes.capacity() + node_velocities.capacity()) *
             sizeof(Eigen::Vector3d) +
         ints * sizeof(int);
}

PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats) {
  scratch.triangle_contacts.clear();
  find_triangle_contacts(*a.triangles, a.epsilon, *b.triangles, b.epsilon, s.distance,
                         scratch.triangle_contacts, stats, scratch.distance);

  ReductionParams params;
  params.method = s.reduction;
  params.link_length =
      recommended_link_length(a.longest_edge, b.longest_edge, a.epsilon, b.epsilon);
  params.min_width = std::min(a.min_edge, b.min_edge);
  params.reference_direction = reference_direction(a, b);
  reduce_contacts(scratch.triangle_contacts.data(),
                  static_cast<int>(scratch.triangle_contacts.size()), *a.triangles, a.epsilon,
                  *b.triangles, b.epsilon, params, scratch.reduction, scratch.points);
  return pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt, history);
}

} // namespace tri
