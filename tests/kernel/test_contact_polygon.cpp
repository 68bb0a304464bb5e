// Tests of contact_polygon.h: overlap polygons of parallel triangles with known areas and
// centroids, the cut to the soft layer, agreement with quadrature on random nearly parallel
// pairs, the 10-degree threshold at 0.99 and 1.01 of it, independence of vertex order and of
// the roles of a and b, the side of the contact normal, scales 1e-6 to 1e3, degenerate input.
#include "contact/contact_polygon.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace {

using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

struct Tri {
  Vector3d v[3];
};

bool patch(const Tri &a, const Tri &b, const Vector3d &normal, double layer,
           tri::ContactPolygon &p) {
  return tri::contact_polygon(a.v[0], a.v[1], a.v[2], b.v[0], b.v[1], b.v[2], normal, layer, p);
}

Vector3d centroid(const Tri &t) { return (t.v[0] + t.v[1] + t.v[2]) / 3.0; }
double area(const Tri &t) { return 0.5 * (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).norm(); }

Tri lifted(const Tri &t, double dz) {
  Tri r = t;
  for (Vector3d &v : r.v)
    v.z() += dz;
  return r;
}

Tri reversed(const Tri &t) { return {{t.v[0], t.v[2], t.v[1]}}; }

const double kLayer = 2e-4;
const Tri kBase = {{Vector3d(0, 0, 0), Vector3d(1e-3, 0, 0), Vector3d(0.3e-3, 0.8e-3, 0)}};

TEST(ContactPolygon, CongruentTrianglesGiveTheTriangleOnTheMidPlane) {
  const double g = 0.3 * kLayer;
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(kBase, reversed(lifted(kBase, g)), Vector3d::UnitZ(), kLayer, p));
  const double A = area(kBase);
  EXPECT_NEAR(p.area, A, 1e-12 * A);
  EXPECT_NEAR(p.weight, (kLayer - g) * A, 1e-12 * kLayer * A);
  EXPECT_NEAR(p.min_triangle_area, A, 1e-12 * A);
  EXPECT_LE((p.centroid - (centroid(kBase) + Vector3d(0, 0, 0.5 * g))).norm(), 1e-12 * 1e-3);
}

// A triangle and its point reflection through its centroid overlap in a hexagon of 2/3 of its
// area with the same centroid.
TEST(ContactPolygon, StarOfDavidIsTwoThirdsAtTheCommonCentroid) {
  const Vector3d c = centroid(kBase);
  Tri b;
  for (int k = 0; k < 3; ++k)
    b.v[k] = 2.0 * c - kBase.v[k] + Vector3d(0, 0, 0.5 * kLayer);
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(kBase, b, Vector3d::UnitZ(), kLayer, p));
  const double A = area(kBase);
  EXPECT_NEAR(p.area, 2.0 / 3.0 * A, 1e-12 * A);
  EXPECT_NEAR(p.weight, 0.5 * kLayer * p.area, 1e-12 * kLayer * A);
  EXPECT_LE((p.centroid - (c + Vector3d(0, 0, 0.25 * kLayer))).norm(), 1e-12 * 1e-3);
}

TEST(ContactPolygon, NestedGivesTheSmallerDisjointGivesNothing) {
  Tri small;
  const Vector3d c = centroid(kBase);
  for (int k = 0; k < 3; ++k)
    small.v[k] = c + 0.4 * (kBase.v[k] - c) + Vector3d(0, 0, 0.1 * kLayer);
  tri::ContactPolygon p;
  for (const bool small_is_a : {false, true}) {
    ASSERT_TRUE(small_is_a ? patch(small, kBase, -Vector3d::UnitZ(), kLayer, p)
                           : patch(kBase, small, Vector3d::UnitZ(), kLayer, p));
    EXPECT_NEAR(p.area, area(small), 1e-12 * area(small));
    EXPECT_NEAR(p.min_triangle_area, area(small), 1e-12 * area(small));
    EXPECT_LE((p.centroid - (centroid(small) - Vector3d(0, 0, 0.05 * kLayer))).norm(), 1e-15);
  }
  // Far apart in the plane: parallel, so `true`, but nothing overlaps.
  Tri away = small;
  for (Vector3d &v : away.v)
    v.x() += 5e-3;
  ASSERT_TRUE(patch(kBase, away, Vector3d::UnitZ(), kLayer, p));
  EXPECT_EQ(p.area, 0.0);
  EXPECT_EQ(p.weight, 0.0);
}

// Two halves of a square, one on each side (a shared edge in projection): touching only.
TEST(ContactPolygon, SharedEdgeIsTouchingOnly) {
  const Tri a = {{Vector3d(0, 0, 0), Vector3d(1e-3, 0, 0), Vector3d(1e-3, 1e-3, 0)}};
  const Tri b = {{Vector3d(0, 0, 1e-5), Vector3d(1e-3, 1e-3, 1e-5), Vector3d(0, 1e-3, 1e-5)}};
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(a, b, Vector3d::UnitZ(), kLayer, p));
  EXPECT_LE(p.area, tri::kPatchAreaRounding * p.min_triangle_area);
}

// a sinks and b rises along x by the same slope (so the mean normal is z): the gap g0 + 2 t x
// leaves the layer at x* = (layer - g0) / (2 t), and only the part of the (congruent)
// triangles with x < x* counts, with an overlap falling linearly to zero there.
TEST(ContactPolygon, CutToTheSoftLayer) {
  const double L = 1e-3, g0 = 0.6 * kLayer, t = std::tan(0.06); // 6.9 degrees between them
  Tri a = {{Vector3d(0, 0, 0), Vector3d(L, 0, 0), Vector3d(0, L, 0)}};
  Tri b = a;
  for (Vector3d &v : a.v)
    v.z() = -t * v.x();
  for (Vector3d &v : b.v)
    v.z() = g0 + t * v.x();
  // The overlap is measured perpendicular to either triangle: the gap along z times
  // cos(phi / 2) = 1 / sqrt(1 + t^2).
  const double c = 1.0 / std::sqrt(1.0 + t * t), sl = 2 * t * c;
  const double xs = (kLayer - c * g0) / sl;
  ASSERT_LT(xs, 0.9 * L);
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(a, b, Vector3d::UnitZ(), kLayer, p));
  const double expected = 0.5 * L * L - 0.5 * (L - xs) * (L - xs);
  EXPECT_NEAR(p.area, expected, 1e-12 * expected);
  // Overlap o0 - sl x on the strip x in [0, x*] of height L - x.
  const double o0 = kLayer - c * g0;
  auto F = [&](double x) { // antiderivatives of (o0 - sl x)(L - x) and of that times x
    return o0 * L * x - 0.5 * (o0 + sl * L) * x * x + sl * x * x * x / 3.0;
  };
  auto G = [&](double x) {
    return 0.5 * o0 * L * x * x - (o0 + sl * L) * x * x * x / 3.0 + 0.25 * sl * x * x * x * x;
  };
  const double W = F(xs) - F(0);
  EXPECT_NEAR(p.weight, W, 1e-12 * W);
  const double xc = (G(xs) - G(0)) / W;
  EXPECT_NEAR(p.centroid.x(), xc, 1e-12 * L);
  EXPECT_NEAR(p.centroid.z(), 0.5 * g0, 1e-12 * L); // mid-surface: (-t x + g0 + t x) / 2
}

// Random nearly parallel pairs (tilts up to 8 degrees, gaps across the layer, the layer cut
// biting often) against midpoint quadrature on a fine grid in the projection plane.
TEST(ContactPolygon, AgreesWithQuadrature) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int cut = 0, compared = 0;
  double worst_area = 0, worst_weight = 0, worst_centroid = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Matrix3d R =
        Eigen::AngleAxisd(3.0 * u(rng), Vector3d(u(rng), u(rng), u(rng)).normalized())
            .toRotationMatrix();
    const Matrix3d tilt =
        Eigen::AngleAxisd(0.14 * std::abs(u(rng)), Vector3d(u(rng), u(rng), 0).normalized())
            .toRotationMatrix();
    Tri a, b;
    for (int k = 0; k < 3; ++k) {
      a.v[k] = Vector3d(1e-3 * u(rng), 1e-3 * u(rng), 0);
      b.v[k] = a.v[k] + Vector3d(0.4e-3 * u(rng), 0.4e-3 * u(rng), 0);
    }
    const Vector3d centre_b(0, 0, kLayer * (0.2 + 0.6 * std::abs(u(rng))));
    for (int k = 0; k < 3; ++k)
      b.v[k] = centre_b + tilt * b.v[k];
    const Vector3d shift(0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng));
    for (int k = 0; k < 3; ++k) {
      a.v[k] = shift + R * a.v[k];
      b.v[k] = shift + R * b.v[k];
    }
    const Vector3d normal = R * Vector3d::UnitZ();
    tri::ContactPolygon p;
    ASSERT_TRUE(patch(a, b, normal, kLayer, p));
    // Quadrature with the same definition: along m, over the plane orthogonal to it.
    const Vector3d na = (a.v[1] - a.v[0]).cross(a.v[2] - a.v[0]).normalized();
    Vector3d nb = (b.v[1] - b.v[0]).cross(b.v[2] - b.v[0]).normalized();
    if (na.dot(nb) < 0)
      nb = -nb;
    Vector3d m = (na + nb).normalized();
    if (m.dot(normal) < 0)
      m = -m;
    const Vector3d e1 = m.unitOrthogonal(), e2 = m.cross(e1);
    auto to2 = [&](const Vector3d &x) {
      return Vector2d((x - shift).dot(e1), (x - shift).dot(e2));
    };
    auto inside = [&](const Tri &t, const Vector2d &x) {
      double s[3];
      for (int k = 0; k < 3; ++k) {
        const Vector2d p0 = to2(t.v[k]), p1 = to2(t.v[(k + 1) % 3]);
        const Vector2d d = p1 - p0, r = x - p0;
        s[k] = d.x() * r.y() - d.y() * r.x();
      }
      return (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
    };
    auto height = [&](const Tri &t, const Vector3d &n, const Vector2d &x) {
      const Vector3d q = shift + x.x() * e1 + x.y() * e2;
      return n.dot(t.v[0] - q) / n.dot(m);
    };
    const int N = 1200;
    const double h = 3.2e-3 / N;
    double A = 0, W = 0;
    Vector3d M = Vector3d::Zero();
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const Vector2d xl(-1.6e-3 + (i + 0.5) * h, -1.6e-3 + (j + 0.5) * h);
        if (!inside(a, xl) || !inside(b, xl))
          continue;
        const double ha = height(a, na, xl), hb = height(b, nb, xl),
                     o = kLayer - (hb - ha) * std::abs(m.dot(na));
        if (o < 0)
          continue;
        A += h * h;
        W += o * h * h;
        M += o * h * h * (shift + xl.x() * e1 + xl.y() * e2 + 0.5 * (ha + hb) * m);
      }
    if (A < 2500 * h * h) { // under 50 x 50 grid cells: too small for the grid to resolve
      EXPECT_LE(p.area, 5000 * h * h);
      continue;
    }
    ++compared;
    worst_area = std::max(worst_area, std::abs(p.area - A) / A);
    worst_weight = std::max(worst_weight, std::abs(p.weight - W) / W);
    worst_centroid = std::max(worst_centroid, (p.centroid - M / W).norm());
    if (W < kLayer * A * 0.999)
      ++cut;
    EXPECT_NEAR(p.area, A, 5e-3 * A) << "trial " << trial;
    EXPECT_NEAR(p.weight, W, 5e-3 * W) << "trial " << trial;
    EXPECT_LE((p.centroid - M / W).norm(), 2.7e-6) << "trial " << trial;
  }
  EXPECT_GE(compared, 12);
  EXPECT_GT(cut, 0); // the layer cut was exercised
  std::printf("%d pairs compared, %d cut by the layer; largest relative error of the area %.1e, "
              "of the weight %.1e; largest centroid error %.1e m (grid cell %.1e m)\n",
              compared, cut, worst_area, worst_weight, worst_centroid, 3.2e-3 / 1200);
}

TEST(ContactPolygon, ParallelMeansWithinTenDegrees) {
  for (const double f : {0.99, 1.01}) {
    const Matrix3d R =
        Eigen::AngleAxisd(f * tri::kParallelFaceAngle, Vector3d(1, 2, 0).normalized())
            .toRotationMatrix();
    Tri b;
    const Vector3d c = centroid(kBase);
    for (int k = 0; k < 3; ++k)
      b.v[k] = c + R * (kBase.v[k] - c) + Vector3d(0, 0, 0.5 * kLayer);
    tri::ContactPolygon p;
    EXPECT_EQ(patch(kBase, b, Vector3d::UnitZ(), kLayer, p), f < 1.0);
    if (f > 1.0) {
      EXPECT_EQ(p.area, 0.0);
      EXPECT_EQ(p.weight, 0.0);
    }
  }
}

// Vertex order (either orientation, any start) and the roles of a and b (with the normal
// reversed) change the result by rounding only.
TEST(ContactPolygon, IndependentOfVertexOrderAndRoles) {
  const Matrix3d R = Eigen::AngleAxisd(0.05, Vector3d(0.3, -1, 0).normalized()).toRotationMatrix();
  Tri b;
  for (int k = 0; k < 3; ++k)
    b.v[k] = R * (Vector3d(0.6e-3, 0.5e-3, 0) - kBase.v[k]) + Vector3d(0, 0, 0.4 * kLayer);
  tri::ContactPolygon ref;
  ASSERT_TRUE(patch(kBase, b, Vector3d::UnitZ(), kLayer, ref));
  ASSERT_GT(ref.area, 0.05 * area(kBase));
  auto same = [&](const tri::ContactPolygon &p, const char *what) {
    EXPECT_NEAR(p.area, ref.area, 1e-11 * ref.area) << what;
    EXPECT_NEAR(p.weight, ref.weight, 1e-11 * ref.weight) << what;
    EXPECT_LE((p.centroid - ref.centroid).norm(), 1e-11 * 1e-3) << what;
  };
  tri::ContactPolygon p;
  for (int start = 0; start < 3; ++start) {
    const Tri ra = {{kBase.v[start], kBase.v[(start + 1) % 3], kBase.v[(start + 2) % 3]}};
    const Tri rb = {{b.v[(start + 2) % 3], b.v[start], b.v[(start + 1) % 3]}};
    ASSERT_TRUE(patch(ra, reversed(rb), Vector3d::UnitZ(), kLayer, p));
    same(p, "vertex order");
    ASSERT_TRUE(patch(reversed(ra), rb, Vector3d::UnitZ(), kLayer, p));
    same(p, "orientation");
  }
  ASSERT_TRUE(patch(b, kBase, -Vector3d::UnitZ(), kLayer, p));
  same(p, "roles swapped");
}

// The contact normal says which side b is on: b behind a (a face sunk through the other, as
// the reduction flips it) gives overlap layer + gap, not layer - gap.
TEST(ContactPolygon, NormalSideSetsTheSignOfTheGap) {
  const double g = 0.3 * kLayer;
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(kBase, lifted(kBase, g), -Vector3d::UnitZ(), kLayer, p));
  EXPECT_NEAR(p.weight, (kLayer + g) * area(kBase), 1e-12 * kLayer * area(kBase));
}

TEST(ContactPolygon, ScaleAndPositionFree) {
  const Matrix3d R = Eigen::AngleAxisd(0.05, Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  Tri b0;
  const Vector3d c = centroid(kBase);
  for (int k = 0; k < 3; ++k)
    b0.v[k] = c + R * (0.7 * (c - kBase.v[k])) + Vector3d(0, 0, 0.3 * kLayer);
  tri::ContactPolygon ref;
  ASSERT_TRUE(patch(kBase, b0, Vector3d::UnitZ(), kLayer, ref));
  for (const double s : {1e-6, 1e-3, 1.0, 1e3})
    for (const double far : {0.0, 1e3}) { // far: moved 1000 sizes away from the origin
      const Vector3d offset = Vector3d(far, -far, 0.5 * far) * s * 1e-3;
      Tri a, b;
      for (int k = 0; k < 3; ++k) {
        a.v[k] = s * kBase.v[k] + offset;
        b.v[k] = s * b0.v[k] + offset;
      }
      tri::ContactPolygon p;
      ASSERT_TRUE(patch(a, b, Vector3d::UnitZ(), s * kLayer, p));
      const double tol = far > 0 ? 1e-9 : 1e-12;
      EXPECT_NEAR(p.area, s * s * ref.area, tol * s * s * ref.area) << s << " " << far;
      EXPECT_NEAR(p.weight, s * s * s * ref.weight, tol * s * s * s * ref.weight);
      EXPECT_LE((p.centroid - offset - s * ref.centroid).norm(), tol * s * 1e-3);
    }
}

TEST(ContactPolygon, DegenerateTriangleIsRejected) {
  const Tri line = {{Vector3d(0, 0, 1e-5), Vector3d(1e-3, 0, 1e-5), Vector3d(2e-3, 0, 1e-5)}};
  const Tri point = {{Vector3d(0, 0, 1e-5), Vector3d(0, 0, 1e-5), Vector3d(0, 0, 1e-5)}};
  tri::ContactPolygon p;
  EXPECT_FALSE(patch(kBase, line, Vector3d::UnitZ(), kLayer, p));
  EXPECT_FALSE(patch(point, kBase, -Vector3d::UnitZ(), kLayer, p));
  const double nan = std::nan("");
  const Tri bad = {{Vector3d(nan, 0, 0), Vector3d(1e-3, 0, 0), Vector3d(0, 1e-3, 0)}};
  EXPECT_FALSE(patch(kBase, bad, Vector3d::UnitZ(), kLayer, p));
  EXPECT_EQ(p.area, 0.0);
}

} // namespace

// ---- second moment of area (the rocking damper's patch extent) ----

namespace second_moment {

// Analytic second moment of a triangle about its centroid: A/12 sum e_i e_i^T, e_i = v_i - c
// (a closed form different from the fan-and-parallel-axis sum of the implementation).
Matrix3d triangle_moment(const Tri &t) {
  const Vector3d c = centroid(t);
  Matrix3d j = Matrix3d::Zero();
  for (const Vector3d &v : t.v)
    j += (v - c) * (v - c).transpose();
  return area(t) / 12.0 * j;
}

void expect_tensor_near(const Matrix3d &got, const Matrix3d &want, double tol, const char *what) {
  EXPECT_LE((got - want).norm(), tol) << what << "\ngot\n" << got << "\nwant\n" << want;
}

} // namespace second_moment

// The right triangle (0,0), (2L,0), (0,2L) and the right triangle (L,L), (-L,L), (L,-L) overlap
// in the square [0, L]^2: J = L^4 / 12 diag(1, 1) about its centre, polar L^4 / 6; the same
// after turning and moving the whole scene (world-frame tensor R J R^T).
TEST(ContactPolygon, SecondMomentOfASquare) {
  using second_moment::expect_tensor_near;
  const double L = 1e-3, g = 0.4 * kLayer;
  const Tri a0 = {{Vector3d(0, 0, 0), Vector3d(2 * L, 0, 0), Vector3d(0, 2 * L, 0)}};
  const Tri b0 = {{Vector3d(L, L, g), Vector3d(-L, L, g), Vector3d(L, -L, g)}};
  const Matrix3d turns[] = {
      Matrix3d::Identity(),
      Eigen::AngleAxisd(1.1, Vector3d(0.2, -0.7, 0.4).normalized()).toRotationMatrix()};
  for (const Matrix3d &R : turns)
    for (const Vector3d &shift : {Vector3d(0, 0, 0), Vector3d(0.3, -0.2, 0.1)}) {
      Tri a, b;
      for (int k = 0; k < 3; ++k) {
        a.v[k] = shift + R * a0.v[k];
        b.v[k] = shift + R * b0.v[k];
      }
      tri::ContactPolygon p;
      ASSERT_TRUE(patch(a, b, R * Vector3d::UnitZ(), kLayer, p));
      EXPECT_NEAR(p.area, L * L, 1e-12 * L * L);
      EXPECT_LE((p.area_centroid - (shift + R * Vector3d(0.5 * L, 0.5 * L, 0.5 * g))).norm(),
                1e-9 * L);
      const Matrix3d want = R * Vector3d(1, 1, 0).asDiagonal() * R.transpose() * (L * L * L * L / 12);
      expect_tensor_near(p.second_moment, want, 1e-9 * L * L * L * L, "square");
      EXPECT_NEAR(p.polar_moment(), L * L * L * L / 6, 1e-9 * L * L * L * L);
      EXPECT_LE((p.second_moment * (R * Vector3d::UnitZ())).norm(), 1e-9 * L * L * L * L);
    }
}

// Congruent triangles: the patch is the triangle. Right triangle with legs b along x and h along
// y: integral x^2 dA = h b^3 / 36, y^2: b h^3 / 36, xy: -b^2 h^2 / 72 about the centroid; and
// the general triangle kBase against the closed form A/12 sum e_i e_i^T.
TEST(ContactPolygon, SecondMomentOfATriangle) {
  using second_moment::expect_tensor_near;
  const double bx = 1e-3, hy = 0.6e-3, g = 0.3 * kLayer;
  const Tri right = {{Vector3d(0, 0, 0), Vector3d(bx, 0, 0), Vector3d(0, hy, 0)}};
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(right, reversed(lifted(right, g)), Vector3d::UnitZ(), kLayer, p));
  Matrix3d want = Matrix3d::Zero();
  want(0, 0) = hy * bx * bx * bx / 36;
  want(1, 1) = bx * hy * hy * hy / 36;
  want(0, 1) = want(1, 0) = -bx * bx * hy * hy / 72;
  const double scale = bx * bx * bx * bx;
  expect_tensor_near(p.second_moment, want, 1e-12 * scale, "right triangle");
  EXPECT_LE((p.area_centroid - Vector3d(bx / 3, hy / 3, 0.5 * g)).norm(), 1e-12 * bx);

  ASSERT_TRUE(patch(kBase, reversed(lifted(kBase, g)), Vector3d::UnitZ(), kLayer, p));
  expect_tensor_near(p.second_moment, second_moment::triangle_moment(kBase), 1e-12 * scale,
                     "kBase");
  // The hexagon of the star of David: J of the triangle minus its three corner triangles
  // (each of side 1/3), moved to the common centroid by the parallel-axis theorem.
  const Vector3d c = centroid(kBase);
  Tri star;
  for (int k = 0; k < 3; ++k)
    star.v[k] = 2.0 * c - kBase.v[k] + Vector3d(0, 0, 0.5 * kLayer);
  ASSERT_TRUE(patch(kBase, star, Vector3d::UnitZ(), kLayer, p));
  Matrix3d hexagon = second_moment::triangle_moment(kBase);
  for (int k = 0; k < 3; ++k) {
    Tri corner;
    for (int i = 0; i < 3; ++i)
      corner.v[i] = kBase.v[k] + (kBase.v[i] - kBase.v[k]) / 3.0;
    const Vector3d d = centroid(corner) - c;
    hexagon -= second_moment::triangle_moment(corner) + area(corner) * d * d.transpose();
  }
  expect_tensor_near(p.second_moment, hexagon, 1e-12 * scale, "hexagon");
}

// A small triangle nested off-centre in a large one, the scene 1000 sizes from the origin: the
// patch is the small triangle, J about ITS centroid (not the large one's, not a vertex's).
TEST(ContactPolygon, SecondMomentOfAnOffsetPatchIsAboutItsOwnCentroid) {
  using second_moment::expect_tensor_near;
  const Vector3d far(1.0, -1.0, 0.5);
  Tri big = kBase, small;
  const Vector3d at(0.55e-3, 0.15e-3, 0.2 * kLayer);
  small.v[0] = at;
  small.v[1] = at + Vector3d(0.2e-3, 0.05e-3, 0);
  small.v[2] = at + Vector3d(-0.05e-3, 0.25e-3, 0);
  for (int k = 0; k < 3; ++k) {
    big.v[k] += far;
    small.v[k] += far;
  }
  const double scale = std::pow(0.25e-3, 4);
  tri::ContactPolygon p;
  for (const bool small_is_a : {false, true}) {
    ASSERT_TRUE(small_is_a ? patch(small, big, -Vector3d::UnitZ(), kLayer, p)
                           : patch(big, small, Vector3d::UnitZ(), kLayer, p));
    EXPECT_NEAR(p.area, area(small), 1e-9 * area(small));
    expect_tensor_near(p.second_moment, second_moment::triangle_moment(small), 1e-7 * scale,
                       "offset");
    EXPECT_LE((p.area_centroid - (centroid(small) - Vector3d(0, 0, 0.1 * kLayer))).norm(),
              1e-9 * 1e-3);
  }
}

// The layer cut and tilts: random nearly parallel pairs against midpoint quadrature (as
// AgreesWithQuadrature, coarser grid), area centroid and second moment.
TEST(ContactPolygon, SecondMomentAgreesWithQuadrature) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  double worst_j = 0, worst_c = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Matrix3d R =
        Eigen::AngleAxisd(3.0 * u(rng), Vector3d(u(rng), u(rng), u(rng)).normalized())
            .toRotationMatrix();
    const Matrix3d tilt =
        Eigen::AngleAxisd(0.14 * std::abs(u(rng)), Vector3d(u(rng), u(rng), 0).normalized())
            .toRotationMatrix();
    Tri a, b;
    for (int k = 0; k < 3; ++k) {
      a.v[k] = Vector3d(1e-3 * u(rng), 1e-3 * u(rng), 0);
      b.v[k] = a.v[k] + Vector3d(0.4e-3 * u(rng), 0.4e-3 * u(rng), 0);
    }
    const Vector3d centre_b(0, 0, kLayer * (0.2 + 0.6 * std::abs(u(rng))));
    for (int k = 0; k < 3; ++k) {
      b.v[k] = centre_b + tilt * b.v[k];
      a.v[k] = R * a.v[k];
      b.v[k] = R * b.v[k];
    }
    const Vector3d normal = R * Vector3d::UnitZ();
    tri::ContactPolygon p;
    ASSERT_TRUE(patch(a, b, normal, kLayer, p));
    const Vector3d na = (a.v[1] - a.v[0]).cross(a.v[2] - a.v[0]).normalized();
    Vector3d nb = (b.v[1] - b.v[0]).cross(b.v[2] - b.v[0]).normalized();
    if (na.dot(nb) < 0)
      nb = -nb;
    Vector3d m = (na + nb).normalized();
    if (m.dot(normal) < 0)
      m = -m;
    const Vector3d e1 = m.unitOrthogonal(), e2 = m.cross(e1);
    auto to2 = [&](const Vector3d &x) { return Vector2d(x.dot(e1), x.dot(e2)); };
    auto inside = [&](const Tri &t, const Vector2d &x) {
      double s[3];
      for (int k = 0; k < 3; ++k) {
        const Vector2d p0 = to2(t.v[k]), d = to2(t.v[(k + 1) % 3]) - p0, r = x - p0;
        s[k] = d.x() * r.y() - d.y() * r.x();
      }
      return (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0);
    };
    auto height = [&](const Tri &t, const Vector3d &n, const Vector2d &x) {
      return n.dot(t.v[0] - (x.x() * e1 + x.y() * e2)) / n.dot(m);
    };
    const int N = 800;
    const double h = 3.2e-3 / N;
    double A = 0;
    Vector2d S1 = Vector2d::Zero();
    Eigen::Matrix2d S2 = Eigen::Matrix2d::Zero();
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        const Vector2d xl(-1.6e-3 + (i + 0.5) * h, -1.6e-3 + (j + 0.5) * h);
        if (!inside(a, xl) || !inside(b, xl))
          continue;
        if (kLayer - (height(b, nb, xl) - height(a, na, xl)) * std::abs(m.dot(na)) < 0)
          continue;
        A += h * h;
        S1 += h * h * xl;
        S2 += h * h * (xl * xl.transpose() + Eigen::Matrix2d::Identity() * h * h / 12);
      }
    if (A < 2500 * h * h)
      continue;
    ++compared;
    const Vector2d c = S1 / A;
    const Eigen::Matrix2d J2 = S2 - A * c * c.transpose();
    Eigen::Matrix<double, 3, 2> B;
    B << e1, e2;
    const Matrix3d J = B * J2 * B.transpose();
    const double err = (p.second_moment - J).norm() / J.trace();
    worst_j = std::max(worst_j, err);
    EXPECT_LE(err, 8e-3) << "trial " << trial;
    const double cerr = (to2(p.area_centroid) - c).norm();
    worst_c = std::max(worst_c, cerr);
    EXPECT_LE(cerr, 2 * h) << "trial " << trial;
    EXPECT_LE((p.second_moment * m).norm(), 1e-12 * J.trace());
  }
  EXPECT_GE(compared, 12);
  std::printf("%d pairs compared; largest error of J relative to its trace %.1e, of the area "
              "centroid %.1e m (grid cell %.1e m)\n",
              compared, worst_j, worst_c, 3.2e-3 / 800);
}

// ---- mean distance of a patch from a point (the twisting-friction lever) ----

namespace mean_distance {

// Integral of |x| over the rectangle [0, X] x [0, Y] (corner at the origin), closed form.
double corner_rectangle(double X, double Y) {
  const double d = std::hypot(X, Y);
  return X * Y * d / 3 + (X * X * X * std::log((Y + d) / X) + Y * Y * Y * std::log((X + d) / Y)) / 6;
}

// Integral of |x - p| over [x0, x1] x [y0, y1] for p anywhere (inside or outside): with
// F(X, Y) = the integral from 0 to X, 0 to Y (sign(X) sign(Y) corner_rectangle(|X|, |Y|)),
// F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0), coordinates relative to p.
double rectangle(double x0, double x1, double y0, double y1, const Vector2d &p) {
  auto F = [](double X, double Y) {
    if (X == 0.0 || Y == 0.0)
      return 0.0;
    return std::copysign(1.0, X) * std::copysign(1.0, Y) * corner_rectangle(std::abs(X), std::abs(Y));
  };
  x0 -= p.x(), x1 -= p.x(), y0 -= p.y(), y1 -= p.y();
  return F(x1, y1) - F(x0, y1) - F(x1, y0) + F(x0, y0);
}

} // namespace mean_distance

// A square of side s about its centre: mean distance s (sqrt 2 + asinh 1) / 6 = 0.38260 s; a
// rectangle about a point inside and one outside it (closed form by corner rectangles); the
// same after turning and moving the scene, in either orientation, projected along a tilted
// normal (the area and the distances shrink with the projection), at scales 1e-6 and 1e3.
TEST(PolygonDistanceIntegral, RectanglesByClosedForm) {
  for (const double scale : {1e-6, 1e-3, 1e3}) {
    const double s = 2.0 * scale;
    const Matrix3d R =
        Eigen::AngleAxisd(0.9, Vector3d(0.3, 0.5, -0.8).normalized()).toRotationMatrix();
    const Vector3d shift = Vector3d(0.4, -1.3, 2.2) * scale;
    const Vector2d corners[4] = {Vector2d(0, 0), Vector2d(s, 0), Vector2d(s, 0.6 * s),
                                 Vector2d(0, 0.6 * s)};
    for (const bool reverse : {false, true}) {
      Vector3d v[4];
      for (int k = 0; k < 4; ++k) {
        const Vector2d c = corners[reverse ? 3 - k : k];
        v[k] = shift + R * Vector3d(c.x(), c.y(), 0);
      }
      const Vector3d n = R * Vector3d::UnitZ();
      for (const Vector2d &p : {Vector2d(0.5 * s, 0.3 * s), Vector2d(0.2 * s, 0.1 * s),
                                Vector2d(1.7 * s, -0.4 * s), Vector2d(s, 0.3 * s)}) {
        const Vector3d p3 = shift + R * Vector3d(p.x(), p.y(), 0.7 * scale);
        const tri::DistanceIntegral r = tri::polygon_distance_integral(v, 4, p3, n);
        EXPECT_NEAR(r.area, 0.6 * s * s, 1e-12 * s * s);
        const double want = mean_distance::rectangle(0, s, 0, 0.6 * s, p);
        EXPECT_NEAR(r.distance, want, 1e-12 * s * s * s)
            << "scale " << scale << " point " << p.transpose() << " reversed " << reverse;
      }
      // Projected along a normal tilted by 0.3 rad about the rectangle's x axis: lengths along
      // y shrink by cos 0.3 (the tilt of the projection direction).
      const Vector3d tilted = R * Vector3d(0, std::sin(0.3), std::cos(0.3));
      const Vector3d centre = shift + R * Vector3d(0.5 * s, 0.3 * s, 0);
      const tri::DistanceIntegral r = tri::polygon_distance_integral(v, 4, centre, tilted);
      const double c = std::cos(0.3);
      EXPECT_NEAR(r.area, 0.6 * s * s * c, 1e-12 * s * s);
      EXPECT_NEAR(r.distance, mean_distance::rectangle(-0.5 * s, 0.5 * s, -0.3 * s * c, 0.3 * s * c,
                                                       Vector2d::Zero()),
                  1e-12 * s * s * s);
    }
    Vector3d sq[4];
    for (int k = 0; k < 4; ++k)
      sq[k] = Vector3d(k == 1 || k == 2 ? s : 0, k >= 2 ? s : 0, 0);
    const tri::DistanceIntegral r =
        tri::polygon_distance_integral(sq, 4, Vector3d(0.5 * s, 0.5 * s, 0), Vector3d::UnitZ());
    EXPECT_NEAR(r.distance / r.area, s * (std::sqrt(2.0) + std::asinh(1.0)) / 6, 1e-13 * s);
  }
  // Fewer than 3 corners: nothing.
  const Vector3d two[2] = {Vector3d::Zero(), Vector3d::UnitX()};
  EXPECT_EQ(tri::polygon_distance_integral(two, 2, Vector3d::Zero(), Vector3d::UnitZ()).area, 0.0);
}

// The polygon's corners (lifted to the mid-surface) come with the patch, and their integrals
// are the patch's: area, and the mean distance from the area centroid against quadrature over
// the nested pair's smaller triangle.
TEST(PolygonDistanceIntegral, PatchCornersCarryThePatch) {
  const Tri big = {{Vector3d(-2e-3, -2e-3, 0), Vector3d(3e-3, -2e-3, 0), Vector3d(0, 3e-3, 0)}};
  const Tri small = lifted(kBase, 0.3 * kLayer);
  tri::ContactPolygon p;
  ASSERT_TRUE(patch(big, small, Vector3d::UnitZ(), kLayer, p));
  ASSERT_GE(p.num_vertices, 3);
  for (int k = 0; k < p.num_vertices; ++k)
    EXPECT_NEAR(p.vertices[k].z(), 0.15 * kLayer, 1e-15);
  const tri::DistanceIntegral r =
      tri::polygon_distance_integral(p.vertices, p.num_vertices, p.area_centroid, Vector3d::UnitZ());
  EXPECT_NEAR(r.area, p.area, 1e-12 * p.area);
  // Quadrature over kBase: barycentric midpoints of a fine grid.
  const int N = 600;
  double sum = 0.0;
  const Vector3d c = p.area_centroid;
  for (int i = 0; i < N; ++i)
    for (int j = 0; i + j < N; ++j) {
      for (int up = 0; up < (i + j + 1 < N ? 2 : 1); ++up) {
        const double u = (i + (up ? 2.0 : 1.0) / 3.0) / N, w = (j + (up ? 2.0 : 1.0) / 3.0) / N;
        const Vector3d x = kBase.v[0] + u * (kBase.v[1] - kBase.v[0]) + w * (kBase.v[2] - kBase.v[0]);
        sum += std::hypot(x.x() - c.x(), x.y() - c.y());
      }
    }
  const double quadrature = sum * area(kBase) / (double(N) * N);
  EXPECT_NEAR(r.distance, quadrature, 1e-5 * quadrature);
}

// Step 5c of contact_reduction.h: the peak of a patch from its overlap moments. A pyramid's
// apex (a vertex of a coarse ball, tilted or not) pressed into a plane is a cone profile: the
// moments' peak is the apex's overlap, and its gradient acts at the apex.
TEST(CurvedPeak, VertexConeGivesItsApex) {
  const double layer = 2e-4;
  const Tri floor1{{Vector3d(-1, -1, 0), Vector3d(1, -1, 0), Vector3d(1, 1, 0)}};
  const Tri floor2{{Vector3d(-1, -1, 0), Vector3d(1, 1, 0), Vector3d(-1, 1, 0)}};
  for (double tilt : {0.0, 0.02, 0.04}) {
    for (int sides : {4, 5, 6}) {
      const double depth = 0.6 * layer; // apex overlap
      const Vector3d apex(1e-4, -2e-4, layer - depth);
      std::vector<Vector3d> ring;
      for (int k = 0; k < sides; ++k) {
        const double phi = 2 * M_PI * k / sides + 0.1;
        const Vector3d d(std::cos(phi), std::sin(phi), 0.0);
        const double r = 4e-3 * (1.0 + 0.2 * std::sin(3.0 * k)); // irregular, beyond o = 0
        ring.push_back(apex + r * d + Vector3d(0, 0, r * (0.1 + tilt * d.x())));
      }
      tri::OverlapMoments mo;
      for (int k = 0; k < sides; ++k) {
        const Tri facet{{apex, ring[k], ring[(k + 1) % sides]}};
        for (const Tri &f : {floor1, floor2}) {
          tri::ContactPolygon p;
          if (patch(facet, f, Vector3d(0, 0, -1), layer, p) && p.area > 0.0)
            tri::add_overlap_moments(p, layer, Vector3d(0, 0, -1), apex, mo);
        }
      }
      const tri::CurvedPeak c = tri::curved_peak(mo.area, mo.m1, mo.m2, mo.m3);
      EXPECT_NEAR(c.peak, depth, 1e-9 * depth) << sides << " " << tilt;
      EXPECT_DOUBLE_EQ(c.validity, 1.0);
      const double sum = c.a_area + c.a_pressure + c.a_second;
      EXPECT_NEAR(sum, 1.0, 1e-9);
      const Vector3d point = (c.a_area * mo.area1 / mo.area + c.a_pressure * mo.first1 / mo.m1 +
                              c.a_second * mo.second1 / mo.m2) /
                             sum;
      EXPECT_NEAR((point - Vector3d(0, 0, point.z())).norm(), 0.0, 1e-9 * 4e-3) << sides << " " << tilt;
    }
  }
}
