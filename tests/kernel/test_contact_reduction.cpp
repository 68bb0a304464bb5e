// Tests of contact_reduction.h: the summed force of a flat face on a plane must not depend on
// the mesh, separate regions must stay separate, the output must not depend on input order,
// and intersecting triangles must give finite normals. Triangle-pair contacts are built by a
// small brute force written here (point-triangle and segment-segment closest points), so the
// test does not depend on the distance kernel under test elsewhere.
#include "contact/contact_reduction.h"
#include "distance/particle_contacts.h"
#include "geometry/point_triangle.h"
#include "model/contact_force.h"
#include "test_meshes.h"
#include "triangle_contact_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using tri::ContactPoint;
using tri::TriangleContact;

struct Tri {
  Vector3d v[3];
};
using Mesh = std::vector<Tri>;

tri::TriangleSoA soa_of(const Mesh &m) {
  tri::TriangleSoA s;
  s.resize(static_cast<int>(m.size()));
  for (int t = 0; t < static_cast<int>(m.size()); ++t)
    for (int k = 0; k < 3; ++k)
      s.set_vertex(t, k, m[t].v[k]);
  return s;
}

// ---- brute-force triangle distance (separated triangles only; enough for these scenes) ----

// Closest point on triangle abc to p: the kernel's (point_triangle.h, tested on its own).
Vector3d closest_on_triangle(const Vector3d &p, const Vector3d &a, const Vector3d &b,
                             const Vector3d &c) {
  return tri::closest_point_on_triangle(p, a, b, c);
}

// Closest points of segments p1q1 and p2q2 (Ericson 5.1.9).
void closest_segments(const Vector3d &p1, const Vector3d &q1, const Vector3d &p2,
                      const Vector3d &q2, Vector3d &c1, Vector3d &c2) {
  const Vector3d d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s, t;
  const double c = d1.dot(r), b = d1.dot(d2), denom = a * e - b * b;
  s = denom > 1e-30 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  c1 = p1 + s * d1;
  c2 = p2 + t * d2;
}

struct Closest {
  double d = std::numeric_limits<double>::infinity();
  Vector3d pa, pb;
  void offer(const Vector3d &a, const Vector3d &b) {
    const double dd = (b - a).norm();
    if (dd < d) {
      d = dd;
      pa = a;
      pb = b;
    }
  }
};

Closest triangle_distance(const Tri &a, const Tri &b) {
  Closest c;
  for (int i = 0; i < 3; ++i) {
    c.offer(a.v[i], closest_on_triangle(a.v[i], b.v[0], b.v[1], b.v[2]));
    c.offer(closest_on_triangle(b.v[i], a.v[0], a.v[1], a.v[2]), b.v[i]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Vector3d ca, cb;
      closest_segments(a.v[i], a.v[(i + 1) % 3], b.v[j], b.v[(j + 1) % 3], ca, cb);
      c.offer(ca, cb);
    }
  return c;
}

// All triangle pairs closer than `layer`, as the distance kernel would report them.
std::vector<TriangleContact> brute_contacts(const Mesh &a, const Mesh &b, double layer) {
  std::vector<TriangleContact> out;
  for (int i = 0; i < static_cast<int>(a.size()); ++i) {
    Vector3d alo = a[i].v[0].cwiseMin(a[i].v[1]).cwiseMin(a[i].v[2]);
    Vector3d ahi = a[i].v[0].cwiseMax(a[i].v[1]).cwiseMax(a[i].v[2]);
    for (int j = 0; j < static_cast<int>(b.size()); ++j) {
      const Vector3d blo = b[j].v[0].cwiseMin(b[j].v[1]).cwiseMin(b[j].v[2]);
      const Vector3d bhi = b[j].v[0].cwiseMax(b[j].v[1]).cwiseMax(b[j].v[2]);
      if (((blo - ahi).array() > layer).any() || ((alo - bhi).array() > layer).any())
        continue;
      const Closest c = triangle_distance(a[i], b[j]);
      if (c.d >= layer)
        continue;
      EXPECT_GT(c.d, 0.0) << "scene triangles must not intersect";
      out.push_back({i, j, c.d, c.pa, c.pb, (c.pb - c.pa) / c.d, false, 0.0});
    }
  }
  return out;
}

// ---- scenes ----

// Axis-aligned unit square grid of k x k cells (2 triangles each) mapped by origin + u*s + v*t.
void add_grid(Mesh &m, const Vector3d &origin, const Vector3d &s, const Vector3d &t, int k) {
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const Vector3d p00 = origin + s * (double(i) / k) + t * (double(j) / k);
      const Vector3d p10 = origin + s * (double(i + 1) / k) + t * (double(j) / k);
      const Vector3d p01 = origin + s * (double(i) / k) + t * (double(j + 1) / k);
      const Vector3d p11 = origin + s * (double(i + 1) / k) + t * (double(j + 1) / k);
      m.push_back({{p00, p10, p11}});
      m.push_back({{p00, p11, p01}});
    }
}

// Cube of side `side`, 2 k^2 triangles per face, rotated by R about its centre.
Mesh cube(double side, int k, const Vector3d &centre, const Matrix3d &R = Matrix3d::Identity()) {
  Mesh m;
  const double h = 0.5 * side;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      Vector3d o = Vector3d::Constant(-h);
      o[axis] = sign * h;
      Vector3d s = Vector3d::Zero(), t = Vector3d::Zero();
      s[(axis + 1) % 3] = side;
      t[(axis + 2) % 3] = side;
      add_grid(m, o, s, t, k);
    }
  for (Tri &t : m)
    for (Vector3d &v : t.v)
      v = centre + R * v;
  return m;
}

// Square plane z = 0, [-half, half]^2, k x k cells.
Mesh plane(double half, int k) {
  Mesh m;
  add_grid(m, Vector3d(-half, -half, 0), Vector3d(2 * half, 0, 0), Vector3d(0, 2 * half, 0), k);
  return m;
}

const double kSide = 0.004; // m, the design's rock size
const double kEps = 1e-4;   // m, soft layer of each body
const double kLayer = 2 * kEps;
const double kKn = 2000.0; // N/m

// cell_a, cell_b: grid cell sides; a grid triangle's longest edge is the cell's diagonal and
// its shortest the cell's side (the paper's minimum mesh width).
tri::ReductionParams params_for(double cell_a, double cell_b) {
  tri::ReductionParams p;
  p.link_length =
      tri::recommended_link_length(std::sqrt(2.0) * cell_a, std::sqrt(2.0) * cell_b, kEps, kEps);
  p.min_width = std::min(cell_a, cell_b);
  p.reference_direction = -Vector3d::UnitZ(); // cube (a) above plane (b)
  return p;
}

// Static normal force on the cube (a), N.
Vector3d force_on_cube(const std::vector<ContactPoint> &points, const Vector3d &centre) {
  tri::BodyState a, b;
  a.x = centre;
  a.mass = 1e-3;
  tri::ContactCoefficients c;
  c.kn = kKn;
  c.tangential = tri::TangentialModel::no_history;
  return tri::pair_contact_force(points, a, b, c, 1e-6, nullptr).force_a;
}

struct Case {
  int k;          // cube cells per face edge: 2 k^2 triangles per face
  int plane_k;    // plane cells per edge
  double overlap; // gap = kLayer - overlap at the lowest point
};

struct Outcome {
  int raw, paper, clusters;
  Vector3d force, point;
};

Outcome run_case(const Case &cs, const Matrix3d &R = Matrix3d::Identity()) {
  const double half_plane = 0.75 * kSide;
  const Mesh b = plane(half_plane, cs.plane_k);
  // Place the cube so that its lowest vertex is at height kLayer - overlap.
  Mesh a = cube(kSide, cs.k, Vector3d::Zero(), R);
  double low = std::numeric_limits<double>::infinity();
  for (const Tri &t : a)
    for (const Vector3d &v : t.v)
      low = std::min(low, v.z());
  const Vector3d centre(0, 0, kLayer - cs.overlap - low);
  for (Tri &t : a)
    for (Vector3d &v : t.v)
      v += centre;
  const std::vector<TriangleContact> raw = brute_contacts(a, b, kLayer);
  const tri::TriangleSoA sa = soa_of(a), sb = soa_of(b);
  const tri::ReductionParams p = params_for(kSide / cs.k, 2 * half_plane / cs.plane_k);
  tri::ReductionParams paper = p;
  paper.method = tri::ReductionMethod::paper_min_width;
  const auto points = tri::reduce_contacts(raw, sa, kEps, sb, kEps, p);
  Outcome o;
  o.raw = static_cast<int>(raw.size());
  o.paper = static_cast<int>(tri::reduce_contacts(raw, sa, kEps, sb, kEps, paper).size());
  o.clusters = static_cast<int>(points.size());
  o.force = force_on_cube(points, centre);
  o.point = points.empty() ? Vector3d::Zero() : Vector3d(points[0].point - centre);
  return o;
}

Matrix3d small_tilt() {
  return (Eigen::AngleAxisd(0.01, Vector3d::UnitX()) * Eigen::AngleAxisd(0.006, Vector3d::UnitY()))
      .toRotationMatrix();
}

// A cube meshed with 12, 48, 192, 768 triangles on a plane meshed coarse (2 triangles),
// matched and fine (cells of eps: many plane triangles lie just outside the footprint and see
// the cube's bottom edges at a slant): the total force is kn * overlap whatever the meshes.
TEST(ContactReduction, FlatFaceForceIndependentOfMeshResolution) {
  for (const double overlap : {0.1 * kLayer, 0.45 * kLayer, 0.8 * kLayer})
    for (const bool tilted : {false, true})
      for (const int plane_k : {1, 8, 60})
        for (const int k : {1, 2, 4, 8}) {
          const Outcome o =
              run_case({k, plane_k, overlap}, tilted ? small_tilt() : Matrix3d::Identity());
          const double expected = kKn * overlap;
          std::printf("overlap/layer %.2f tilt %d plane %2d tri/face %3d: raw %5d paper %4d "
                      "clusters %d  Fz/(kn overlap) %.6f  point-centre (%.2e, %.2e)\n",
                      overlap / kLayer, tilted, plane_k, 2 * k * k, o.raw, o.paper, o.clusters,
                      o.force.z() / expected, o.point.x(), o.point.y());
          EXPECT_EQ(o.clusters, 1) << "k " << k << " plane " << plane_k;
          EXPECT_NEAR(o.force.z(), expected, 0.01 * expected) << "k " << k << " plane " << plane_k;
          EXPECT_NEAR(o.force.head<2>().norm(), 0.0, 0.01 * expected);
        }
}

// The weight that the cube carries at equilibrium fixes its overlap: the same at every mesh.
TEST(ContactReduction, EquilibriumOverlapIndependentOfMeshResolution) {
  const double weight = kKn * 0.6 * kLayer; // N
  std::vector<double> overlaps;
  for (const int k : {1, 2, 4, 8}) {
    double lo = 0.0, hi = kLayer;
    // The target must lie between the forces at the ends, or the bisection finds nothing.
    ASSERT_LT(run_case({k, 60, lo}).force.z(), weight) << "k " << k;
    ASSERT_GT(run_case({k, 60, 0.999 * hi}).force.z(), weight) << "k " << k;
    for (int it = 0; it < 16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (run_case({k, 60, mid}).force.z() < weight ? lo : hi) = mid;
    }
    overlaps.push_back(0.5 * (lo + hi));
    // Converged to the equilibrium: the force there is the weight.
    EXPECT_NEAR(run_case({k, 60, overlaps.back()}).force.z(), weight, 1e-3 * weight) << "k " << k;
    std::printf("tri/face %3d: equilibrium overlap / layer %.6f\n", 2 * k * k,
                overlaps.back() / kLayer);
  }
  for (double o : overlaps)
    EXPECT_NEAR(o, overlaps[0], 0.01 * overlaps[0]);
}

// The paper's baseline keeps more points as the mesh is refined: why it is not enough.
TEST(ContactReduction, PaperBaselineCountGrowsWithResolution) {
  const Outcome coarse = run_case({1, 1, 0.45 * kLayer});
  const Outcome fine = run_case({8, 1, 0.45 * kLayer});
  EXPECT_GE(fine.paper, 4 * coarse.paper);
  EXPECT_EQ(fine.clusters, 1);
}

// A non-convex particle (two cubes joined as one mesh) touching the plane in two places.
TEST(ContactReduction, TwoSeparateRegionsStayTwoContacts) {
  const double gap = kLayer - 0.5 * kLayer;
  const double z = 0.5 * kSide + gap;
  Mesh a = cube(kSide, 4, Vector3d(-kSide, 0, z));
  const Mesh right = cube(kSide, 4, Vector3d(kSide, 0, z));
  a.insert(a.end(), right.begin(), right.end());
  const Mesh b = plane(2 * kSide, 16); // cells of kSide / 4, like the cubes'
  const auto raw = brute_contacts(a, b, kLayer);
  const auto points =
      tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, params_for(kSide / 4, kSide / 4));
  ASSERT_EQ(points.size(), 2u);
  std::vector<double> xs = {points[0].point.x(), points[1].point.x()};
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -kSide, 0.25 * kSide);
  EXPECT_NEAR(xs[1], kSide, 0.25 * kSide);
  for (const ContactPoint &p : points) {
    EXPECT_NEAR(p.overlap, kLayer - gap, 1e-12);
    EXPECT_NEAR(p.normal.z(), -1.0, 1e-9);
  }
}

// A cube wedged in a corner: on the floor and against a wall, the two patches meeting at the
// cube's edge. Two contacts, one per face, with their own normals and overlaps.
TEST(ContactReduction, WedgedInCornerKeepsOneContactPerFace) {
  const double gap_floor = 0.4 * kLayer, gap_wall = 0.7 * kLayer;
  const Vector3d centre(-0.5 * kSide - gap_wall, 0, 0.5 * kSide + gap_floor);
  const Mesh a = cube(kSide, 4, centre);
  Mesh b;
  add_grid(b, Vector3d(-2 * kSide, -kSide, 0), Vector3d(2 * kSide, 0, 0), Vector3d(0, 2 * kSide, 0),
           16);
  add_grid(b, Vector3d(0, -kSide, 0), Vector3d(0, 2 * kSide, 0), Vector3d(0, 0, 2 * kSide), 16);
  const auto raw = brute_contacts(a, b, kLayer);
  tri::ReductionParams p = params_for(kSide / 4, kSide / 8);
  p.reference_direction = Vector3d(1, 0, -1).normalized();
  const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, p);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_NEAR(points[0].overlap, kLayer - gap_floor, 1e-12);
  EXPECT_GT(points[0].normal.dot(-Vector3d::UnitZ()), 0.999);
  EXPECT_NEAR(points[1].overlap, kLayer - gap_wall, 1e-12);
  EXPECT_GT(points[1].normal.dot(Vector3d::UnitX()), 0.999);
}

// Shuffles `raw` `trials` times and expects reduce_contacts to give `ref` bit for bit.
void expect_order_independent(std::vector<TriangleContact> &raw, const tri::TriangleSoA &sa,
                              const tri::TriangleSoA &sb, const tri::ReductionParams &p,
                              const std::vector<tri::ContactPoint> &ref, unsigned seed,
                              int trials) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < trials; ++trial) {
    std::shuffle(raw.begin(), raw.end(), rng);
    const auto out = tri::reduce_contacts(raw, sa, kEps, sb, kEps, p);
    ASSERT_EQ(out.size(), ref.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(out[i].point[k], ref[i].point[k]);
        EXPECT_EQ(out[i].normal[k], ref[i].normal[k]);
      }
      EXPECT_EQ(out[i].overlap, ref[i].overlap);
      EXPECT_EQ(out[i].num_merged, ref[i].num_merged);
      EXPECT_EQ(out[i].tri_a, ref[i].tri_a);
      EXPECT_EQ(out[i].tri_b, ref[i].tri_b);
    }
  }
}

// Any permutation of the triangle-pair contacts gives a bit-identical result.
TEST(ContactReduction, PermutationOfInputGivesIdenticalOutput) {
  const double gap = 0.3 * kLayer;
  const Mesh a = cube(kSide, 4, Vector3d(0.0001, -0.0002, 0.5 * kSide + gap), small_tilt());
  const Mesh b = plane(0.75 * kSide, 60);
  std::vector<TriangleContact> raw = brute_contacts(a, b, kLayer);
  ASSERT_GT(raw.size(), 100u);
  const tri::ReductionParams p = params_for(kSide / 4, 1.5 * kSide / 60);
  const tri::TriangleSoA sa = soa_of(a), sb = soa_of(b);
  const auto ref = tri::reduce_contacts(raw, sa, kEps, sb, kEps, p);
  expect_order_independent(raw, sa, sb, p, ref, 12345, 5);
}

// The same for a small set (the reduction ranks up to two dozen contacts instead of sorting
// them), where a cube lying flat gives contacts tied in overlap, ordered by their triangles;
// and with one contact given twice (tied in overlap and triangles: the full comparator), whose
// result must not depend on the order either.
TEST(ContactReduction, PermutationOfFewTiedContactsGivesIdenticalOutput) {
  const double gap = 0.3 * kLayer;
  const Mesh a = cube(kSide, 1, Vector3d(0.0001, -0.0002, 0.5 * kSide + gap));
  const Mesh b = plane(0.75 * kSide, 1);
  std::vector<TriangleContact> raw = brute_contacts(a, b, kLayer);
  ASSERT_GE(raw.size(), 4u);
  ASSERT_LE(raw.size(), 23u); // within the ranked sizes, also with one contact twice
  int tied = 0;
  for (std::size_t i = 1; i < raw.size(); ++i)
    tied += raw[i].distance == raw[0].distance;
  ASSERT_GT(tied, 0); // ties in overlap, settled by the triangles
  const tri::ReductionParams p = params_for(kSide, 1.5 * kSide);
  const tri::TriangleSoA sa = soa_of(a), sb = soa_of(b);
  for (int twice = 0; twice < 2; ++twice) {
    if (twice)
      raw.push_back(raw[raw.size() / 2]);
    const auto ref = tri::reduce_contacts(raw, sa, kEps, sb, kEps, p);
    ASSERT_FALSE(ref.empty());
    expect_order_independent(raw, sa, sb, p, ref, 777 + twice, 8);
  }
}

// Hand-made contacts test the clustering, not the placement: their triangles are taken
// perpendicular to each other (a's in planes x = const, b's in planes y = const), so that no
// member has a contact polygon and each keeps its midpoint, weighted by overlap (the rule for
// vertex, edge and tilted-face contacts). Triangle indices 0..15.
Mesh crossed_triangles(int count, int axis) {
  Mesh m;
  for (int i = 0; i < count; ++i) {
    Tri t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = Vector3d::Zero();
      t.v[k][axis] = 1e-4 * i;
    }
    t.v[1][(axis + 1) % 3] = 1e-4;
    t.v[2][(axis + 2) % 3] = 1e-4;
    m.push_back(t);
  }
  return m;
}

std::vector<ContactPoint> reduce_crossed(const std::vector<TriangleContact> &raw, int count_a,
                                         int count_b, const tri::ReductionParams &p) {
  return tri::reduce_contacts(raw, soa_of(crossed_triangles(count_a, 0)), kEps,
                              soa_of(crossed_triangles(count_b, 1)), kEps, p);
}

// Hand-made contacts name triangles that are never parallel (no contact polygons) and lie a
// metre away from the contacts' points, so that an intersecting contact's depth through the
// intersection (no vertex within the crossing's footprint) adds nothing to its own.
std::vector<ContactPoint> reduce_hand(const std::vector<TriangleContact> &raw,
                                      const tri::ReductionParams &p) {
  Mesh a = crossed_triangles(16, 0), b = crossed_triangles(16, 1);
  for (Mesh *m : {&a, &b})
    for (Tri &t : *m)
      for (Vector3d &v : t.v)
        v += Vector3d(1.0, 1.0, 1.0);
  return tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, p);
}

TriangleContact hand_contact(int ta, int tb, const Vector3d &p, const Vector3d &n, double d,
                             bool intersecting, double depth = 0.0) {
  if (d == 0.0) // n may be NaN on purpose
    return {ta, tb, d, p, p, n, intersecting, depth};
  return {ta, tb, d, p - 0.5 * d * n, p + 0.5 * d * n, n, intersecting, depth};
}

// Intersecting triangles: a non-finite kernel normal falls back to the reference direction.
TEST(ContactReduction, IntersectingContactWithoutNormalGetsReferenceDirection) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  tri::ReductionParams p = params_for(1e-3, 1e-3);
  p.reference_direction = Vector3d(3, 0, 4); // not unit on purpose
  const auto points = reduce_hand(
      {hand_contact(0, 0, Vector3d(1e-3, 0, 0), Vector3d(nan, nan, nan), 0.0, true, 3e-5)}, p);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(points[0].intersecting);
  EXPECT_TRUE(points[0].normal.allFinite());
  EXPECT_NEAR((points[0].normal - Vector3d(0.6, 0, 0.8)).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(points[0].overlap, kLayer + 3e-5); // layer + penetration depth
}

// Two intersecting pairs at one spot with opposite normals (a deep, symmetric crossing): the
// weighted mean cancels, yet the contact's normal is finite and unit.
TEST(ContactReduction, OpposingIntersectingNormalsStayFinite) {
  const Vector3d n(0, 0, 1);
  const auto points = reduce_hand({hand_contact(0, 0, Vector3d::Zero(), n, 0.0, true),
                                   hand_contact(1, 1, Vector3d(1e-5, 0, 0), -n, 0.0, true)},
                                  params_for(1e-3, 1e-3));
  ASSERT_FALSE(points.empty());
  for (const ContactPoint &c : points) {
    EXPECT_TRUE(c.normal.allFinite());
    EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
  }
}

// A face sunk below the plane by d (a above b, true normal -z): the bottom-face pairs are
// separated but see the plane from behind (normal +z, distance d); the side faces cross the
// plane (depth d). One contact, normal -z, overlap layer + d: the force still pushes a out.
TEST(ContactReduction, SunkFaceIsFlippedToPushOut) {
  const double d = 0.5 * kEps;
  std::vector<TriangleContact> raw;
  for (int i = 0; i < 4; ++i)
    raw.push_back(hand_contact(i, i, Vector3d(1e-4 * i, 0, 0), Vector3d::UnitZ(), d, false));
  raw.push_back(hand_contact(10, 4, Vector3d(-1e-4, 0, 0), -Vector3d::UnitZ(), 0.0, true, d));
  raw.push_back(hand_contact(11, 5, Vector3d(4e-4, 0, 0), -Vector3d::UnitZ(), 0.0, true, d));
  const auto points = reduce_hand(raw, params_for(2e-4, 2e-4));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].normal.z(), -1.0, 1e-12);
  EXPECT_NEAR(points[0].overlap, kLayer + d, 1e-15);
  EXPECT_EQ(points[0].num_merged, 6);
  EXPECT_TRUE(points[0].intersecting);
}

// A flat patch (a above b, normal -z, gap g) and one contact at its border where b's triangle
// lies outside the footprint and sees a's edge at 56 degrees: absorbed into the patch, and it
// neither moves nor tilts it. A contact of a perpendicular face next to it is not absorbed.
TEST(ContactReduction, RimContactIsAbsorbedPerpendicularFaceIsNot) {
  const double g = 0.2 * kLayer, h = 1.5 * g;
  std::vector<TriangleContact> raw;
  for (int i = 0; i < 3; ++i)
    raw.push_back(
        hand_contact(i, i, Vector3d(-1e-4 * i, 0, 0.5 * g), -Vector3d::UnitZ(), g, false));
  const Vector3d corner(0, 0, g), below(h, 0, 0);
  raw.push_back(
      {7, 7, (below - corner).norm(), corner, below, (below - corner).normalized(), false, 0.0});
  auto points = reduce_hand(raw, params_for(1e-4, 1e-4));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].num_merged, 4);
  EXPECT_NEAR(points[0].normal.z(), -1.0, 1e-15);
  EXPECT_NEAR(points[0].point.x(), -1e-4, 1e-15);
  EXPECT_NEAR(points[0].overlap, kLayer - g, 1e-15);
  // A wall face at x = 1.5 g, touched by a's side at distance 0.9 g: a contact of its own.
  raw.push_back(
      hand_contact(8, 8, Vector3d(1.05 * g, 0, 0.5 * g), Vector3d::UnitX(), 0.9 * g, false));
  points = reduce_hand(raw, params_for(1e-4, 1e-4));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_NEAR(points[0].normal.x(), 1.0, 1e-15);
  EXPECT_NEAR(points[1].normal.z(), -1.0, 1e-15);
}

// Raw contacts at or beyond the layer carry no force and are dropped; no contacts, no points.
TEST(ContactReduction, ContactsOutsideTheLayerAreIgnored) {
  EXPECT_TRUE(reduce_hand({}, params_for(1e-3, 1e-3)).empty());
  const auto points =
      reduce_hand({hand_contact(0, 0, Vector3d::Zero(), Vector3d::UnitZ(), kLayer, false)},
                  params_for(1e-3, 1e-3));
  EXPECT_TRUE(points.empty());
}

TEST(ContactReduction, RecommendedLinkLengthUsesFinerMesh) {
  EXPECT_NEAR(
      tri::recommended_link_length(1e-3, std::numeric_limits<double>::infinity(), 1e-4, 2e-4),
      2e-3 + 3e-4, 1e-8 * 2.3e-3);
  EXPECT_NEAR(tri::recommended_link_length(5e-3, 1e-3, 1e-4, 1e-4), 2.2e-3, 1e-8 * 2.2e-3);
}

// ---- the contact point of flat faces: contact polygons (contact_polygon.h) ----

// Triangle contacts of a and b: source 0 the brute force above, 1 and 2 the distance kernel
// (brute force, hybrid). On parallel faces each picks its own arbitrary closest pairs.
std::vector<TriangleContact> contacts_by(int source, const Mesh &a, const Mesh &b) {
  if (source == 0)
    return brute_contacts(a, b, kLayer);
  tri::ContactOptions opt;
  opt.kernel = source == 1 ? tri::DistanceKernel::BruteForce : tri::DistanceKernel::Hybrid;
  tri::ContactStats stats;
  std::vector<TriangleContact> out;
  tri_test::find_triangle_contacts(soa_of(a), kEps, soa_of(b), kEps, opt, out, stats);
  return out;
}

// A cube (2 k^2 triangles per face) turned by R and moved so that its lowest vertex is at
// height `gap` above the plane z = 0, its centre above (x, y); returns the centre.
Vector3d place_cube(Mesh &a, int k, const Vector3d &xy, double gap, const Matrix3d &R) {
  a = cube(kSide, k, Vector3d::Zero(), R);
  double low = std::numeric_limits<double>::infinity();
  for (const Tri &t : a)
    for (const Vector3d &v : t.v)
      low = std::min(low, v.z());
  const Vector3d centre(xy.x(), xy.y(), gap - low);
  for (Tri &t : a)
    for (Vector3d &v : t.v)
      v += centre;
  return centre;
}

Matrix3d yaw(double angle) {
  return Eigen::AngleAxisd(angle, Vector3d::UnitZ()).toRotationMatrix();
}

// The cube of the problem statement: resting flat, meshed 2 to 128 triangles per face, on a
// plane of 2 triangles or finely meshed, centred anywhere, turned about z or not, contacts from
// three sources. The point is the centre of the bottom face on the mid-plane, to rounding;
// before contact polygons it was 1.2 mm off (2 triangles per face, 2-triangle plane).
TEST(ContactReductionPoint, FlatFaceIsCentredForEveryMeshing) {
  const Vector3d xy(0.37e-3, -0.21e-3, 0);
  const double gap = 0.5 * kLayer, half_plane = 1.5 * kSide;
  double worst = 0.0;
  for (const int plane_k : {1, 16, 60})
    for (const int k : {1, 2, 4, 8})
      for (const double turn : {0.0, 0.3})
        for (int source = 0; source < 3; ++source) {
          if (plane_k == 60 && source == 0)
            continue; // the slow test-side brute force is covered by the coarser planes
          Mesh a;
          place_cube(a, k, xy, gap, yaw(turn));
          const Mesh b = plane(half_plane, plane_k);
          const auto raw = contacts_by(source, a, b);
          const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                                   params_for(kSide / k, 2 * half_plane / plane_k));
          ASSERT_EQ(points.size(), 1u) << "k " << k << " plane " << plane_k;
          const Vector3d expected = xy + Vector3d(0, 0, 0.5 * gap);
          const double off = (points[0].point - expected).norm();
          worst = std::max(worst, off);
          EXPECT_LE(off, 1e-6 * kSide) << "tri/face " << 2 * k * k << " plane " << plane_k
                                       << " yaw " << turn << " source " << source;
          EXPECT_NEAR(points[0].overlap, kLayer - gap, 1e-12 * kLayer);
          EXPECT_NEAR(points[0].normal.z(), -1.0, 1e-12);
        }
  std::printf("flat cube: largest contact-point offset %.3e m (side %.0e m)\n", worst, kSide);
}

// The cube overhangs a corner of the plane: the point is the centre of the overlap rectangle.
TEST(ContactReductionPoint, OverhangingCubeIsCentredOnTheOverlap) {
  const double half_plane = 0.75 * kSide, gap = 0.3 * kLayer, h = 0.5 * kSide;
  const Vector3d xy(half_plane - 0.2 * kSide, -half_plane + 0.35 * kSide, 0);
  // Overlap of [x - h, x + h] x [y - h, y + h] with the plane [-H, H]^2.
  const double x0 = std::max(xy.x() - h, -half_plane), x1 = std::min(xy.x() + h, half_plane);
  const double y0 = std::max(xy.y() - h, -half_plane), y1 = std::min(xy.y() + h, half_plane);
  const Vector3d expected(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * gap);
  ASSERT_GT((expected.head<2>() - xy.head<2>()).norm(), 0.1 * kSide); // a real overhang
  for (const int plane_k : {1, 16})
    for (const int k : {1, 2, 4, 8})
      for (int source = 0; source < 3; source += 2) {
        Mesh a;
        place_cube(a, k, xy, gap, Matrix3d::Identity());
        const Mesh b = plane(half_plane, plane_k);
        const auto raw = contacts_by(source, a, b);
        const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                                 params_for(kSide / k, 2 * half_plane / plane_k));
        ASSERT_EQ(points.size(), 1u);
        EXPECT_LE((points[0].point - expected).norm(), 1e-6 * kSide)
            << "tri/face " << 2 * k * k << " plane " << plane_k << " source " << source << ": "
            << points[0].point.transpose() << " vs " << expected.transpose();
      }
}

// Faces tilted by a small angle (below kParallelFaceAngle) press harder on their lower side.
// Nearly flat (tilt 1e-5 rad: the overlap is uneven by 1.25e-4 of the deepest, r = 1.25e-3)
// the point lies within (weight of the deepest point, step 5b) of the centre of the patch's
// area, for every meshing, and the overlap is o_s (1 - c).
// Clearly tilted (0.02 rad: uneven by 25 % of the deepest; 0.03 rad: the layers overlap on a
// strip along the low edge only) it is the deepest pairs' midpoint, on the low edge, with the
// deepest overlap: the force of the potential 1/2 kn overlap^2.
TEST(ContactReductionPoint, SlightlyTiltedFaceSlidesFromTheAreaCentreToTheLowEdge) {
  const double gap = 0.2 * kLayer, h = 0.5 * kSide;
  const Vector3d xy(-0.3e-3, 0.45e-3, 0);
  for (const double tilt : {1e-5, 0.02, 0.03}) {
    const Matrix3d R = Eigen::AngleAxisd(tilt, Vector3d::UnitY()).toRotationMatrix(); // +x low
    // Along the face, s in [-h, h] from its centre, the gap is gap + sin(tilt) (h - s): the
    // overlap o(s) = o_low - slope (h - s).
    const double slope = std::sin(tilt), o_low = kLayer - gap;
    const bool flat = tilt < 1e-4;
    // Flat case: the whole face overlaps, mean = o(0), area centre at s = 0.
    const double uneven = slope * h, r = uneven / (tri::kFlatPatchBand * o_low);
    const double t = (1.0 - r) * (1.0 - 3.0 * r), c = 2.0 * tri::kFlatPatchBand * r * r * (1.0 - r);
    const double slide = (1.0 - t - c) / (1.0 - c); // weight of the low edge's middle
    const double expected_overlap = (o_low - uneven * (1.0 - r) * (1.0 - r)) * (1.0 - c);
    std::vector<Vector3d> found;
    for (const int plane_k : {1, 16})
      for (const int k : {1, 2, 4, 8}) {
        Mesh a;
        const Vector3d centre = place_cube(a, k, xy, gap, R);
        const Mesh b = plane(1.5 * kSide, plane_k);
        const auto raw = contacts_by(2, a, b);
        const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                                 params_for(kSide / k, 3 * kSide / plane_k));
        ASSERT_EQ(points.size(), 1u);
        found.push_back(points[0].point);
        const Vector3d face_centre = centre + R * Vector3d(0, 0, -h);
        const double dx = points[0].point.x() - face_centre.x();
        std::printf("tilt %.5f tri/face %3d plane %2d: point - face centre (%.4e, %.4e), "
                    "overlap %.6e\n",
                    tilt, 2 * k * k, plane_k, dx, points[0].point.y() - face_centre.y(),
                    points[0].overlap);
        // Step 6: a face on a face, even or uneven (beyond the band's end the energy blend
        // beta is 0), has face weight 1 this far below 5 degrees of tilt.
        EXPECT_NEAR(points[0].face_weight, 1.0, 1e-9) << "tilt " << tilt;
        if (flat) {
          ASSERT_LT(r, 0.01);
          // The deepest point: at this tilt the whole face lies within kDeepestTaper of the
          // deepest pair, so it is an average of closest points on the low half of the face
          // (tapered towards the low edge), between the face's centre and the low edge.
          EXPECT_GE(dx, 0.0);
          EXPECT_LE(dx, slide * h * std::cos(tilt) + 1e-9 * kSide);
          EXPECT_LE(std::abs(points[0].point.y() - face_centre.y()), slide * h);
          EXPECT_NEAR(points[0].overlap, expected_overlap, 1e-9 * kLayer);
        } else {
          // At the low edge: the deepest region of the polygons, within the taper's extent
          // (kDeepestTaper of the layer, over a slope of sin(tilt)) of the edge; the overlap
          // is the polygons' (measured along their bisector: short of the perpendicular one
          // by gap (1 / cos(tilt / 2) - 1)).
          const double taper_extent = 1e-3 * kLayer / slope;
          EXPECT_LE(dx, h * std::cos(tilt) + 1e-9 * kSide);
          EXPECT_GE(dx, h * std::cos(tilt) - taper_extent);
          EXPECT_LE(std::abs(points[0].point.y() - face_centre.y()), h * (1 + 1e-9));
          EXPECT_NEAR(points[0].overlap, o_low, gap * tilt * tilt / 4 + 1e-9 * kLayer);
        }
      }
    if (flat) {
      for (const Vector3d &p : found)
        EXPECT_LE((p - found[0]).norm(), 1e-2 * kSide) << "tilt " << tilt;
    }
  }
}

// The point and the overlap of a face contact are those of a potential: along a path that
// tilts a face from clearly uneven one way, through flat, to clearly uneven the other way, the
// work of the reduced contact's force and torque (kn overlap n at point) equals the change of
// 1/2 kn overlap^2 between the ends (step 5b). A linear blend from the centre of pressure to
// the deepest pair with the deepest overlap (the previous model) misses by 0.5 %.
TEST(ContactReductionPoint, FaceContactForceIsTheGradientOfItsEnergy) {
  const double gap = 0.3 * kLayer, h = 0.5 * kSide;
  const Vector3d xy(0.1e-3, -0.2e-3, 0);
  const Mesh b = plane(1.5 * kSide, 4);
  const double band_tilt = tri::kFlatPatchBand * (kLayer - gap) / h; // tilt where r = 1
  for (const int k : {1, 4}) {
    auto state = [&](double tilt, double lift, Vector3d &point, double &overlap, Vector3d &centre,
                     Vector3d *normal = nullptr) {
      const Matrix3d R = Eigen::AngleAxisd(tilt, Vector3d::UnitY()).toRotationMatrix();
      Mesh a;
      centre = place_cube(a, k, xy, gap + lift, R);
      const auto raw = contacts_by(2, a, b);
      const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                               params_for(kSide / k, 3 * kSide / 4));
      ASSERT_EQ(points.size(), 1u);
      point = points[0].point;
      overlap = points[0].overlap;
      if (normal)
        *normal = points[0].normal;
    };
    // Path in (tilt, lift): from -2 band_tilt through flat to 1.5 band_tilt (the overlap goes
    // from clearly tilted through flat to clearly tilted the other way, where the energy is
    // 1/2 kn overlap^2) while lifting by 0.1 layer along a parabola (place_cube keeps the low edge
    // at gap + lift, so the centre moves too); midpoint rule.
    const int steps = 400;
    auto tilt_at = [&](int i) { return band_tilt * (-2.0 + 3.5 * i / steps); };
    auto lift_at = [&](int i) { return 0.1 * kLayer * (double(i) / steps) * (double(i) / steps); };
    double work = 0.0, overlap0 = 0.0, overlap1 = 0.0;
    Vector3d p = Vector3d::Zero(), c, c_begin, c_end, unused;
    double o = 0.0;
    Vector3d n = -Vector3d::UnitZ();
    state(tilt_at(0), lift_at(0), unused, overlap0, c_begin);
    for (int i = 0; i < steps; ++i) {
      state(tilt_at(i + 1), lift_at(i + 1), unused, o, c_end);
      state(0.5 * (tilt_at(i) + tilt_at(i + 1)), 0.5 * (lift_at(i) + lift_at(i + 1)), p, o, c, &n);
      // Force on the cube (a): kn o along -n (kn = 1; n from a to b, about -z). Torque about its
      // centre (p - c) x F; a rotation by d(tilt) is about +y through the centre.
      const Vector3d f = -o * n;
      work += f.dot(c_end - c_begin) + (p - c).cross(f).y() * (tilt_at(i + 1) - tilt_at(i));
      c_begin = c_end;
    }
    overlap1 = o;
    state(tilt_at(steps), lift_at(steps), unused, overlap1, c_end);
    const double energy_change = 0.5 * (overlap1 * overlap1 - overlap0 * overlap0);
    std::printf("k %d: work %.6e, -energy change %.6e\n", k, work, -energy_change);
    EXPECT_NEAR(work, -energy_change, 1e-3 * std::abs(energy_change)) << "k " << k;
  }
}

// The one contact of a and b (kn = 1, the reduction's defaults for cells of a and b).
ContactPoint sole_contact(const Mesh &a, const Mesh &b, double cell_a, double cell_b) {
  const auto points = tri::reduce_contacts(contacts_by(1, a, b), soa_of(a), kEps, soa_of(b), kEps,
                                           params_for(cell_a, cell_b));
  EXPECT_EQ(points.size(), 1u);
  return points.empty() ? ContactPoint{} : points[0];
}

// Along a path s from `from` to `to` (midpoint rule, 400 steps): the work of the contact's
// force, sum of work(contact at s, ds), against minus the change of its energy
// 1/2 energy_overlap^2 (kn = 1); expects them equal to `tolerance` of the energy change.
template <class ContactAt, class Work>
void expect_work_is_energy(double from, double to, ContactAt contact_at, Work work,
                           double tolerance, const char *what) {
  const int steps = 400;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double s0 = from + (to - from) * i / steps, s1 = from + (to - from) * (i + 1) / steps;
    sum += work(contact_at(0.5 * (s0 + s1)), s1 - s0);
  }
  const double e0 = contact_at(from).energy_overlap, e1 = contact_at(to).energy_overlap;
  const double energy_change = 0.5 * (e1 * e1 - e0 * e0);
  std::printf("%s: work %.6e, -energy change %.6e\n", what, sum, -energy_change);
  EXPECT_NEAR(sum, -energy_change, tolerance * std::abs(energy_change)) << what;
}

// A face 9 degrees off another (inside the polygons' 10 degrees) whose triangle reaches only a
// sliver over the other's edge: the sliver's overlap is nearly uniform by its size alone, but
// the faces are not flat on each other. Sliding it over the edge (the sliver growing from 5 to
// 40 um) must cost the work of the contact's force: the energy of a flat patch (its mean
// square overlap) would ignore the edge sweeping through it. Measured with the patch's own
// unevenness alone: 38 % off, the sliver taken for flat; a rock of 40 triangles lost 8e-4 of its
// energy in one such contact (validation/contact/energy_nonconvex, six bodies).
TEST(ContactReductionPoint, SliverOfATiltedFaceKeepsTheEnergy) {
  const double slope = std::tan(9.0 * M_PI / 180.0);
  const Mesh b = {Tri{{Vector3d(0, -1e-3, 0), Vector3d(2e-3, 0, 0), Vector3d(0, 1e-3, 0)}}};
  const double from = 5e-6, to = 40e-6;
  // a: one rigid triangle moved along +x, its apex at x = reach over b, lower by `slope` towards
  // -x; at reach = from it is 0.7 layer above b at b's edge x = 0 (overlap 0.3 layer there, its
  // deepest), and deeper as it slides on.
  auto contact_at = [&](double reach) {
    auto at = [&](double dx, double y) {
      return Vector3d(reach + dx, y, 0.7 * kLayer + slope * (from + dx));
    };
    return sole_contact({Tri{{at(0, 0), at(-2e-3, -1e-3), at(-2e-3, 1e-3)}}}, b, 2e-3, 2e-3);
  };
  // the force on a along its motion, +x
  auto work = [](const ContactPoint &c, double dx) { return -c.overlap * c.normal.x() * dx; };
  expect_work_is_energy(from, to, contact_at, work, 1e-3, "sliver");
}

// A patch narrower than a layer tilting: a triangle 40 um wide lying nearly flat inside a
// larger one (0.2 to 3 degrees, turned about an axis through its corner), so that how flat the
// patch counts depends on the tilt as much as on its own unevenness. The work of the force's
// torque along the tilt equals the energy change: the tilt's share of the unevenness enters
// the torque as a couple (without it 17 % off). What is left, 0.34 % here, is the force's
// direction (the bisector blended with the deepest pair's normal), the gradient's only to
// first order in the tilt: it grows with the lever across the layer, -0.7 % about a pivot
// halfway through it, -1.5 % about one on b.
TEST(ContactReductionPoint, TiltingNarrowPatchKeepsTheEnergy) {
  const Mesh b = {Tri{{Vector3d(-1e-3, -1e-3, 0), Vector3d(1e-3, -1e-3, 0), Vector3d(0, 1e-3, 0)}}};
  const Vector3d corner(20e-6, 0, 0.75 * kLayer);
  // a's triangle in its own frame (a corner at the origin, extending to -x), turned by `tilt`
  // about y, then moved onto `corner`.
  auto contact_at = [&](double tilt) {
    const Matrix3d R = Eigen::AngleAxisd(-tilt, Vector3d::UnitY()).toRotationMatrix();
    auto at = [&](double x, double y) { return Vector3d(corner + R * Vector3d(x, y, 0)); };
    return sole_contact({Tri{{at(0, 0), at(-40e-6, -20e-6), at(-40e-6, 20e-6)}}}, b, 40e-6, 2e-3);
  };
  // a turns by -d(tilt) about y through `corner`, under the force's torque about it
  auto work = [&](const ContactPoint &c, double dtilt) {
    return (c.point - corner).cross(Vector3d(-c.overlap * c.normal)).y() * -dtilt;
  };
  expect_work_is_energy(0.2 * M_PI / 180, 3.0 * M_PI / 180, contact_at, work, 5e-3,
                        "tilting narrow patch");
}

// Two closest points trading places (header, step 5): a body with two downward spikes (four
// facets each, so each tip is seen by several tied triangle pairs) 2 mm apart rocks over a
// plane so that the tips' depths cross, from 3 tapers one way to 3 tapers the other. The work
// of the reduced force and torque equals the change of 1/2 kn energy_overlap^2 along the path
// to 1e-4 of kn overlap x taper (the scale of what the crossing can gain or lose), and the
// overlap of each tip alone is its depth whatever the number of triangle pairs that see it.
// With the previous rule (the deepest overlap, the point tapered over members within 1e-3 of
// the layer) the work missed by 9.4e-4 of that scale, 9 times the tolerance; this rule is
// within 1e-7 of it.
TEST(ContactReductionPoint, CrossingTipsKeepTheEnergy) {
  const double half = 1e-3, h = 0.5e-3; // tips at x = -+half, spikes h tall
  auto spike = [&](Mesh &m, const Vector3d &tip) {
    const Vector3d c[4] = {{h, 0, h}, {0, h, h}, {-h, 0, h}, {0, -h, h}};
    for (int i = 0; i < 4; ++i)
      m.push_back({{tip, tip + c[i], tip + c[(i + 1) % 4]}});
  };
  const Mesh b = plane(1.5 * kSide, 4);
  const double taper = 1e-3 * kLayer, gap = 0.6 * kLayer;
  const double tilt_end = 3.0 * taper / (2.0 * half);
  auto state = [&](double tilt, double lift, Vector3d &point, Vector3d &normal, double &overlap,
                   double &energy_overlap, Vector3d &centre) {
    const Matrix3d R = Eigen::AngleAxisd(tilt, Vector3d::UnitY()).toRotationMatrix();
    centre = Vector3d(0.1e-3, 0.05e-3, gap + lift + h);
    Mesh a;
    spike(a, Vector3d(-half, 0, -h));
    spike(a, Vector3d(half, 0, -h));
    for (Tri &t : a)
      for (Vector3d &v : t.v)
        v = centre + R * v;
    const auto raw = brute_contacts(a, b, kLayer);
    const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                             params_for(2 * half, 0.75 * kSide));
    ASSERT_EQ(points.size(), 1u);
    point = points[0].point;
    normal = points[0].normal;
    overlap = points[0].overlap;
    energy_overlap = points[0].energy_overlap;
  };
  // Each tip alone deepest by far more than the taper: its own depth.
  Vector3d p, n, c0, c1, c;
  double o, e;
  state(-100 * tilt_end, 0.0, p, n, o, e, c);
  const double t = 100 * tilt_end;
  const double tip_depth = kLayer - (gap + h * (1.0 - std::cos(t)) - half * std::sin(t));
  EXPECT_NEAR(o, tip_depth, 1e-12 * kLayer);
  EXPECT_NEAR(e, tip_depth, 1e-12 * kLayer);
  // The path: tilt through the crossing while lifting by 1 % of the layer (midpoint rule).
  const int steps = 400;
  auto tilt_at = [&](int i) { return tilt_end * (-1.0 + 2.0 * i / steps); };
  auto lift_at = [&](int i) { return 0.01 * kLayer * i / steps; };
  double work = 0.0, e0, e1;
  state(tilt_at(0), lift_at(0), p, n, o, e0, c0);
  for (int i = 0; i < steps; ++i) {
    state(tilt_at(i + 1), lift_at(i + 1), p, n, o, e, c1);
    state(0.5 * (tilt_at(i) + tilt_at(i + 1)), 0.5 * (lift_at(i) + lift_at(i + 1)), p, n, o, e,
          c);
    const Vector3d f = -o * n; // on a (kn = 1; n from a to b)
    work += f.dot(c1 - c0) + (p - c).cross(f).y() * (tilt_at(i + 1) - tilt_at(i));
    c0 = c1;
  }
  state(tilt_at(steps), lift_at(steps), p, n, o, e1, c1);
  const double energy_change = 0.5 * (e1 * e1 - e0 * e0);
  std::printf("work %.9e, -energy change %.9e\n", work, -energy_change);
  EXPECT_NEAR(work, -energy_change, 1e-4 * e0 * taper);
}

// A non-convex pair touching in two spots 2 mm apart: two tips of a pressing on the two
// flanks of a valley in b, 40 degrees apart (inside the 45 degree split angle). Tilting a, the
// tips' overlaps cross. With a distinct-spot distance the spots stay two contacts throughout,
// whichever is deeper, and the force does the work the two contacts' energy loses. As one class
// (distance 0) they were one contact holding the deeper spot's energy alone, and six colliding
// voxel jacks lost 5.6e-4 of their energy in the step where two such spots crossed
// (validation/contact/energy_nonconvex).
TEST(ContactReductionPoint, TwoSpotsOfANonConvexPairStayTwoContacts) {
  const double half = 1e-3, h = 0.5e-3, flank = 20.0 * M_PI / 180.0, t = std::tan(flank);
  const double L = 2e-3, W = 1e-3, gap = 0.9 * kLayer;
  Mesh b;
  add_grid(b, Vector3d(-L, -W, t * L), Vector3d(L, 0, -t * L), Vector3d(0, 2 * W, 0), 2);
  add_grid(b, Vector3d(0, -W, 0), Vector3d(L, 0, t * L), Vector3d(0, 2 * W, 0), 2);
  const double tilt_end = 0.05 * kLayer / half;
  auto state = [&](double tilt, double distinct, std::vector<ContactPoint> &points,
                   Vector3d &centre) {
    const Matrix3d R = Eigen::AngleAxisd(tilt, Vector3d::UnitY()).toRotationMatrix();
    centre = Vector3d(0.0, 0.05e-3, t * half + gap / std::cos(flank));
    Mesh a;
    for (const double x : {-half, half}) {
      const Vector3d tip(x, 0, 0);
      const Vector3d c[4] = {{h, 0, h}, {0, h, h}, {-h, 0, h}, {0, -h, h}};
      for (int i = 0; i < 4; ++i)
        a.push_back({{tip, tip + c[i], tip + c[(i + 1) % 4]}});
    }
    for (Tri &tr : a)
      for (Vector3d &v : tr.v)
        v = centre + R * v;
    // 1 mm cells: the link length (3 mm) joins the spots in one region, as a voxel jack's
    tri::ReductionParams params = params_for(2 * half, L / 2);
    params.distinct_spot_distance = distinct;
    points = tri::reduce_contacts(brute_contacts(a, b, kLayer), soa_of(a), kEps, soa_of(b), kEps,
                                  params);
  };
  std::vector<ContactPoint> points;
  Vector3d c;
  state(0.5 * tilt_end, 0.0, points, c);
  EXPECT_EQ(points.size(), 1u); // one class: the angle alone decides
  auto energy = [](const std::vector<ContactPoint> &ps) {
    double e = 0.0;
    for (const ContactPoint &p : ps)
      e += 0.5 * p.energy_overlap * p.energy_overlap;
    return e;
  };
  const int steps = 200;
  auto tilt_at = [&](double i) { return tilt_end * (-0.25 + 1.25 * i / steps); };
  double work = 0.0;
  state(tilt_at(0), kLayer, points, c);
  const double e0 = energy(points);
  for (int i = 0; i < steps; ++i) {
    state(tilt_at(i + 0.5), kLayer, points, c);
    ASSERT_EQ(points.size(), 2u) << "step " << i;
    for (const ContactPoint &p : points) {
      const Vector3d f = -p.overlap * p.normal; // on a (kn = 1; n from a to b)
      work += (p.point - c).cross(f).y() * (tilt_at(i + 1) - tilt_at(i));
    }
  }
  state(tilt_at(steps), kLayer, points, c);
  const double e1 = energy(points);
  std::printf("work %.9e, -energy change %.9e\n", work, e0 - e1);
  EXPECT_GT(std::abs(e1 - e0), 0.05 * e0); // the tilt moves the energy
  EXPECT_NEAR(work, e0 - e1, 1e-6 * e0);
}

// The same two closest points, one seen by four triangle pairs and one by two, trading places
// as a pair's closest point jumps from one end of a parallel edge to the other (it sees both
// ends tied at that moment): the counts swap while the depths cross. The smooth maximum counts
// each point once, so the reduced point passes the crossing continuously; counting members, it
// jumped by a third of the distance between the points (voxel jacks gained 1.3e-4 of their
// energy in one step, validation/contact/energy_nonconvex).
TEST(ContactReductionPoint, ClosestPointsSeenByManyPairsCountOnce) {
  // Members' triangles: a's stand upright, b's lie flat (never parallel: no polygons).
  Mesh a, b;
  for (int t = 0; t < 2; ++t)
    a.push_back({{Vector3d(t, 0, 0) * 1e-3, Vector3d(t, 0, 1) * 1e-3, Vector3d(t, 1, 1) * 1e-3}});
  for (int t = 0; t < 4; ++t)
    b.push_back({{Vector3d(t, 0, 0) * 1e-3, Vector3d(t + 1, 0, 0) * 1e-3,
                  Vector3d(t, 1, 0) * 1e-3}});
  const double taper = 1e-3 * kLayer, spacing = 0.5 * kLayer, depth = 0.1 * kLayer;
  const Vector3d p1(0.2e-3, 0.3e-3, 0.0), p2 = p1 + Vector3d(spacing, 0.0, 0.0);
  auto member = [&](int ta, int tb, const Vector3d &at, double overlap) {
    TriangleContact c{};
    c.tri_a = ta;
    c.tri_b = tb;
    c.distance = kLayer - overlap;
    c.normal = Vector3d(0, 0, -1); // from a (above) down to b
    c.point_a = at - 0.5 * c.distance * c.normal;
    c.point_b = at + 0.5 * c.distance * c.normal;
    c.intersecting = false;
    c.penetration_depth = 0.0;
    return c;
  };
  // ahead > 0: p1 deeper, seen by a's triangle 0 against b's 0-3, p2 by a's 1 against 0-1;
  // ahead < 0: a's 0 against b's 1 and 2 see p2 now.
  auto reduced_point = [&](double ahead) {
    const double o1 = depth + std::max(0.0, ahead), o2 = depth + std::max(0.0, -ahead);
    std::vector<TriangleContact> raw;
    for (int tb = 0; tb < 4; ++tb) {
      const bool jumped = ahead < 0.0 && (tb == 1 || tb == 2);
      raw.push_back(member(0, tb, jumped ? p2 : p1, jumped ? o2 : o1));
    }
    for (int tb = 0; tb < 2; ++tb)
      raw.push_back(member(1, tb, p2, o2));
    const auto points =
        tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, params_for(1e-3, 1e-3));
    EXPECT_EQ(points.size(), 1u);
    return points.empty() ? Vector3d(Vector3d::Zero()) : points[0].point;
  };
  for (const double ahead : {1e-3 * taper, 1e-5 * taper}) {
    const Vector3d before = reduced_point(ahead), after = reduced_point(-ahead);
    EXPECT_LT((after - before).norm(), 1e-2 * spacing) << "ahead " << ahead / taper << " tapers";
    // Tied, the two points share the force equally: the middle.
    EXPECT_LT((before - 0.5 * (p1 + p2)).norm(), 1e-2 * spacing);
  }
  // Far apart in depth, the deeper point alone.
  EXPECT_LT((reduced_point(3 * taper) - p1).norm(), 1e-9 * spacing);
  EXPECT_LT((reduced_point(-3 * taper) - p2).norm(), 1e-9 * spacing);
  // Tied exactly, with a third point half a taper shallower on their bisector: the deepest's
  // own part of the gradient goes to the two tied points equally, not 4 : 2 by their pairs.
  {
    const Vector3d p3 = 0.5 * (p1 + p2) + Vector3d(0.0, spacing, 0.0);
    std::vector<TriangleContact> raw;
    for (int tb = 0; tb < 4; ++tb)
      raw.push_back(member(0, tb, p1, depth));
    for (int tb = 0; tb < 2; ++tb)
      raw.push_back(member(1, tb, p2, depth));
    raw.push_back(member(1, 2, p3, depth - 0.5 * taper));
    const auto points =
        tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, params_for(1e-3, 1e-3));
    ASSERT_EQ(points.size(), 1u);
    EXPECT_LT(std::abs(points[0].point.x() - 0.5 * (p1.x() + p2.x())), 1e-6 * spacing);
  }
}

// Tilted beyond kParallelFaceAngle the cube rests on an edge or a vertex: no member has a
// contact polygon and the point is exactly what the midpoint rule gives (the same contacts
// reduced with triangles that are never parallel), on the edge or at the vertex.
TEST(ContactReductionPoint, TiltedCubeKeepsItsEdgeOrVertexPoint) {
  const double gap = 0.4 * kLayer;
  const Vector3d xy(0.2e-3, 0.1e-3, 0);
  const Matrix3d rotations[] = {
      Eigen::AngleAxisd(0.5, Vector3d::UnitY()).toRotationMatrix(), // edge down, 29 degrees
      Eigen::AngleAxisd(0.2, Vector3d::UnitY()).toRotationMatrix(), // edge down, 11 degrees
      (Eigen::AngleAxisd(0.6, Vector3d::UnitX()) * Eigen::AngleAxisd(0.4, Vector3d::UnitY()))
          .toRotationMatrix()}; // vertex down
  for (int r = 0; r < 3; ++r)
    for (const int plane_k : {1, 16})
      for (const int k : {1, 4}) {
        Mesh a;
        place_cube(a, k, xy, gap, rotations[r]);
        const Mesh b = plane(1.5 * kSide, plane_k);
        const auto raw = contacts_by(2, a, b);
        const tri::ReductionParams p = params_for(kSide / k, 3 * kSide / plane_k);
        const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, p);
        const auto midpoint_rule =
            reduce_crossed(raw, static_cast<int>(a.size()), static_cast<int>(b.size()), p);
        ASSERT_EQ(points.size(), 1u);
        ASSERT_EQ(midpoint_rule.size(), 1u);
        for (int i = 0; i < 3; ++i)
          EXPECT_EQ(points[0].point[i], midpoint_rule[0].point[i]);
        // At the lowest vertex (vertex down) or over the lowest edge (edge down, about y):
        // within the strip where the layers overlap, not at the face's centre 2 mm away.
        Vector3d low(0, 0, std::numeric_limits<double>::infinity());
        for (const Tri &t : a)
          for (const Vector3d &v : t.v)
            if (v.z() < low.z())
              low = v;
        EXPECT_NEAR(points[0].point.x(), low.x(), 0.5 * kLayer);
        if (r == 2) {
          EXPECT_NEAR(points[0].point.y(), low.y(), 0.5 * kLayer);
        }
        EXPECT_NEAR(points[0].point.z(), 0.5 * gap, 0.1 * kLayer);
      }
}

// Step 5b recomputes the exact triangle distance only of the polygon members that could be the
// deepest (ReductionParams::distance_tolerance): with the hybrid's certified tolerance the
// result is bitwise the one that recomputes every member. Faces flat and tilted by up to 8
// degrees (several polygon members of different depth), meshed 2 to 32 triangles per face,
// on planes of 2 and 512 triangles, yawed.
TEST(ContactReductionPoint, SkippingMembersThatCannotBeDeepestChangesNothing) {
  const Vector3d xy(0.13e-3, -0.27e-3, 0);
  int compared = 0, with_polygons = 0;
  for (const double tilt : {0.0, 0.002, 0.03, 0.14})
    for (const double yaw_angle : {0.0, 0.7})
      for (const int k : {1, 4})
        for (const int plane_k : {1, 16}) {
          const Matrix3d R = (Eigen::AngleAxisd(yaw_angle, Vector3d::UnitZ()) *
                              Eigen::AngleAxisd(tilt, Vector3d(1, 0.4, 0).normalized()))
                                 .toRotationMatrix();
          Mesh a;
          place_cube(a, k, xy, 0.3 * kLayer, R);
          const Mesh b = plane(1.5 * kSide, plane_k);
          const auto raw = contacts_by(2, a, b);
          tri::ReductionParams every = params_for(kSide / k, 3 * kSide / plane_k);
          tri::ReductionParams pruned = every;
          tri::ContactOptions opt; // the hybrid kernel contacts_by(2) ran with
          pruned.distance_tolerance = tri::certified_tolerance(opt, kEps, kEps);
          ASSERT_TRUE(std::isinf(every.distance_tolerance)); // the default recomputes all
          ASSERT_GT(pruned.distance_tolerance, 0.0);
          const auto want = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, every);
          const auto got = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps, pruned);
          ASSERT_EQ(got.size(), want.size());
          for (std::size_t c = 0; c < got.size(); ++c) {
            for (int i = 0; i < 3; ++i) {
              EXPECT_EQ(got[c].point[i], want[c].point[i]);
              EXPECT_EQ(got[c].normal[i], want[c].normal[i]);
            }
            EXPECT_EQ(got[c].overlap, want[c].overlap);
            EXPECT_EQ(got[c].energy_overlap, want[c].energy_overlap);
            EXPECT_EQ(got[c].face_weight, want[c].face_weight);
            EXPECT_EQ(got[c].patch_mean_radius, want[c].patch_mean_radius);
            ++compared;
            with_polygons += want[c].patch_area > 0.0;
          }
        }
  EXPECT_GE(compared, 32);
  EXPECT_GE(with_polygons, 24); // the path under test: face contacts with polygons
}

// Step 6: the patch of a face contact is the faces' overlap region for every meshing -- the
// overhanging cube's rectangle [x0, x1] x [y0, y1]: area wx wy, and about the contact point
// (its centre) integral x^2 dA = wy wx^3 / 12, y^2: wx wy^3 / 12, xy: 0, nothing along z --
// even though each member polygon's centroid is elsewhere (parallel-axis theorem).
TEST(ContactReductionPoint, PatchAreaAndSecondMomentAreTheOverlapsForEveryMeshing) {
  const double half_plane = 0.75 * kSide, gap = 0.3 * kLayer, h = 0.5 * kSide;
  const Vector3d xy(half_plane - 0.2 * kSide, -half_plane + 0.35 * kSide, 0);
  const double x0 = std::max(xy.x() - h, -half_plane), x1 = std::min(xy.x() + h, half_plane);
  const double y0 = std::max(xy.y() - h, -half_plane), y1 = std::min(xy.y() + h, half_plane);
  const double wx = x1 - x0, wy = y1 - y0;
  Matrix3d want = Matrix3d::Zero();
  want(0, 0) = wy * wx * wx * wx / 12;
  want(1, 1) = wx * wy * wy * wy / 12;
  const double scale = std::pow(kSide, 4);
  // Mean distance of the wx x wy rectangle from its centre, closed form (four corner
  // rectangles: integral over [0, X] x [0, Y] of |x| dA).
  auto corner = [](double X, double Y) {
    const double d = std::hypot(X, Y);
    return X * Y * d / 3 + (X * X * X * std::log((Y + d) / X) + Y * Y * Y * std::log((X + d) / Y)) / 6;
  };
  const double want_radius = 4 * corner(0.5 * wx, 0.5 * wy) / (wx * wy);
  double worst = 0.0;
  for (const int plane_k : {1, 16})
    for (const int k : {1, 2, 4, 8})
      for (int source = 0; source < 3; source += 2) {
        Mesh a;
        place_cube(a, k, xy, gap, Matrix3d::Identity());
        const Mesh b = plane(half_plane, plane_k);
        const auto raw = contacts_by(source, a, b);
        const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                                 params_for(kSide / k, 2 * half_plane / plane_k));
        ASSERT_EQ(points.size(), 1u);
        EXPECT_NEAR(points[0].patch_area, wx * wy, 1e-9 * wx * wy)
            << "tri/face " << 2 * k * k << " plane " << plane_k << " source " << source;
        // The hybrid kernel's normal is exact to its tolerance, not to rounding: the projection
        // onto its contact plane leaves J's z entries at that level.
        const double err = (points[0].patch_second_moment - want).norm();
        worst = std::max(worst, err / scale);
        EXPECT_LE(err, (source == 2 ? 1e-6 : 1e-9) * scale) << "tri/face " << 2 * k * k << " plane " << plane_k
                                     << " source " << source << "\n"
                                     << points[0].patch_second_moment;
        // The twisting lever: the rectangle's mean distance from its centre (the point), and a
        // face lying flat has face weight 1.
        EXPECT_NEAR(points[0].patch_mean_radius, want_radius, 1e-9 * kSide)
            << "tri/face " << 2 * k * k << " plane " << plane_k << " source " << source;
        EXPECT_NEAR(points[0].face_weight, 1.0, 1e-9);
      }
  std::printf("overhanging cube: largest error of the patch's second moment %.1e side^4\n", worst);
}

// A flat face that is turned about z keeps the rotated tensor (isotropic for a square: the
// same); tilted beyond kParallelFaceAngle (edge or vertex down) the contact is point-like: no
// patch, no couple.
TEST(ContactReductionPoint, EdgeOrVertexContactHasNoPatch) {
  const double gap = 0.4 * kLayer;
  const Vector3d xy(0.2e-3, 0.1e-3, 0);
  const Matrix3d rotations[] = {
      Eigen::AngleAxisd(0.5, Vector3d::UnitY()).toRotationMatrix(),
      Eigen::AngleAxisd(0.2, Vector3d::UnitY()).toRotationMatrix(),
      (Eigen::AngleAxisd(0.6, Vector3d::UnitX()) * Eigen::AngleAxisd(0.4, Vector3d::UnitY()))
          .toRotationMatrix()};
  for (const Matrix3d &R : rotations)
    for (const int k : {1, 4}) {
      Mesh a;
      place_cube(a, k, xy, gap, R);
      const Mesh b = plane(1.5 * kSide, 16);
      const auto raw = contacts_by(2, a, b);
      const auto points = tri::reduce_contacts(raw, soa_of(a), kEps, soa_of(b), kEps,
                                               params_for(kSide / k, 3 * kSide / 16));
      ASSERT_EQ(points.size(), 1u);
      EXPECT_EQ(points[0].patch_area, 0.0);
      EXPECT_EQ(points[0].patch_second_moment, Matrix3d::Zero());
      EXPECT_EQ(points[0].patch_mean_radius, 0.0);
      EXPECT_EQ(points[0].face_weight, 0.0); // free to twist
    }
  Mesh a;
  place_cube(a, 2, xy, gap, yaw(0.3));
  const Mesh b = plane(1.5 * kSide, 16);
  const auto points = tri::reduce_contacts(contacts_by(2, a, b), soa_of(a), kEps, soa_of(b), kEps,
                                           params_for(kSide / 2, 3 * kSide / 16));
  ASSERT_EQ(points.size(), 1u);
  const double s4 = std::pow(kSide, 4);
  EXPECT_NEAR(points[0].patch_area, kSide * kSide, 1e-9 * kSide * kSide);
  Matrix3d want = Matrix3d::Zero();
  want(0, 0) = want(1, 1) = s4 / 12;
  EXPECT_LE((points[0].patch_second_moment - want).norm(), 1e-6 * s4); // hybrid normal
}

// ContactPoint::point_is_material: a point at one place that goes with the bodies (a vertex
// down; a face tilted by 2 degrees about a diagonal, whose one deepest corner pushes: a patch,
// the deepest pair's law) against a point that slides (an edge down, at a clear angle or lying
// within the polygons' 10 degrees, and a face lying flat, whose point is its centre of pressure).
TEST(ContactReductionPoint, OnlyAPointAtOnePlaceGoesWithTheMaterial) {
  const double gap = 0.4 * kLayer;
  const Vector3d xy(0.2e-3, 0.1e-3, 0);
  const Vector3d diagonal = Vector3d(1, 1, 0).normalized();
  struct Case {
    const char *what;
    Matrix3d R;
    bool material, patch;
  };
  const Case cases[] = {
      {"vertex down",
       (Eigen::AngleAxisd(0.6, Vector3d::UnitX()) * Eigen::AngleAxisd(0.4, Vector3d::UnitY()))
           .toRotationMatrix(),
       true, false},
      {"face tilted about a diagonal", Eigen::AngleAxisd(0.035, diagonal).toRotationMatrix(), true,
       true},
      {"edge down, 29 degrees", Eigen::AngleAxisd(0.5, Vector3d::UnitY()).toRotationMatrix(), false,
       false},
      {"edge down, 2 degrees", Eigen::AngleAxisd(0.035, Vector3d::UnitY()).toRotationMatrix(),
       false, true},
      {"face lying flat", yaw(0.3), false, true}};
  for (const Case &c : cases)
    for (const int k : {1, 4}) {
      Mesh a;
      place_cube(a, k, xy, gap, c.R);
      const Mesh b = plane(1.5 * kSide, 16);
      const auto points = tri::reduce_contacts(contacts_by(2, a, b), soa_of(a), kEps, soa_of(b),
                                               kEps, params_for(kSide / k, 3 * kSide / 16));
      ASSERT_EQ(points.size(), 1u) << c.what;
      EXPECT_EQ(points[0].point_is_material, c.material) << c.what << ", k " << k;
      EXPECT_EQ(points[0].patch_area > 0.0, c.patch) << c.what << ", k " << k;
    }
}

// A contact naming a triangle that the meshes do not have is a caller error, said as such.
TEST(ContactReduction, TriangleIndexOutOfRangeThrows) {
  EXPECT_THROW(
      reduce_crossed({hand_contact(3, 0, Vector3d::Zero(), Vector3d::UnitZ(), kEps, false)}, 3, 1,
                     params_for(1e-3, 1e-3)),
      std::out_of_range);
}

} // namespace

// Step 6's face weight: a face on a face is a face however it is pressed (the cube tilted so
// little that the whole face still overlaps, but unevenly beyond the flat band: the energy
// blend beta is 0 there, the face weight 1; see SlightlyTiltedFaceSlidesFromTheAreaCentreToTheLowEdge),
// falls smoothly between 5 and 10 degrees of tilt, and a ball on near-flat facets (a soft
// contact over many facets whose slopes turn under it) is a point: free to roll and to twist.
TEST(ContactReductionPoint, FaceWeightIsOneForAFaceOnAFaceAndZeroForABall) {
  const Vector3d xy(0.1e-3, -0.2e-3, 0);
  const Mesh b = plane(1.5 * kSide, 4);
  for (const double degrees : {6.0, 7.5, 9.0}) {
    Mesh a;
    place_cube(a, 2, xy, 0.2 * kLayer,
               Eigen::AngleAxisd(degrees * M_PI / 180.0, Vector3d::UnitY()).toRotationMatrix());
    const auto points = tri::reduce_contacts(contacts_by(2, a, b), soa_of(a), kEps, soa_of(b),
                                             kEps, params_for(kSide / 2, 3 * kSide / 4));
    ASSERT_EQ(points.size(), 1u);
    ASSERT_GT(points[0].patch_area, 0.0) << degrees;
    // The polygons' overlap slope is about 2 tan(tilt / 2) everywhere (measured on their
    // bisector plane): the weight is the smooth step in it from 2 tan(2.5 deg) (1) to
    // 2 tan(5 deg) (0), to within 1e-2.
    const double s = (std::tan(0.5 * degrees * M_PI / 180.0) - std::tan(2.5 * M_PI / 180.0)) /
                     (std::tan(5.0 * M_PI / 180.0) - std::tan(2.5 * M_PI / 180.0));
    const double want = 1.0 - s * s * (3.0 - 2.0 * s);
    EXPECT_NEAR(points[0].face_weight, want, 1e-2) << degrees << " degrees";
    EXPECT_GT(points[0].face_weight, 0.0);
    EXPECT_LT(points[0].face_weight, 1.0);
  }
  // A 1280-triangle ball of radius 2 mm, 50 um deep in the layers: patch of about 0.45 mm
  // radius, its facets' slopes spread by about 0.1.
  const double radius = 0.002;
  const tri::TriangleMesh ico = tri_test::icosphere(3);
  Mesh ball;
  double low = std::numeric_limits<double>::infinity();
  for (const auto &t : ico.triangles) {
    Tri tr;
    for (int k = 0; k < 3; ++k) {
      tr.v[k] = radius * ico.vertices[t[k]];
      low = std::min(low, tr.v[k].z());
    }
    ball.push_back(tr);
  }
  for (Tri &t : ball)
    for (Vector3d &v : t.v)
      v += Vector3d(xy.x(), xy.y(), kLayer - 5e-5 - low);
  const double edge = 0.131 * radius;
  const auto points = tri::reduce_contacts(contacts_by(2, ball, b), soa_of(ball), kEps, soa_of(b),
                                           kEps, params_for(edge / std::sqrt(2.0), 3 * kSide / 4));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_GT(points[0].patch_area, 0.0); // near-flat facets have polygons ...
  EXPECT_EQ(points[0].face_weight, 0.0); // ... but the ball is not a face
}
