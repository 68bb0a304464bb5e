// validate_mesh: each kind of broken mesh gives its own message naming the problem and where.
#include "body/mesh_validation.h"
#include "test_meshes.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace {

using tri_test::box;
using tri_test::tetrahedron;

// The message of the ShapeError validate_mesh throws, or "" if it passes.
std::string problem(const tri::TriangleMesh &m) {
  return tri_test::shape_error_message([&] { tri::validate_mesh(m); });
}

// Readable failure: prints the whole message when the expected phrase is missing.
::testing::AssertionResult Contains(const std::string &message, const std::string &phrase) {
  if (message.find(phrase) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "message \"" << message << "\" lacks \"" << phrase << "\"";
}

TEST(MeshValidation, ValidMeshesPass) {
  EXPECT_EQ(problem(box()), "");
  EXPECT_EQ(problem(box(3e-6, 2e-6, 1e-6)), ""); // tolerances are relative: micrometres pass
  EXPECT_EQ(problem(box(3e3, 2e3, 1e3)), "");
  EXPECT_EQ(problem(tetrahedron()), "");
}

TEST(MeshValidation, TooFewTriangles) {
  tri::TriangleMesh m = tetrahedron();
  m.triangles.pop_back();
  EXPECT_TRUE(Contains(problem(m), "mesh has 3 triangles; a closed surface needs at least 4"));
  EXPECT_TRUE(Contains(problem(tri::TriangleMesh{}), "mesh has 0 triangles"));
}

TEST(MeshValidation, IndexOutOfRange) {
  tri::TriangleMesh m = box();
  m.triangles[5][1] = 8;
  EXPECT_TRUE(Contains(problem(m), "triangle 5 refers to vertex 8, but the mesh has 8 vertices"));
  m.triangles[5][1] = -1;
  EXPECT_TRUE(Contains(problem(m), "triangle 5 refers to vertex -1"));
}

TEST(MeshValidation, OpenMesh) {
  tri::TriangleMesh m = box();
  m.triangles.erase(m.triangles.begin() + 7); // {2, 7, 3}: edges (2,7), (3,7), (2,3) open
  const std::string msg = problem(m);
  EXPECT_TRUE(Contains(msg, "mesh is not closed"));
  EXPECT_TRUE(Contains(msg, "edge (2, 3) of triangle 7 belongs to no other triangle"));
}

TEST(MeshValidation, NonManifoldEdge) {
  // Two tetrahedra glued along one edge only: edge (0, 1) has four triangles.
  tri::TriangleMesh m = tetrahedron();
  m.vertices.emplace_back(0, -1, 0);
  m.vertices.emplace_back(0, 0, -1);
  for (int t = 0; t < 4; ++t) {
    std::array<int, 3> tr = m.triangles[t];
    for (int &v : tr)
      v = v == 2 ? 4 : v == 3 ? 5 : v;
    m.triangles.push_back({tr[0], tr[2], tr[1]}); // mirrored: flip the winding
  }
  const std::string msg = problem(m);
  EXPECT_TRUE(Contains(msg, "non-manifold"));
  EXPECT_TRUE(Contains(msg, "edge (0, 1) is shared by 4 triangles (0, 1, 4, 5)"));
}

TEST(MeshValidation, OneFlippedTriangleIsNamed) {
  tri::TriangleMesh m = box();
  std::swap(m.triangles[9][1], m.triangles[9][2]);
  const std::string msg = problem(m);
  EXPECT_TRUE(Contains(
      msg, "mesh is inconsistently oriented: 1 triangle is flipped relative to its neighbours"));
  EXPECT_TRUE(Contains(msg, "(triangle 9)"));
}

TEST(MeshValidation, AllFlippedIsInverted) {
  tri::TriangleMesh m = box(3, 2, 1);
  for (auto &t : m.triangles)
    std::swap(t[1], t[2]);
  const std::string msg = problem(m);
  EXPECT_TRUE(Contains(msg, "mesh is inverted (inside out): signed volume -6 is negative"));
}

TEST(MeshValidation, ZeroAreaTriangle) {
  // Tetrahedron with vertex 4 at the middle of edge (0, 1): face (0, 1, 2) is split in two at
  // vertex 4 and the zero-area sliver (1, 0, 4) closes the gap; the mesh is otherwise valid.
  tri::TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0, 0}};
  m.triangles = {{0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 2, 4}, {4, 2, 1}, {1, 0, 4}};
  // Sanity: the same mesh with vertex 4 lifted off the edge is valid.
  tri::TriangleMesh lifted = m;
  lifted.vertices[4] = {0.5, -0.1, 0};
  ASSERT_EQ(problem(lifted), "");
  const std::string msg = problem(m);
  EXPECT_TRUE(Contains(msg, "triangle 5 is degenerate: zero or near-zero area"));
  // Near-zero relative to the mesh size is degenerate too; small but real is not.
  m.vertices[4] = {0.5, -1e-12, 0};
  EXPECT_TRUE(Contains(problem(m), "triangle 5 is degenerate"));
  m.vertices[4] = {0.5, -1e-6, 0};
  EXPECT_EQ(problem(m), "");
}

TEST(MeshValidation, RepeatedVertexInATriangle) {
  tri::TriangleMesh m = box();
  m.triangles[3] = {1, 7, 1};
  EXPECT_TRUE(Contains(problem(m), "triangle 3 is degenerate: it uses a vertex twice (1, 7, 1)"));
}

TEST(MeshValidation, NonFiniteCoordinate) {
  tri::TriangleMesh m = box();
  m.vertices[6].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(Contains(problem(m), "vertex 6 has a non-finite coordinate (0, nan, 1)"));
  m.vertices[6].y() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(Contains(problem(m), "vertex 6 has a non-finite coordinate (0, inf, 1)"));
}

// Coordinates that are finite but whose cube is not (a file in micrometres given `scale 1e300`):
// the volume is inf or NaN, and the message says so instead of printing "near-zero volume nan".
TEST(MeshValidation, MeshTooLargeToMeasure) {
  EXPECT_TRUE(Contains(problem(box(1e120, 1e120, 1e120)), "mesh is too large to measure"));
  EXPECT_EQ(problem(box(1e90, 1e90, 1e90)), "");
}

TEST(MeshValidation, TwoPieces) {
  tri::TriangleMesh m = box();
  const tri::TriangleMesh other = box();
  for (const auto &v : other.vertices)
    m.vertices.push_back(v + Eigen::Vector3d(3, 0, 0));
  for (auto t : other.triangles)
    m.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  EXPECT_TRUE(Contains(problem(m), "mesh is not one connected piece: it has 2 pieces"));
}

TEST(MeshValidation, FlatClosedMesh) {
  // A "tetrahedron" whose four corners are coplanar: closed, oriented, zero volume.
  tri::TriangleMesh m = tetrahedron();
  m.vertices[3] = {1, 1, 0};
  EXPECT_TRUE(Contains(problem(m), "mesh encloses zero or near-zero volume"));
}

} // namespace
