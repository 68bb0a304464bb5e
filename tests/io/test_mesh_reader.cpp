// read_mesh_file: the same shape written as ASCII STL, binary STL, OBJ and PLY (by the tiny
// writers below, at run time, into a temporary directory) reads back with the same mass
// properties; broken files give a MeshFileError that starts with the path and says what.
#include "../kernel/test_meshes.h"
#include "mesh_reader.h"
#include "shape.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using tri_test::box;

// Octahedron subdivided `level` times onto a sphere of radius r: a many-triangle test shape
// whose coordinates are not representable exactly in float (as in real files).
tri::TriangleMesh sphere(int level, double r) {
  tri::TriangleMesh m = tri_test::octasphere(level);
  for (auto &v : m.vertices)
    v = r * v + Eigen::Vector3d(0.01, -0.02, 0.03);
  return m;
}

// --- tiny writers: just enough of each format -------------------------------------------

void write_ascii_stl(const fs::path &path, const tri::TriangleMesh &m) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid test\n";
  for (int t = 0; t < m.num_triangles(); ++t) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d &p = m.corner(t, k);
      out << "      vertex " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
}

void put_u32(std::ofstream &out, std::uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16),
                              static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char *>(b), 4);
}
void put_f32(std::ofstream &out, double v) { // little-endian IEEE float, as STL requires
  const float f = static_cast<float>(v);
  std::uint32_t u;
  std::memcpy(&u, &f, 4);
  put_u32(out, u);
}

void write_binary_stl(const fs::path &path, const tri::TriangleMesh &m,
                      const std::string &header = "binary test") {
  std::ofstream out(path, std::ios::binary);
  std::string h = header;
  h.resize(80, ' ');
  out.write(h.data(), 80);
  put_u32(out, static_cast<std::uint32_t>(m.num_triangles()));
  for (int t = 0; t < m.num_triangles(); ++t) {
    for (int i = 0; i < 3; ++i)
      put_f32(out, 0.0); // normal: readers recompute it
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        put_f32(out, m.corner(t, k)[i]);
    out.write("\0\0", 2); // attribute byte count
  }
}

void write_obj(const fs::path &path, const tri::TriangleMesh &m) {
  std::ofstream out(path);
  out.precision(17);
  out << "# test\no shape\n";
  for (const auto &v : m.vertices)
    out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto &t : m.triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void write_ascii_ply(const fs::path &path, const tri::TriangleMesh &m) {
  std::ofstream out(path);
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << m.num_vertices()
      << "\nproperty double x\nproperty double y\nproperty double z\nelement face "
      << m.num_triangles() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto &v : m.vertices)
    out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto &t : m.triangles)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_binary_ply(const fs::path &path, const tri::TriangleMesh &m) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment test\nelement vertex " << m.num_vertices()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "element face " << m.num_triangles()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto &v : m.vertices)
    for (int i = 0; i < 3; ++i)
      put_f32(out, v[i]);
  for (const auto &t : m.triangles) {
    out.put(3);
    for (int v : t)
      put_u32(out, static_cast<std::uint32_t>(v));
  }
}

void write_text(const fs::path &path, const std::string &text) { std::ofstream(path) << text; }

void truncate_to(const fs::path &path, std::uintmax_t size) { fs::resize_file(path, size); }

::testing::AssertionResult StartsWithPathAndSays(const std::string &message, const fs::path &path,
                                                 const std::string &phrase) {
  if (message.rfind(path.string() + ": ", 0) == 0 && message.find(phrase) != std::string::npos)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "message \"" << message << "\" should start with \""
                                       << path.string() << ": \" and contain \"" << phrase << "\"";
}

class MeshReader : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("tri_mesh_reader_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string &name) const { return dir_ / name; }

  // Writes `text` to file `name`, reads it, and checks the error as StartsWithPathAndSays.
  ::testing::AssertionResult TextFileFailsWith(const std::string &name, const std::string &text,
                                               const std::string &phrase) const {
    const fs::path path = file(name);
    write_text(path, text);
    return StartsWithPathAndSays(read_error(path), path, phrase);
  }

  // The MeshFileError message for reading `path` ("" if it reads), with a check that VTK
  // printed nothing.
  static std::string read_error(const fs::path &path) {
    ::testing::internal::CaptureStderr();
    ::testing::internal::CaptureStdout();
    std::string message;
    try {
      tri::read_mesh_file(path.string());
    } catch (const tri::MeshFileError &e) {
      message = e.what();
    }
    const std::string printed =
        ::testing::internal::GetCapturedStderr() + ::testing::internal::GetCapturedStdout();
    EXPECT_EQ(printed, "") << "reading " << path << " printed to the terminal";
    return message;
  }

  fs::path dir_;
};

void expect_same_shape(const tri::Shape &read, const tri::Shape &original, double rel) {
  EXPECT_EQ(read.mesh.num_triangles(), original.mesh.num_triangles());
  EXPECT_EQ(read.mesh.num_vertices(), original.mesh.num_vertices()); // corners merged
  EXPECT_NEAR(read.volume, original.volume, rel * original.volume);
  EXPECT_NEAR((read.inertia_per_density - original.inertia_per_density).norm(), 0.0,
              rel * original.inertia_per_density.norm());
  EXPECT_NEAR(read.bounding_radius, original.bounding_radius, rel * original.bounding_radius);
}

TEST_F(MeshReader, AllFormatsGiveTheSameShape) {
  for (const auto &[name, mesh] :
       {std::pair{std::string("box"),
                  tri_test::transformed(box(3, 1, 2), Eigen::Matrix3d::Identity(),
                                        Eigen::Vector3d(5, -4, 3))},
        std::pair{std::string("sphere"), sphere(3, 0.002)}}) {
    SCOPED_TRACE(name);
    const tri::Shape original = tri::make_shape(name, mesh);
    write_ascii_stl(file(name + "_ascii.stl"), mesh);
    write_binary_stl(file(name + "_binary.stl"), mesh);
    write_obj(file(name + ".obj"), mesh);
    write_ascii_ply(file(name + ".ply"), mesh);
    write_binary_ply(file(name + "_binary.ply"), mesh);
    for (const char *f : {"_ascii.stl", "_binary.stl", ".obj", ".ply", "_binary.ply"}) {
      SCOPED_TRACE(f);
      const fs::path path = file(name + f);
      const tri::Shape read = tri::make_shape(name, tri::read_mesh_file(path.string()));
      // Binary STL stores floats, and VTK's readers keep every format's points as floats:
      // 6e-8 relative per coordinate. The box's coordinates are exact in float.
      expect_same_shape(read, original, name == "box" ? 1e-14 : 1e-6);
    }
  }
}

TEST_F(MeshReader, ExtensionIsCaseInsensitive) {
  write_binary_stl(file("BOX.STL"), box(1, 2, 3));
  EXPECT_EQ(tri::read_mesh_file(file("BOX.STL").string()).num_triangles(), 12);
}

TEST_F(MeshReader, BinaryStlWhoseHeaderSaysSolid) {
  // Some CAD exporters start the binary header with "solid"; the size identifies it.
  const tri::TriangleMesh mesh = box(3, 1, 2);
  write_binary_stl(file("solid.stl"), mesh, "solid exported by some CAD tool");
  const tri::Shape s = tri::make_shape("s", tri::read_mesh_file(file("solid.stl").string()));
  EXPECT_NEAR(s.volume, 6.0, 1e-12);
}

TEST_F(MeshReader, QuadFacesAreTriangulated) {
  write_text(file("quads.obj"),
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
             "v 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
             "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n");
  const tri::TriangleMesh m = tri::read_mesh_file(file("quads.obj").string());
  EXPECT_EQ(m.num_triangles(), 12);
  EXPECT_NEAR(tri::make_shape("cube", m).volume, 1.0, 1e-14);
}

TEST_F(MeshReader, TruncatedBinaryStl) {
  const fs::path path = file("cut.stl");
  write_binary_stl(path, box(3, 1, 2));
  truncate_to(path, 84 + 50 * 12 - 20);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path,
                                    "binary STL is truncated or malformed: its header announces "
                                    "12 triangles (684 bytes) but the file has 664 bytes"));
}

TEST_F(MeshReader, TruncatedBinaryStlWhoseHeaderSaysSolid) {
  const fs::path path = file("cut_solid.stl");
  write_binary_stl(path, box(3, 1, 2), "solid but binary");
  truncate_to(path, 84 + 50 * 12 - 20);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path, "binary STL is truncated"));
}

TEST_F(MeshReader, TruncatedAsciiStl) {
  const fs::path path = file("cut_ascii.stl");
  write_ascii_stl(path, sphere(1, 1.0));
  truncate_to(path, fs::file_size(path) / 2);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path, "ASCII STL is truncated"));
}

TEST_F(MeshReader, MalformedAsciiStl) {
  // Complete on the outside, garbage inside: VTK's complaint becomes the exception.
  EXPECT_TRUE(TextFileFailsWith(
      "bad_ascii.stl",
      "solid x\n  facet normal 0 0 0\n    outer loop\n      vertex 0 0 zero\n"
      "      vertex 1 0 0\n      vertex 0 1 0\n    endloop\n  endfacet\nendsolid x\n",
      "cannot read mesh file (STL)"));
}

TEST_F(MeshReader, GarbageContent) {
  const std::string garbage = "this is not a mesh at all\n\x01\x02\x03 just some bytes\n";
  EXPECT_TRUE(TextFileFailsWith("garbage.stl", garbage, "not an STL file"));
  EXPECT_TRUE(TextFileFailsWith("garbage.obj", garbage, "contains no triangles"));
  EXPECT_TRUE(TextFileFailsWith("garbage.ply", garbage, "not a PLY file"));
}

TEST_F(MeshReader, TruncatedPly) {
  // VTK 9.1's PLY reader aborts the process on these; the reader must catch them first.
  for (const char *format : {"ascii", "binary"}) {
    SCOPED_TRACE(format);
    const fs::path path = file(std::string("cut_") + format + ".ply");
    if (std::string(format) == "ascii")
      write_ascii_ply(path, sphere(2, 1.0));
    else
      write_binary_ply(path, sphere(2, 1.0));
    truncate_to(path, fs::file_size(path) - 7); // inside the last face
    EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path,
                                      "PLY file is truncated: face 127 of 128 is incomplete"));
    truncate_to(path, fs::file_size(path) / 3);
    EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path, "PLY file is truncated: vertex "));
  }
}

TEST_F(MeshReader, PlyFaceWithMissingVertex) {
  EXPECT_TRUE(TextFileFailsWith(
      "dangling.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
      "PLY file is malformed: face 0 refers to vertex 3, but there are 3 vertices"));
}

TEST_F(MeshReader, ObjFaceWithMissingVertex) {
  EXPECT_TRUE(TextFileFailsWith("dangling.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n",
                                "mesh file is malformed: face 1 refers to vertex 9 (1-based), "
                                "but there are 3 vertices"));
}

// Inputs found by tests/fuzz that VTK 9.1's readers crash on, or misread, unless the reader
// stops them first; each must end in a MeshFileError that says why.
TEST_F(MeshReader, AsciiStlWithBytesThatAreNotText) {
  // VTK took this for binary and believed a "triangle count" made of text (2 GB).
  std::string text = "solid x\n  fac" + std::string(40, '\0') + "et normal 0 0 1\n";
  for (int k = 0; k < 4; ++k)
    text += "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
            "      vertex 0 1 0\n    endloop\n  endfacet\n";
  text += "endsolid x\n";
  EXPECT_TRUE(TextFileFailsWith("nul.stl", text, "nor ASCII text: byte 0x0 at offset 13"));
}

TEST_F(MeshReader, CoordinateBeyondFloatRange) {
  std::string text = "solid x\n";
  const char *corners[4][3] = {{"0 0 0", "0 1 0", "1 0 0"},
                               {"0 0 0", "1 0 0", "0 0 1e39"},
                               {"0 0 0", "0 0 1e39", "0 1 0"},
                               {"1 0 0", "0 1 0", "0 0 1e39"}};
  for (const auto &facet : corners) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (const char *corner : facet)
      text += std::string("vertex ") + corner + "\n";
    text += "endloop\nendfacet\n";
  }
  text += "endsolid x\n";
  EXPECT_TRUE(TextFileFailsWith("huge.stl", text, "not a finite 32-bit float"));
}

TEST_F(MeshReader, ObjTextureAndNormalIndicesAreChecked) {
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  EXPECT_TRUE(TextFileFailsWith("no_normals.obj", tet + "f 1//1 3//1 2//1\n",
                                "refers to normal 1 (1-based), but there are 0 normals"));
  EXPECT_TRUE(TextFileFailsWith(
      "bad_tcoord.obj", tet + "vt 0 0\nf 1/1 3/2 2/1\n",
      "refers to texture coordinate 2 (1-based), but there are 1 texture coordinate before it"));
  EXPECT_TRUE(
      TextFileFailsWith("slash.obj", tet + "f 4/ 3 2\n", "has a corner with an index missing"));
  EXPECT_TRUE(
      TextFileFailsWith("mixed.obj", tet + "vn 0 0 1\nf 1//1 3 2\n", "mixes the corner forms"));
  // Found by a longer run: texture and normal indices in range, vertices missing.
  EXPECT_TRUE(TextFileFailsWith("no_vertices.obj", "vn 0 0 1\nvt 0 0\nf 1/1/1 3/1/1 2/1/1\n",
                                "refers to vertex 1 (1-based), but there are 0 vertices"));
  // An index beyond long long (strtoll saturates; negating its result overflowed).
  EXPECT_TRUE(TextFileFailsWith("huge.obj", tet + "f -4 -3 -66666666666666666666661\n",
                                "refers to vertex -66666666666666666666661 (1-based)"));
  // Negative indices count back from the element, as in VTK.
  write_text(file("relative.obj"), tet + "vt 0 0\nf -4/1 -2/1 -3/1\nf -4/1 -3/1 -1/1\n"
                                         "f -4/1 -1/1 -2/1\nf -3/1 -2/1 -1/1\n");
  EXPECT_EQ(read_error(file("relative.obj")), "");
  // Well-formed texture and normal indices still read (VTK wants one form in every face).
  write_text(file("ok.obj"), tet + "vt 0 0\nvn 0 0 1\nf 1/1/1 3/1/1 2/1/1\nf 1/1/1 2/1/1 4/1/1\n"
                                   "f 1/1/1 4/1/1 3/1/1\nf 2/1/1 3/1/1 4/1/1\n");
  EXPECT_EQ(read_error(file("ok.obj")), "");
}

TEST_F(MeshReader, PlyStructureThatVtkCannotRead) {
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string head = "ply\nformat ascii 1.0\n";
  EXPECT_TRUE(TextFileFailsWith("no_vertex.ply", head + face + "end_header\n3 0 1 2\n",
                                "no \"element vertex\""));
  EXPECT_TRUE(TextFileFailsWith("no_face.ply", head + vertex + "end_header\n0 0 0\n1 0 0\n0 1 0\n",
                                "no \"element face\""));
  EXPECT_TRUE(TextFileFailsWith("empty_face.ply",
                                head + vertex + face + "end_header\n0 0 0\n1 0 0\n0 1 0\n0\n",
                                "face 0 has 0 vertex indices"));
  EXPECT_TRUE(TextFileFailsWith("header_line.ply",
                                head + vertex + face + "end_header0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                                "\"end_header\" is not a line of its own"));
  EXPECT_TRUE(TextFileFailsWith("nul.ply",
                                head + vertex + face + "end_header\n0 0 0\n1 " +
                                    std::string(1, '\0') + " 0\n0 1 0\n3 0 1 2\n",
                                "ASCII PLY file is not text: byte 0x0"));
  // A comment may name end_header; the header ends at the line that is end_header.
  write_text(file("comment.ply"),
             head + "comment the end_header line ends the header\n" +
                 "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  EXPECT_EQ(read_error(file("comment.ply")), "");
  // One element per line: a short line is a truncated element even if the next fills it.
  EXPECT_TRUE(TextFileFailsWith("split.ply",
                                head + vertex + face + "end_header\n0 0\n0 1 0 0\n0 1 0\n3 0 1 2\n",
                                "PLY file is truncated: vertex 0 of 3"));
  // Values must be numbers: vtkPLY rewrites some words in place and then reads through a wild
  // pointer ("0vertex_index", found by fuzz_ply).
  EXPECT_TRUE(TextFileFailsWith("word.ply",
                                head + vertex + face + "end_header\n0 0vertex_index 0\n1 0 0\n"
                                    "0 1 0\n3 0 1 2\n",
                                "\"0vertex_index\" where a number was expected"));
  // More inputs vtkPLY crashes on, refused first (fuzz_ply): a count that is not an integer,
  // an element without properties, a stray header line, a last line without its line end.
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_TRUE(TextFileFailsWith("count.ply", head + "element vertex 3.0\n" +
                                    vertex.substr(vertex.find('\n') + 1) + face + "end_header\n" + body,
                                "bad element line \"element vertex 3.0\""));
  EXPECT_TRUE(TextFileFailsWith("empty_element.ply",
                                head + "element extra 1\n" + vertex + face + "end_header\n" + body,
                                "element \"extra\" has no properties"));
  EXPECT_TRUE(TextFileFailsWith("stray.ply", head + vertex + face + "\n0 000 1\nend_header\n" + body,
                                "unexpected header line \"\""));
  EXPECT_TRUE(TextFileFailsWith("no_line_end.ply",
                                head + vertex + face + "end_header\n" + body.substr(0, body.size() - 1),
                                "its last line has no line end"));
}

TEST_F(MeshReader, TruncatedObj) {
  // Cut inside a face line: VTK's complaint becomes the exception. (Cut at a line end, an
  // OBJ simply has fewer faces; make_shape then reports the hole.)
  EXPECT_TRUE(TextFileFailsWith(
      "cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4",
      "cannot read mesh file (OBJ): VTK reported: Error reading file near line 8"));
}

TEST_F(MeshReader, MissingFile) {
  const fs::path path = file("nowhere.stl");
  EXPECT_TRUE(StartsWithPathAndSays(read_error(path), path, "cannot read mesh file: no such file"));
}

TEST_F(MeshReader, DirectoryIsNotAFile) {
  const fs::path path = file("folder.stl");
  fs::create_directory(path);
  EXPECT_TRUE(
      StartsWithPathAndSays(read_error(path), path, "cannot read mesh file: not a regular file"));
}

TEST_F(MeshReader, UnknownExtension) {
  EXPECT_TRUE(TextFileFailsWith(
      "shape.xyz", "1 2 3\n", "unknown mesh file extension '.xyz' (expected .stl, .obj or .ply)"));
  EXPECT_TRUE(TextFileFailsWith("shape", "1 2 3\n", "unknown mesh file extension ''"));
}

TEST_F(MeshReader, EmptyFileAndEmptyMesh) {
  EXPECT_TRUE(TextFileFailsWith("empty.obj", "", "mesh file is empty"));
  EXPECT_TRUE(TextFileFailsWith("nothing.stl", "solid nothing\nendsolid nothing\n",
                                "mesh file contains no triangles"));
  EXPECT_TRUE(TextFileFailsWith("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n",
                                "mesh file contains no triangles"));
}

TEST_F(MeshReader, OpenMeshReadsButMakeShapeRejectsIt) {
  // Closedness is make_shape's job: the reader returns what is in the file.
  tri::TriangleMesh m = box(1, 1, 1);
  m.triangles.pop_back();
  write_binary_stl(file("open.stl"), m);
  const tri::TriangleMesh read = tri::read_mesh_file(file("open.stl").string());
  EXPECT_EQ(read.num_triangles(), 11);
  EXPECT_THROW(tri::make_shape("open", read), tri::ShapeError);
}

} // namespace

namespace {

TEST(ExampleMeshes, GearIsClosedAndNotConvex) {
  // examples/falling/meshes/gear.stl (made by make_meshes.py there), in millimetres.
  // Found from this source file (CMake compiles it by absolute path): tests/io/ -> repo root.
  const std::string path = (fs::path(__FILE__).parent_path().parent_path().parent_path() /
                            "examples/falling/meshes/gear.stl")
                               .string();
  const tri::Shape gear = tri::make_shape("gear", tri::scaled(tri::read_mesh_file(path), 0.001));
  EXPECT_EQ(gear.mesh.num_triangles(), 128);
  EXPECT_EQ(gear.mesh.num_vertices(), 66); // 2 x 32 outline corners + 2 cap centres
  EXPECT_FALSE(gear.convex);
  EXPECT_NEAR(gear.volume, 13.5315e-9, 1e-13);
  EXPECT_NEAR(gear.bounding_radius, std::hypot(2.0, 0.75) * 1e-3, 1e-8);
}

} // namespace
