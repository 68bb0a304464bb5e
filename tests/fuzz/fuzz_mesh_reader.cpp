// libFuzzer target: tri::read_mesh_file on arbitrary bytes, then make_shape as
// fix tri/particles calls it. Built once per format (TRI_FUZZ_EXTENSION = ".stl", ".obj",
// ".ply"), since the reader dispatches on the file name.
//
// Accepted outcomes: MeshFileError from the reader, ShapeError from make_shape, or a shape.
// Anything else traps: another exception type, a mesh with no triangles or an index out of
// range, a non-finite coordinate (the reader must turn overflowing or "nan" numbers into
// MeshFileError), duplicate vertices (the reader merges exactly equal points), or a shape
// with non-finite mass properties or a non-positive volume, radius or shortest edge.
// Crashes, hangs and sanitizer reports are libFuzzer's own findings.
#include "body/shape.h"
#include "mesh_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <unistd.h>

#ifndef TRI_FUZZ_EXTENSION
#error "define TRI_FUZZ_EXTENSION"
#endif

namespace {

// The reader takes a path, so every input goes through one file per process (libFuzzer's
// -fork and -jobs modes run several processes side by side).
const std::string &input_path() {
  static const std::string path = [] {
    const char *tmp = std::getenv("TMPDIR");
    std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/tri-fuzz-XXXXXX";
    if (!mkdtemp(dir.data()))
      std::abort();
    static std::string cleanup_dir = dir;
    std::atexit([] {
      std::remove((cleanup_dir + "/input" TRI_FUZZ_EXTENSION).c_str());
      rmdir(cleanup_dir.c_str());
    });
    return dir + "/input" TRI_FUZZ_EXTENSION;
  }();
  return path;
}

void check(bool ok, const char *what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_mesh_reader: %s\n", what);
    __builtin_trap();
  }
}

void check_mesh(const tri::TriangleMesh &mesh) {
  check(!mesh.triangles.empty(), "reader returned a mesh without triangles");
  for (const auto &v : mesh.vertices)
    check(v.allFinite(), "reader returned a non-finite coordinate");
  for (const auto &t : mesh.triangles)
    for (int i : t)
      check(i >= 0 && i < mesh.num_vertices(), "reader returned a vertex index out of range");
  std::set<std::tuple<double, double, double>> distinct;
  for (const auto &v : mesh.vertices)
    distinct.emplace(v.x(), v.y(), v.z());
  check(distinct.size() == mesh.vertices.size(), "reader left exactly equal vertices unmerged");
}

void check_shape(const tri::Shape &s) {
  check(std::isfinite(s.volume) && s.volume > 0, "shape volume not finite and positive");
  // make_shape refuses moments of no solid (a folded, self-intersecting surface).
  const Eigen::Vector3d &I = s.inertia_per_density;
  check(I.allFinite() && I.minCoeff() > 0, "shape inertia not finite and positive");
  check(I.sum() - 2.0 * I.maxCoeff() >= -1e-9 * I.maxCoeff(), "shape inertia breaks I1 + I2 >= I3");
  check(std::isfinite(s.bounding_radius) && s.bounding_radius > 0, "bounding radius");
  check(std::isfinite(s.min_edge_length) && s.min_edge_length > 0, "shortest edge");
  check(s.soa.num_triangles() == s.mesh.num_triangles(), "SoA and mesh disagree");
  for (const auto &v : s.mesh.vertices)
    check(v.allFinite(), "shape has a non-finite vertex");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string &path = input_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
    if (!out)
      std::abort();
  }
  tri::TriangleMesh mesh;
  try {
    mesh = tri::read_mesh_file(path);
  } catch (const tri::MeshFileError &) {
    return 0;
  }
  check_mesh(mesh);
  try {
    check_shape(tri::make_shape("fuzz", std::move(mesh)));
  } catch (const tri::ShapeError &) {
  }
  return 0;
}
