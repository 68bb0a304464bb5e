// read_mesh_file: the file's bytes, the parser its extension names, then the indexed mesh.
#include "mesh_reader.h"

#include "mesh_formats.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace tri {

namespace {

[[noreturn]] void fail(const std::string &path, const std::string &what) {
  throw MeshFileError(path + ": " + what);
}

std::string lowercase_extension(const std::string &path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The whole file (mesh files are small next to the memory a simulation uses).
std::string file_bytes(const std::string &path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status))
    fail(path, "cannot read mesh file: no such file");
  if (!std::filesystem::is_regular_file(status))
    fail(path, "cannot read mesh file: not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    fail(path, std::string("cannot open mesh file: ") + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad())
    fail(path, "error while reading mesh file");
  return bytes.str();
}

} // namespace

TriangleMesh read_mesh_file(const std::string &path) {
  const std::string ext = lowercase_extension(path);
  mesh_io::RawMesh (*parse)(std::string_view) = nullptr;
  if (ext == ".stl")
    parse = mesh_io::parse_stl;
  else if (ext == ".obj")
    parse = mesh_io::parse_obj;
  else if (ext == ".ply")
    parse = mesh_io::parse_ply;
  else
    fail(path, "unknown mesh file extension '" + ext + "' (expected .stl, .obj or .ply)");
  const std::string bytes = file_bytes(path);
  if (bytes.empty())
    fail(path, "mesh file is empty");
  try {
    return mesh_io::index_triangles(parse(bytes));
  } catch (const mesh_io::FormatError &e) {
    fail(path, e.what());
  }
}

} // namespace tri
