// VTK XML output of particle surfaces; see surface_writer.h.
#include "surface_writer.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLongLongArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace tri {

void SurfaceCells::append_particle(const TriangleSoA &world, const ParticleValues &p) {
  const int ntri = world.num_triangles();
  for (int t = 0; t < ntri; ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::size_t i = 3 * static_cast<std::size_t>(t) + k;
      xyz.insert(xyz.end(), {world.x[i], world.y[i], world.z[i]});
    }
    atom_id.push_back(p.id);
    shape_id.push_back(p.shape);
    type.push_back(p.type);
    velocity.insert(velocity.end(), p.velocity, p.velocity + 3);
    omega.insert(omega.end(), p.omega, p.omega + 3);
    force.insert(force.end(), p.force, p.force + 3);
    torque.insert(torque.end(), p.torque, p.torque + 3);
    orientation.insert(orientation.end(), p.orientation, p.orientation + 4);
  }
}

void SurfaceCells::clear() {
  for (auto *d : {&xyz, &velocity, &omega, &force, &torque, &orientation})
    d->clear();
  atom_id.clear();
  shape_id.clear();
  type.clear();
}

void WallCells::append_triangle(long long id, const double corners[9], const double v[3]) {
  xyz.insert(xyz.end(), corners, corners + 9);
  triangle_id.push_back(id);
  velocity.insert(velocity.end(), v, v + 3);
}

void WallCells::clear() {
  xyz.clear();
  triangle_id.clear();
  velocity.clear();
}

namespace {

namespace fs = std::filesystem;

void make_parent_directory(const std::string &path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty())
    return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec)
    throw std::runtime_error("cannot create directory '" + parent.string() + "' for '" + path +
                             "': " + ec.message());
}

void check_sizes(const std::string &path, const SurfaceCells &c) {
  const std::size_t n = c.atom_id.size();
  const bool ok = c.xyz.size() == 9 * n && c.shape_id.size() == n && c.type.size() == n &&
                  c.velocity.size() == 3 * n && c.omega.size() == 3 * n &&
                  c.force.size() == 3 * n && c.torque.size() == 3 * n &&
                  c.orientation.size() == 4 * n;
  if (!ok)
    throw std::runtime_error("inconsistent SurfaceCells array sizes for '" + path + "' (" +
                             std::to_string(n) + " triangles by atom_id)");
}

void check_sizes(const std::string &path, const WallCells &c) {
  const std::size_t n = c.triangle_id.size();
  if (c.xyz.size() != 9 * n || c.velocity.size() != 3 * n)
    throw std::runtime_error("inconsistent WallCells array sizes for '" + path + "' (" +
                             std::to_string(n) + " triangles by triangle_id)");
}

// A VTK array named `name` with `ncomp` components holding `count` tuples from `data`
// (nothing is read when count is 0, so an empty SurfaceCells still yields the full schema).
template <class Array, class T>
vtkSmartPointer<Array> make_array(const char *name, int ncomp, const std::vector<T> &data,
                                  std::size_t count) {
  static_assert(sizeof(typename Array::ValueType) == sizeof(T), "array value type mismatch");
  auto a = vtkSmartPointer<Array>::New();
  a->SetName(name);
  a->SetNumberOfComponents(ncomp);
  a->SetNumberOfTuples(static_cast<vtkIdType>(count));
  if (count > 0)
    std::memcpy(a->GetPointer(0), data.data(), count * ncomp * sizeof(T));
  return a;
}

// n triangles whose corners are xyz (9 per triangle), each with its own 3 points.
vtkSmartPointer<vtkPolyData> triangles_polydata(const std::vector<double> &xyz, std::size_t n) {
  const vtkIdType npts = static_cast<vtkIdType>(3 * n);
  vtkNew<vtkPoints> points;
  points->SetData(make_array<vtkDoubleArray>("Points", 3, xyz, 3 * n));

  // Triangle t uses points 3t, 3t+1, 3t+2: offsets 0, 3, 6, ... and connectivity 0..3n-1.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(n) + 1);
  for (vtkIdType t = 0; t <= static_cast<vtkIdType>(n); ++t)
    offsets->SetValue(t, 3 * t);
  connectivity->SetNumberOfValues(npts);
  for (vtkIdType i = 0; i < npts; ++i)
    connectivity->SetValue(i, i);
  vtkNew<vtkCellArray> triangles;
  triangles->SetData(offsets, connectivity);

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  return poly;
}

// The one place that decides what a surface file contains, used both for the pieces and for
// the declarations of the .pvtp summary, so the two cannot disagree. With schema_only the
// arrays are created empty (the summary needs names and types, not data).
vtkSmartPointer<vtkPolyData> to_polydata(const SurfaceCells &c, bool schema_only) {
  const std::size_t n = schema_only ? 0 : c.atom_id.size();
  vtkSmartPointer<vtkPolyData> poly = triangles_polydata(c.xyz, n);
  vtkCellData *cd = poly->GetCellData();
  cd->AddArray(make_array<vtkLongLongArray>("id", 1, c.atom_id, n));
  cd->AddArray(make_array<vtkIntArray>("shape", 1, c.shape_id, n));
  cd->AddArray(make_array<vtkIntArray>("type", 1, c.type, n));
  cd->AddArray(make_array<vtkDoubleArray>("velocity", 3, c.velocity, n));
  cd->AddArray(make_array<vtkDoubleArray>("omega", 3, c.omega, n));
  cd->AddArray(make_array<vtkDoubleArray>("force", 3, c.force, n));
  cd->AddArray(make_array<vtkDoubleArray>("torque", 3, c.torque, n));
  cd->AddArray(make_array<vtkDoubleArray>("orientation", 4, c.orientation, n));
  return poly;
}

vtkSmartPointer<vtkPolyData> to_polydata(const WallCells &c) {
  const std::size_t n = c.triangle_id.size();
  vtkSmartPointer<vtkPolyData> poly = triangles_polydata(c.xyz, n);
  vtkCellData *cd = poly->GetCellData();
  cd->AddArray(make_array<vtkLongLongArray>("id", 1, c.triangle_id, n));
  cd->AddArray(make_array<vtkDoubleArray>("velocity", 3, c.velocity, n));
  return poly;
}

// The VTK XML name of an array's value type (the `type` attribute of a DataArray).
std::string xml_type(vtkDataArray *a, const std::string &path) {
  switch (a->GetDataType()) {
  case VTK_DOUBLE:
    return "Float64";
  case VTK_FLOAT:
    return "Float32";
  case VTK_INT:
    return "Int32";
  case VTK_LONG_LONG:
    return "Int64";
  case VTK_ID_TYPE:
    return sizeof(vtkIdType) == 8 ? "Int64" : "Int32";
  default:
    throw std::runtime_error("no VTK XML type for array '" + std::string(a->GetName()) + "' in '" +
                             path + "'");
  }
}

std::string xml_escape(const std::string &s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&apos;";
      break;
    default:
      out += ch;
    }
  }
  return out;
}

const char *byte_order() {
  const unsigned short one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first ? "LittleEndian" : "BigEndian";
}

// Writes `text` to `path` through a temporary file in the same directory and a rename, so a
// reader (ParaView re-reading a .pvd mid-run) sees either the old or the new file, never half.
void write_text_atomically(const std::string &path, const std::string &text) {
  make_parent_directory(path);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
      throw std::runtime_error("cannot write '" + path + "' (via '" + tmp + "')");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec)
    throw std::runtime_error("cannot write '" + path + "': " + ec.message());
}

// Writes `poly` with vtkXMLPolyDataWriter: binary appended data, zlib, 64-bit headers.
void write_polydata(const std::string &path, vtkPolyData *poly) {
  make_parent_directory(path);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff(); // raw binary, not base64: smaller and faster
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64(); // block sizes beyond 4 GiB stay representable
  if (writer->Write() != 1 || writer->GetErrorCode() != 0)
    throw std::runtime_error("cannot write VTK file '" + path + "'");
}

} // namespace

void write_vtp(const std::string &path, const SurfaceCells &cells) {
  check_sizes(path, cells);
  write_polydata(path, to_polydata(cells, false));
}

void write_wall_vtp(const std::string &path, const WallCells &cells) {
  check_sizes(path, cells);
  write_polydata(path, to_polydata(cells));
}

// The summary is written here as text, not by vtkXMLPPolyDataWriter: that writer derives the
// piece names itself (<base>_<index>.vtp; CreatePieceFileName is not virtual) and produces
// the pieces from its own input, with a vtkMultiProcessController to learn about other
// ranks. Our pieces are written independently by the ranks, under names the fix chooses,
// without VTK's parallel machinery, so the writer cannot describe them. The file is a dozen
// lines, and its declarations come from the same to_polydata() as the pieces.
void write_pvtp(const std::string &path, const std::vector<std::string> &piece_files,
                const SurfaceCells &schema_example) {
  check_sizes(path, schema_example);
  const vtkSmartPointer<vtkPolyData> schema = to_polydata(schema_example, true);
  std::string x;
  x += "<?xml version=\"1.0\"?>\n";
  x += "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"";
  x += byte_order();
  x += "\" header_type=\"UInt64\">\n";
  x += "  <PPolyData GhostLevel=\"0\">\n";
  x += "    <PPoints>\n";
  x += "      <PDataArray type=\"" + xml_type(schema->GetPoints()->GetData(), path) +
       "\" Name=\"Points\" NumberOfComponents=\"3\"/>\n";
  x += "    </PPoints>\n";
  x += "    <PCellData>\n";
  vtkCellData *cd = schema->GetCellData();
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i) {
    vtkDataArray *a = cd->GetArray(i);
    x += "      <PDataArray type=\"" + xml_type(a, path) + "\" Name=\"" + xml_escape(a->GetName()) +
         "\"";
    if (a->GetNumberOfComponents() != 1)
      x += " NumberOfComponents=\"" + std::to_string(a->GetNumberOfComponents()) + "\"";
    x += "/>\n";
  }
  x += "    </PCellData>\n";
  for (const std::string &piece : piece_files)
    x += "    <Piece Source=\"" + xml_escape(piece) + "\"/>\n";
  x += "  </PPolyData>\n";
  x += "</VTKFile>\n";
  write_text_atomically(path, x);
}

void write_pvd(const std::string &path, const std::vector<std::pair<double, std::string>> &frames) {
  std::vector<PvdEntry> entries;
  for (const auto &[t, file] : frames)
    entries.push_back(PvdEntry{t, file, 0, ""});
  write_pvd_parts(path, entries);
}

void write_pvd_parts(const std::string &path, const std::vector<PvdEntry> &entries) {
  std::string x;
  x += "<?xml version=\"1.0\"?>\n";
  x += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"";
  x += byte_order();
  x += "\">\n  <Collection>\n";
  char time[32];
  for (const PvdEntry &e : entries) {
    std::snprintf(time, sizeof time, "%.17g", e.time);
    x += "    <DataSet timestep=\"";
    x += time;
    x += "\" group=\"\" part=\"" + std::to_string(e.part) + "\"";
    if (!e.name.empty())
      x += " name=\"" + xml_escape(e.name) + "\"";
    x += " file=\"" + xml_escape(e.file) + "\"/>\n";
  }
  x += "  </Collection>\n</VTKFile>\n";
  write_text_atomically(path, x);
}

} // namespace tri
