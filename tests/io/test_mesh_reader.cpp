// read_mesh_file: the same shape written as ASCII STL, binary STL, OBJ and PLY (by the tiny
// writers below, at run time, into a temporary directory) reads back with the same mass
// properties, text numbers with all their digits; broken files give a MeshFileError that starts
// with the path and says what.
#include "../kernel/test_meshes.h"
#include "body/shape.h"
#include "mesh_reader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

  // The MeshFileError message for reading `path` ("" if it reads), with a check that nothing
  // was printed.
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
      // Binary STL and this binary PLY store floats: 6e-8 relative per coordinate. The text
      // files hold 17 digits, which read back as the very doubles written (only the order of
      // vertices, and so of sums, may differ). The box's coordinates are exact in float.
      const bool binary = std::string(f).find("binary") != std::string::npos;
      expect_same_shape(read, original, name == "box" || !binary ? 1e-13 : 1e-6);
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
  // Complete on the outside, garbage inside: the line and what is wrong with it.
  EXPECT_TRUE(TextFileFailsWith(
      "bad_ascii.stl",
      "solid x\n  facet normal 0 0 0\n    outer loop\n      vertex 0 0 zero\n"
      "      vertex 1 0 0\n      vertex 0 1 0\n    endloop\n  endfacet\nendsolid x\n",
      "ASCII STL is malformed: \"zero\" where a number was expected (line 4)"));
}

TEST_F(MeshReader, GarbageContent) {
  const std::string garbage = "this is not a mesh at all\n\x01\x02\x03 just some bytes\n";
  EXPECT_TRUE(TextFileFailsWith("garbage.stl", garbage, "not an STL file"));
  EXPECT_TRUE(TextFileFailsWith("garbage.obj", garbage, "contains no triangles"));
  EXPECT_TRUE(TextFileFailsWith("garbage.ply", garbage, "not a PLY file"));
}

TEST_F(MeshReader, TruncatedPly) {
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

// Inputs found by tests/fuzz while VTK 9.1's readers read the files (they crashed on them or
// misread them, so the reader had to refuse them first); the reader's own parsers must end each
// in a MeshFileError that says why.
TEST_F(MeshReader, AsciiStlWithBytesThatAreNotText) {
  // VTK took this for binary and believed a "triangle count" made of text (2 GB). ASCII STL
  // must be text.
  std::string text = "solid x\n  fac" + std::string(40, '\0') + "et normal 0 0 1\n";
  for (int k = 0; k < 4; ++k)
    text += "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
            "      vertex 0 1 0\n    endloop\n  endfacet\n";
  text += "endsolid x\n";
  EXPECT_TRUE(TextFileFailsWith("nul.stl", text, "nor ASCII text: byte 0x0 at offset 13"));
}

// A tetrahedron as ASCII STL whose apex has the coordinate `z` (a word of the file).
std::string ascii_stl_tetrahedron(const std::string &z) {
  std::string text = "solid x\n";
  const std::string apex = "0 0 " + z;
  const std::string corners[4][3] = {{"0 0 0", "0 1 0", "1 0 0"},
                                     {"0 0 0", "1 0 0", apex},
                                     {"0 0 0", apex, "0 1 0"},
                                     {"1 0 0", "0 1 0", apex}};
  for (const auto &facet : corners) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (const std::string &corner : facet)
      text += "vertex " + corner + "\n";
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid x\n";
}

TEST_F(MeshReader, CoordinateThatIsNotFinite) {
  // Text is read as double: 1e39 (beyond float, which VTK turned into inf) is a coordinate.
  write_text(file("big.stl"), ascii_stl_tetrahedron("1e39"));
  EXPECT_EQ(tri::read_mesh_file(file("big.stl").string()).vertices.back().z(), 1e39);
  EXPECT_TRUE(TextFileFailsWith("nan.stl", ascii_stl_tetrahedron("nan"),
                                "a triangle corner has a coordinate that is not a finite number "
                                "(0, 0, nan)"));
  EXPECT_TRUE(TextFileFailsWith("inf.stl", ascii_stl_tetrahedron("-inf"),
                                "a triangle corner has a coordinate that is not a finite number "
                                "(0, 0, -inf)"));
  EXPECT_TRUE(TextFileFailsWith("beyond.stl", ascii_stl_tetrahedron("1e309"),
                                "ASCII STL is malformed: \"1e309\" is out of the range of a "
                                "double (line 13)"));
  // Binary STL: the bits of a NaN.
  tri::TriangleMesh m = box(1, 1, 1);
  m.vertices[0].x() = std::nan("");
  write_binary_stl(file("nan_binary.stl"), m);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(file("nan_binary.stl")), file("nan_binary.stl"),
                                    "not a finite number (nan,"));
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
  // Negative indices count back from the face: -1 is the last vertex defined before it.
  write_text(file("relative.obj"), tet + "vt 0 0\nf -4/1 -2/1 -3/1\nf -4/1 -3/1 -1/1\n"
                                         "f -4/1 -1/1 -2/1\nf -3/1 -2/1 -1/1\n");
  EXPECT_EQ(read_error(file("relative.obj")), "");
  // Well-formed texture and normal indices read (one form throughout a face).
  write_text(file("ok.obj"), tet + "vt 0 0\nvn 0 0 1\nf 1/1/1 3/1/1 2/1/1\nf 1/1/1 2/1/1 4/1/1\n"
                                   "f 1/1/1 4/1/1 3/1/1\nf 2/1/1 3/1/1 4/1/1\n");
  EXPECT_EQ(read_error(file("ok.obj")), "");
}

TEST_F(MeshReader, MalformedPlyStructure) {
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
  // Values must be numbers (vtkPLY rewrote "0vertex_index" in place and then read through a
  // wild pointer, found by fuzz_ply).
  EXPECT_TRUE(TextFileFailsWith("word.ply",
                                head + vertex + face + "end_header\n0 0vertex_index 0\n1 0 0\n"
                                    "0 1 0\n3 0 1 2\n",
                                "\"0vertex_index\" where a number was expected"));
  // More inputs vtkPLY crashed on (fuzz_ply): a count that is not an integer, an element
  // without properties, a stray header line; all malformed. A last line without its line end
  // (vtkPLY freed a face twice) is no fault of the file, and it reads.
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_TRUE(TextFileFailsWith("count.ply", head + "element vertex 3.0\n" +
                                    vertex.substr(vertex.find('\n') + 1) + face + "end_header\n" + body,
                                "bad element line \"element vertex 3.0\""));
  EXPECT_TRUE(TextFileFailsWith("empty_element.ply",
                                head + "element extra 1\n" + vertex + face + "end_header\n" + body,
                                "element \"extra\" has no properties"));
  EXPECT_TRUE(TextFileFailsWith("stray.ply", head + vertex + face + "\n0 000 1\nend_header\n" + body,
                                "unexpected header line \"\""));
  write_text(file("no_line_end.ply"), head + vertex + face + "end_header\n" +
                                          body.substr(0, body.size() - 1));
  EXPECT_EQ(read_error(file("no_line_end.ply")), "");
}

TEST_F(MeshReader, TruncatedObj) {
  // Cut inside a face line: a face with too few corners. (Cut at a line end, an OBJ simply
  // has fewer faces; make_shape then reports the hole.)
  EXPECT_TRUE(TextFileFailsWith(
      "cut.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4",
      "mesh file is malformed: face 3 has 2 corners (a face needs at least 3) (line 8)"));
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

// --- precision, dialects and polygons ----------------------------------------------------

// Bytes of `value` in the given byte order (PLY's binary formats).
template <typename T> std::string bytes_of(T value, bool big_endian) {
  std::string b(sizeof(T), '\0');
  std::memcpy(b.data(), &value, sizeof(T));
  const std::uint16_t probe = 1;
  const bool host_little = *reinterpret_cast<const unsigned char *>(&probe) == 1;
  if (host_little == big_endian)
    std::reverse(b.begin(), b.end());
  return b;
}

// Coordinates with more digits than a float holds, as words of a file.
const char *kDigits[4][3] = {{"0.1234567890123", "-0.9876543210987", "1e-7"},
                             {"1.0000000000000002", "0.3333333333333333", "-2.5e-3"},
                             {"0.30000000000000004", "1.2345678901234567e2", "0"},
                             {"-0.1", "0.7071067811865476", "3.141592653589793"}};
const int kTetFaces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// The same as the doubles that strtod gives for kDigits, in the file's order.
void expect_digits_kept(const tri::TriangleMesh &m) {
  ASSERT_EQ(m.num_vertices(), 4);
  // Vertices come in the order the triangles first use them: 0, 2, 1, 3.
  const int file_vertex[4] = {0, 2, 1, 3};
  for (int v = 0; v < 4; ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(m.vertices[v][k], std::strtod(kDigits[file_vertex[v]][k], nullptr))
          << "vertex " << v << " coordinate " << k << " (" << kDigits[file_vertex[v]][k] << ")";
}

TEST_F(MeshReader, TextCoordinatesKeepDoublePrecision) {
  std::string obj, ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 4\n"
                         "property list uchar int vertex_indices\nend_header\n";
  std::string stl = "solid digits\n";
  for (const auto &v : kDigits) {
    obj += std::string("v ") + v[0] + " " + v[1] + " " + v[2] + "\n";
    ply += std::string(v[0]) + " " + v[1] + " " + v[2] + "\n"; // declared float, written double
  }
  for (const auto &f : kTetFaces) {
    obj += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
           std::to_string(f[2] + 1) + "\n";
    ply += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
           "\n";
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int c : f)
      stl += std::string("   vertex ") + kDigits[c][0] + " " + kDigits[c][1] + " " +
             kDigits[c][2] + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid digits\n";
  for (const auto &[name, text] : {std::pair<std::string, std::string>{"digits.obj", obj},
                                   {"digits.ply", ply},
                                   {"digits.stl", stl}}) {
    SCOPED_TRACE(name);
    write_text(file(name), text);
    expect_digits_kept(tri::read_mesh_file(file(name).string()));
  }
}

// A tetrahedron with kDigits' corners as binary PLY: x y z of `type` ("double" or "float"),
// with a vertex property before and after them, and faces with uint indices.
std::string binary_ply_tetrahedron(const std::string &type, bool big_endian) {
  std::string b = std::string("ply\nformat ") +
                  (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 4\nproperty uchar red\nproperty " + type +
                  " x\nproperty " + type + " y\nproperty " + type +
                  " z\nproperty short flags\nelement face 4\n"
                  "property list uchar uint vertex_indices\nend_header\n";
  for (const auto &v : kDigits) {
    b += bytes_of<std::uint8_t>(200, big_endian);
    for (const char *word : v) {
      const double x = std::strtod(word, nullptr);
      b += type == "double" ? bytes_of(x, big_endian) : bytes_of(static_cast<float>(x), big_endian);
    }
    b += bytes_of<std::int16_t>(-3, big_endian);
  }
  for (const auto &f : kTetFaces) {
    b += bytes_of<std::uint8_t>(3, big_endian);
    for (int c : f)
      b += bytes_of(static_cast<std::uint32_t>(c), big_endian);
  }
  return b;
}

TEST_F(MeshReader, BinaryPlyInBothByteOrders) {
  for (const bool big_endian : {false, true}) {
    SCOPED_TRACE(big_endian ? "big endian" : "little endian");
    write_text(file("double.ply"), binary_ply_tetrahedron("double", big_endian));
    expect_digits_kept(tri::read_mesh_file(file("double.ply").string()));
    // float32 properties: exactly the float, widened.
    write_text(file("float.ply"), binary_ply_tetrahedron("float32", big_endian));
    const tri::TriangleMesh m = tri::read_mesh_file(file("float.ply").string());
    ASSERT_EQ(m.num_vertices(), 4);
    EXPECT_EQ(m.vertices[0].x(), static_cast<double>(static_cast<float>(0.1234567890123)));
    EXPECT_NE(m.vertices[0].x(), 0.1234567890123);
  }
}

TEST_F(MeshReader, PlyOtherElementsAndPropertiesAreSkipped) {
  // The same tetrahedron as the plain one, with x, y, z out of order among other vertex
  // properties, a list in the vertex element, elements before, between and after, more face
  // properties (a scalar and a second list) around vertex_index, CRLF and a blank line.
  const std::string plain =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string rich =
      "ply\r\nformat ascii 1.0\r\ncomment exported by a tool\r\nobj_info anything\r\n"
      "element camera 1\r\nproperty float view_px\r\nproperty list uchar double params\r\n"
      "element vertex 4\r\nproperty double nx\r\nproperty float z\r\nproperty uchar red\r\n"
      "property list ushort int neighbours\r\nproperty int x\r\nproperty float64 y\r\n"
      "element edge 2\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
      "element face 4\r\nproperty uint8 flags\r\nproperty list uint8 int32 vertex_index\r\n"
      "property list uchar float texcoord\r\nelement material 1\r\nproperty short a\r\n"
      "end_header\r\n"
      "1.5 2 0.5 0.25\r\n"
      "0.1 0 255 2 1 2 0 0\r\n-0.5 0 7 0 1 0\r\n0 0 1 1 3 0 1\r\n0 1 0 0 0 0\r\n"
      "\r\n0 1\r\n2 3\r\n"
      "9 3 0 2 1 6 0 0 1 0 0 1\r\n9 3 0 1 3 0\r\n9 3 0 3 2 0\r\n9 3 1 2 3 2 0.5 0.5\r\n"
      "-4\r\n\r\n";
  write_text(file("plain.ply"), plain);
  write_text(file("rich.ply"), rich);
  const tri::TriangleMesh a = tri::read_mesh_file(file("plain.ply").string());
  const tri::TriangleMesh b = tri::read_mesh_file(file("rich.ply").string());
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST_F(MeshReader, ObjNegativeIndicesAndPolygons) {
  // A unit cube: quads with negative (relative) indices, texture and normal indices, a
  // comment, groups, a line element and CRLF line ends.
  const std::string cube =
      "# cube\r\nmtllib cube.mtl\r\no cube\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
      "v 0 0 1\r\nv 1 0 1 1.0\r\nv 1 1 1 0.5 0.5 0.5\r\nv 0 1 1\r\nvt 0 0\r\nvn 0 0 1\r\n"
      "g sides\r\nusemtl m\r\ns off\r\n"
      "f -8/1 -5/1 -6/1 -7/1\r\nf -4//1 -3//1 -2//1 -1//1\r\nf 1/1/1 2/1/1 6/1/1 5/1/1\r\n"
      "f 2 3 7 6\r\nf 3 4 8 7\r\nf 4 1 5 8\r\nl 1 2\r\n";
  write_text(file("cube.obj"), cube);
  const tri::TriangleMesh m = tri::read_mesh_file(file("cube.obj").string());
  ASSERT_EQ(m.num_triangles(), 12);
  EXPECT_NEAR(tri::make_shape("cube", m).volume, 1.0, 1e-15);
  // A convex polygon is the fan from its first corner, in the file's corner order: f 1 4 3 2
  // is (1, 4, 3), (1, 3, 2), here vertices 0, 1, 2, 3 in order of first use.
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(m.vertices[1], Eigen::Vector3d(0, 1, 0));
  // A pentagon, and a quad with a repeated corner (a triangle written as a quad).
  write_text(file("pentagon.obj"),
             "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nv 1 1 -1\n"
             "f 1 2 3 4 5\nf 2 1 6 6\nf 3 2 6\nf 4 3 6\nf 5 4 6\nf 1 5 6\n");
  const tri::TriangleMesh p = tri::read_mesh_file(file("pentagon.obj").string());
  EXPECT_EQ(p.num_triangles(), 3 + 5);
  EXPECT_EQ(p.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(p.triangles[2], (std::array<int, 3>{0, 3, 4}));
  EXPECT_NO_THROW(tri::make_shape("pentagon", p));
}

TEST_F(MeshReader, PolygonsThatAreNotConvex) {
  // A prism on an arrowhead (concave) with the top and bottom as one polygon each, and a cube
  // whose bottom and front faces carry a corner in the middle of their common edge: both are
  // split into triangles without folds (ear clipping), so the volume is right.
  write_text(file("arrow.obj"), "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 1 0\nv 0 2 0\n"
                                "v 0 0 1\nv 2 0 1\nv 2 2 1\nv 1 1 1\nv 0 2 1\n"
                                "f 1 5 4 3 2\nf 6 7 8 9 10\nf 1 2 7 6\nf 2 3 8 7\nf 3 4 9 8\n"
                                "f 4 5 10 9\nf 5 1 6 10\n");
  const tri::Shape arrow = tri::make_shape("arrow", tri::read_mesh_file(file("arrow.obj").string()));
  EXPECT_EQ(arrow.mesh.num_triangles(), 16);
  EXPECT_NEAR(arrow.volume, 3.0, 1e-14);
  EXPECT_FALSE(arrow.convex);
  write_text(file("midpoint.obj"), "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
                                   "v 1 1 1\nv 0 1 1\nv 0.5 0 0\n"
                                   "f 1 4 3 2 9\nf 5 6 7 8\nf 1 9 2 6 5\nf 2 3 7 6\nf 3 4 8 7\n"
                                   "f 4 1 5 8\n");
  const tri::Shape cube =
      tri::make_shape("midpoint", tri::read_mesh_file(file("midpoint.obj").string()));
  EXPECT_EQ(cube.mesh.num_triangles(), 14);
  EXPECT_NEAR(cube.volume, 1.0, 1e-15);
  // A bow tie crosses itself: there is no right way to split it.
  EXPECT_TRUE(TextFileFailsWith("bowtie.obj", "v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 1 0\nf 1 2 3 4\n",
                                "mesh file is malformed: face 0 cannot be split into triangles: "
                                "its corners do not form a simple polygon"));
  EXPECT_TRUE(TextFileFailsWith("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3 4\n",
                                "face 0 cannot be split into triangles: it has no area"));
  EXPECT_TRUE(TextFileFailsWith("two.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 1\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n4 0 1 1 0\n",
                                "PLY file is malformed: face 0 cannot be split into triangles: it "
                                "has fewer than 3 distinct corners"));
}

TEST_F(MeshReader, AsciiStlDialects) {
  // Keywords in any case, tabs, CRLF, a colour line, two solids, blank lines: one mesh.
  const std::string text =
      "SOLID part one\r\n\r\ncolor 1 0 0 1\r\n  FACET NORMAL 0 0 -1\r\n\tOUTER\tLOOP\r\n"
      "\tVERTEX 0 0 0\r\n\tVERTEX 0 1 0\r\n\tVERTEX 1 0 0\r\n\tENDLOOP\r\n  ENDFACET\r\n"
      "ENDSOLID part one\r\nsolid two\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n"
      "vertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\n"
      "vertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 0\n"
      "outer loop\nvertex 1 0 0\nvertex 0 1 0\nvertex +0 +0 +1.0e0\nendloop\nendfacet\n"
      "endsolid two\n\n";
  write_text(file("dialect.stl"), text);
  const tri::TriangleMesh m = tri::read_mesh_file(file("dialect.stl").string());
  EXPECT_EQ(m.num_triangles(), 4);
  EXPECT_EQ(m.num_vertices(), 4);
  EXPECT_NEAR(tri::make_shape("tet", m).volume, 1.0 / 6.0, 1e-16);
}

TEST_F(MeshReader, MalformedAsciiStlLines) {
  const std::string head = "solid x\nfacet normal 0 0 1\nouter loop\n";
  const std::string tail = "endloop\nendfacet\nendsolid x\n";
  const std::string corners = "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
  EXPECT_TRUE(TextFileFailsWith("short.stl", head + "vertex 0 0\nvertex 1 0 0\nvertex 0 1 0\n" + tail,
                                "ASCII STL is malformed: a vertex needs three coordinates x y z "
                                "(line 4)"));
  EXPECT_TRUE(TextFileFailsWith("long.stl", head + "vertex 0 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n" + tail,
                                "ASCII STL is malformed: a vertex has more than three coordinates "
                                "(line 4)"));
  EXPECT_TRUE(TextFileFailsWith("four.stl", head + corners + "vertex 1 1 0\n" + tail,
                                "ASCII STL is malformed: expected \"endloop\" after three vertices, "
                                "found \"vertex 1 1 0\" (line 7)"));
  EXPECT_TRUE(TextFileFailsWith("noloop.stl", "solid x\nfacet normal 0 0 1\n" + corners + tail,
                                "expected \"outer loop\", found \"vertex 0 0 0\" (line 3)"));
  EXPECT_TRUE(TextFileFailsWith("junk.stl", "solid x\nendsolid x\nfacet\nendsolid x\n",
                                "expected \"solid\", found \"facet\" (line 3)"));
  EXPECT_TRUE(TextFileFailsWith("hex.stl", head + "vertex 0x1p3 0 0\n" + tail,
                                "\"0x1p3\" where a number was expected (line 4)"));
}

TEST_F(MeshReader, MalformedObjLines) {
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  EXPECT_TRUE(TextFileFailsWith("short.obj", "v 0 0\n", "mesh file is malformed: a vertex needs "
                                                        "three coordinates x y z (line 1)"));
  EXPECT_TRUE(TextFileFailsWith("word.obj", "v 0 0 1 junk\n", "\"junk\" where a number was "
                                                              "expected (line 1)"));
  EXPECT_TRUE(TextFileFailsWith("many.obj", "v 0 0 1 1 1 1 1 1\n",
                                "a vertex has more than seven numbers"));
  EXPECT_TRUE(TextFileFailsWith("range.obj", "v 0 0 1e400\n",
                                "\"1e400\" is out of the range of a double (line 1)"));
  EXPECT_TRUE(TextFileFailsWith("comment.obj", tet + "f 1 2 3 # a comment\n",
                                "face 0 has a corner \"#\" whose vertex index is not an integer "
                                "(line 5)"));
  EXPECT_TRUE(TextFileFailsWith("decimal.obj", tet + "f 1 2.0 3\n",
                                "face 0 has a corner \"2.0\" whose vertex index is not an integer"));
  EXPECT_TRUE(TextFileFailsWith("zero.obj", tet + "f 0 1 2\n",
                                "face 0 refers to vertex 0 (1-based), but there are 4 vertices "
                                "before it (line 5)"));
  // Relative indices count only what comes before the face.
  EXPECT_TRUE(TextFileFailsWith("later.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n",
                                "face 0 refers to vertex -3 (1-based), but there are 2 vertices "
                                "before it (line 3)"));
  EXPECT_TRUE(TextFileFailsWith("empty.obj", tet + "f\n",
                                "face 0 has 0 corners (a face needs at least 3) (line 5)"));
}

TEST_F(MeshReader, MalformedPlyBodies) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_TRUE(TextFileFailsWith("extra_value.ply", head + "0 0 0 5\n1 0 0\n0 1 0\n3 0 1 2\n",
                                "PLY file is malformed: vertex 0 has more values than its "
                                "properties (line 10)"));
  EXPECT_TRUE(TextFileFailsWith("after.ply", head + body + "0 0 1\n",
                                "PLY file is malformed: text after the last element (line 14)"));
  EXPECT_TRUE(TextFileFailsWith("float_count.ply", head + "0 0 0\n1 0 0\n0 1 0\n3.0 0 1 2\n",
                                "\"3.0\" where an integer was expected (line 13)"));
  EXPECT_TRUE(TextFileFailsWith(
      "float_index.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n" +
          body,
      "the face element's vertex_indices list holds floating-point values"));
  EXPECT_TRUE(TextFileFailsWith("twice.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                "property float x\nend_header\n",
                                "element \"vertex\" has two properties \"x\""));
  EXPECT_TRUE(TextFileFailsWith("property.ply",
                                "ply\nformat ascii 1.0\nelement vertex 3\nproperty float\n"
                                "end_header\n",
                                "bad property line \"property float\""));
  EXPECT_TRUE(TextFileFailsWith("format.ply",
                                "ply\nformat binary_middle_endian 1.0\nend_header\n",
                                "unknown format \"binary_middle_endian\""));
  // Binary: bytes after the last element are data the header does not describe.
  const std::string binary_head =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string binary = binary_head;
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      binary += bytes_of(static_cast<float>(v == k + 1), false);
  binary += bytes_of<std::uint8_t>(3, false);
  for (int v = 0; v < 3; ++v)
    binary += bytes_of<std::int32_t>(v, false);
  write_text(file("binary.ply"), binary);
  EXPECT_EQ(read_error(file("binary.ply")), "");
  EXPECT_TRUE(TextFileFailsWith("binary_more.ply", binary + "\n",
                                "PLY file is malformed: 1 bytes follow the last element"));
}

TEST_F(MeshReader, HugeAnnouncedCountsAllocateNothing) {
  // Counts that a few bytes cannot back: each must end in a message, quickly and without
  // reserving what the header announces.
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 1\nproperty list uint int vertex_indices\n";
  EXPECT_TRUE(TextFileFailsWith(
      "many_vertices.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n" + xyz + faces +
          "end_header\n",
      "the header announces 4000000000 vertices, more than this reader can index"));
  EXPECT_TRUE(TextFileFailsWith(
      "many_faces.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 0\n" + xyz +
          "element face 9223372036854775807\nproperty list uint int vertex_indices\n"
          "end_header\n",
      "PLY file is truncated: face 0 of 9223372036854775807 is incomplete"));
  EXPECT_TRUE(TextFileFailsWith(
      "beyond.ply",
      "ply\nformat ascii 1.0\nelement vertex 99999999999999999999\n" + xyz + faces + "end_header\n",
      "bad element line \"element vertex 99999999999999999999\""));
  // A face whose list count (4294967295 indices) the rest of the file cannot hold.
  std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + xyz + faces +
                       "end_header\n";
  binary += std::string(36, '\0') + bytes_of<std::uint32_t>(0xffffffffu, false) +
            bytes_of<std::int32_t>(0, false);
  write_text(file("long_list.ply"), binary);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(file("long_list.ply")), file("long_list.ply"),
                                    "PLY file is truncated: face 0 of 1 is incomplete"));
  // A binary STL's count is checked against the file's size before anything is read.
  std::string stl(80, ' ');
  stl += bytes_of<std::uint32_t>(0xffffffffu, false);
  write_text(file("many.stl"), stl);
  EXPECT_TRUE(StartsWithPathAndSays(read_error(file("many.stl")), file("many.stl"),
                                    "its header announces 4294967295 triangles (214748364834 "
                                    "bytes) but the file has 84 bytes"));
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
