#include "mesh_reader.h"

#include <vtkAbstractPolyDataReader.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

namespace tri {

namespace {

// VTK reports problems as text, through observers of the reporting object or, failing that,
// the process-wide vtkOutputWindow. Both routes land here, so nothing reaches stderr and
// the text can go into the exception.
class MessageCollector : public vtkOutputWindow {
public:
  static MessageCollector *New();
  vtkTypeMacro(MessageCollector, vtkOutputWindow);
  std::vector<std::string> messages;

  void DisplayText(const char *text) override { add(text); }
  void DisplayErrorText(const char *text) override { add(text); }
  void DisplayWarningText(const char *text) override { add(text); }
  void DisplayGenericWarningText(const char *text) override { add(text); }
  void DisplayDebugText(const char *) override {}
  void add(const char *text) { messages.emplace_back(text ? text : ""); }

protected:
  MessageCollector() = default;
};
vtkStandardNewMacro(MessageCollector);

void collect_event(vtkObject *, unsigned long, void *client, void *call) {
  static_cast<MessageCollector *>(client)->add(static_cast<const char *>(call));
}

// Installs a MessageCollector as VTK's output window for its lifetime. VTK's window is
// global, hence the lock (mesh files are read at set-up, so contention is harmless).
class ScopedMessageCapture {
public:
  ScopedMessageCapture() : lock_(mutex()) {
    previous_ = vtkOutputWindow::GetInstance();
    collector_ = vtkSmartPointer<MessageCollector>::New();
    vtkOutputWindow::SetInstance(collector_);
  }
  ~ScopedMessageCapture() { vtkOutputWindow::SetInstance(previous_); }
  ScopedMessageCapture(const ScopedMessageCapture &) = delete;
  ScopedMessageCapture &operator=(const ScopedMessageCapture &) = delete;

  void observe(vtkObject *object) {
    if (!object)
      return;
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(collect_event);
    command->SetClientData(collector_.GetPointer());
    object->AddObserver(vtkCommand::ErrorEvent, command);
    object->AddObserver(vtkCommand::WarningEvent, command);
  }
  const std::vector<std::string> &messages() const { return collector_->messages; }

private:
  static std::mutex &mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkSmartPointer<MessageCollector> collector_;
};

[[noreturn]] void fail(const std::string &path, const std::string &what) {
  throw MeshFileError(path + ": " + what);
}

std::string lowercase_extension(const std::string &path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Reads the whole file (mesh files are small); also proves that it is readable.
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

// Text files must hold printable ASCII and line layout only: VTK's text parsers split lines
// with C string functions (a NUL ends a line early) and words at spaces and tabs.
void check_text(const std::string &path, const std::string &bytes, std::size_t begin,
                std::size_t end, const std::string &what) {
  for (std::size_t i = begin; i < end; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if ((c < 0x20 || c > 0x7e) && c != '\n' && c != '\r' && c != '\t') {
      std::ostringstream os;
      os << what << ": byte 0x" << std::hex << int(c) << std::dec << " at offset " << i;
      fail(path, os.str());
    }
  }
}

bool starts_with_solid(const std::string &bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i])))
    ++i;
  std::string word = bytes.substr(i, 5);
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return word == "solid";
}

// vtkSTLReader reads whatever is there: a binary file cut short loses triangles silently
// and a cut ASCII file may end mid-facet. Decide the kind here and check it is complete.
void check_stl_complete(const std::string &path, const std::string &bytes) {
  constexpr std::size_t kHeader = 84, kPerTriangle = 50;
  if (bytes.size() >= kHeader) {
    const auto *p = reinterpret_cast<const unsigned char *>(bytes.data()) + 80;
    const std::uint64_t count = std::uint64_t(p[0]) | std::uint64_t(p[1]) << 8 |
                                std::uint64_t(p[2]) << 16 | std::uint64_t(p[3]) << 24;
    if (bytes.size() == kHeader + kPerTriangle * count)
      return; // binary, complete
    // Binary headers may start with "solid" too; binary data almost always holds zero bytes
    // (attribute counts, zero normal components), ASCII text never does.
    const bool has_zero_byte = bytes.find('\0', kHeader) != std::string::npos;
    if (!starts_with_solid(bytes) || has_zero_byte) {
      std::ostringstream os;
      os << "binary STL is truncated or malformed: its header announces " << count << " triangles ("
         << kHeader + kPerTriangle * count << " bytes) but the file has " << bytes.size()
         << " bytes";
      fail(path, os.str());
    }
  } else if (!starts_with_solid(bytes)) {
    std::ostringstream os;
    os << "not an STL file: " << bytes.size()
       << " bytes is too short for a binary STL (84-byte header) and it does not start with "
          "\"solid\" (ASCII STL)";
    fail(path, os.str());
  }
  // ASCII must be text throughout: vtkSTLReader decides the kind again from the bytes near
  // the start, and a few control bytes there make it read a text file as binary, trusting
  // a "triangle count" made of text (fuzzing found 2 GB allocated for an 872-byte file).
  check_text(path, bytes, 0, bytes.size(),
             "STL file is neither binary (its size is not 84 + 50 x its triangle count) nor "
             "ASCII text");
  // ASCII: the last word must be "endsolid" or follow it (endsolid [name]).
  std::string tail = bytes.substr(bytes.size() > 1024 ? bytes.size() - 1024 : 0);
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (tail.find("endsolid") == std::string::npos)
    fail(path, "ASCII STL is truncated or malformed: no \"endsolid\" line at its end");
}

// --- PLY structure check ----------------------------------------------------------------
// VTK 9.1's vtkPLYReader frees an invalid pointer (aborting the process) on a truncated file
// and does not range-check face indices. So the body is walked here first, following the
// header: every element instance must be complete and every vertex index must name a vertex.
// Nothing is kept; VTK then reads a file known to be well-formed.

struct PlyProperty {
  std::string name;
  bool is_list = false;
  std::string count_type, value_type; // count_type only for lists
};
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

int ply_type_size(const std::string &type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},   {"int8", 1},    {"uchar", 1},  {"uint8", 1},  {"short", 2}, {"int16", 2},
      {"ushort", 2}, {"uint16", 2},  {"int", 4},    {"int32", 4},  {"uint", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

bool ply_type_is_integer(const std::string &type) {
  return type.find("float") == std::string::npos && type != "double";
}

// Reads one binary integer of a PLY integer type; false at the end of the data.
bool ply_binary_integer(const std::string &bytes, std::size_t &pos, const std::string &type,
                        bool big_endian, std::int64_t &value) {
  const int size = ply_type_size(type);
  if (pos + size > bytes.size())
    return false;
  std::uint64_t u = 0;
  for (int i = 0; i < size; ++i) {
    const auto byte = static_cast<unsigned char>(bytes[pos + (big_endian ? i : size - 1 - i)]);
    u = (u << 8) | byte;
  }
  pos += size;
  const bool is_signed = type[0] != 'u';
  if (is_signed && size < 8 && (u >> (8 * size - 1)) != 0)
    u |= ~std::uint64_t(0) << (8 * size); // sign-extend
  value = static_cast<std::int64_t>(u);
  return true;
}

void check_ply_complete(const std::string &path, const std::string &bytes) {
  auto bad = [&](const std::string &what) { fail(path, "PLY file is malformed: " + what); };
  if (bytes.compare(0, 3, "ply") != 0)
    fail(path, "not a PLY file: it does not start with \"ply\"");
  // The first line that starts with end_header (a comment may mention it).
  const std::size_t line_start = bytes.find("\nend_header");
  if (line_start == std::string::npos)
    bad("no \"end_header\" line");
  const std::size_t end_header = line_start + 1;
  std::size_t body = bytes.find('\n', end_header);
  body = body == std::string::npos ? bytes.size() : body + 1;
  // VTK only stops at a line that is exactly end_header; anything else keeps it reading the
  // body as header, past the checks below.
  if (bytes.find_first_not_of(" \t\r\n", end_header + 10) < body)
    bad("\"end_header\" is not a line of its own");

  std::istringstream header(bytes.substr(0, end_header));
  std::string line, format;
  std::vector<PlyElement> elements;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
    } else if (keyword == "element") {
      // Exactly "element NAME COUNT": vtkPLY reads "1.0" as a count and then frees the
      // element's property list twice when it has none (found by fuzz_ply).
      PlyElement e;
      std::string count, extra;
      if (!(words >> e.name >> count) || (words >> extra) ||
          count.find_first_not_of("0123456789") != std::string::npos)
        bad("bad element line \"" + line + "\"");
      e.count = std::strtoull(count.c_str(), nullptr, 10);
      for (const PlyElement &other : elements)
        if (other.name == e.name)
          bad("element \"" + e.name + "\" is declared twice");
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty())
        bad("property before any element");
      PlyProperty p;
      std::string type;
      words >> type;
      if (type == "list") {
        p.is_list = true;
        words >> p.count_type >> p.value_type;
        if (!ply_type_is_integer(p.count_type) || ply_type_size(p.count_type) == 0)
          bad("list count type \"" + p.count_type + "\" is not an integer type");
      } else {
        p.value_type = type;
      }
      words >> p.name;
      if (ply_type_size(p.value_type) == 0)
        bad("unknown property type \"" + p.value_type + "\"");
      elements.back().properties.push_back(p);
    } else if (keyword != "ply" && keyword != "comment" && keyword != "obj_info") {
      // vtkPLY mistakes other header lines for data and reads through a null word pointer
      // (an empty line followed by "0 000 1", found by fuzz_ply).
      bad("unexpected header line \"" + line + "\"");
    }
  }
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    bad("unknown format \"" + format + "\"");
  for (const PlyElement &e : elements)
    if (e.properties.empty())
      bad("element \"" + e.name + "\" has no properties");
  check_text(path, bytes, 0, format == "ascii" ? bytes.size() : body,
             format == "ascii" ? "ASCII PLY file is not text" : "PLY header is not text");

  // vtkPLYReader looks these up without checking that they exist (a null dereference).
  const auto find = [&](const std::string &name) -> const PlyElement * {
    for (const PlyElement &e : elements)
      if (e.name == name)
        return &e;
    return nullptr;
  };
  const PlyElement *vertex = find("vertex"), *face = find("face");
  if (!vertex)
    bad("no \"element vertex\" in the header");
  for (const char *axis : {"x", "y", "z"}) {
    const bool found =
        std::any_of(vertex->properties.begin(), vertex->properties.end(),
                    [&](const PlyProperty &p) { return !p.is_list && p.name == axis; });
    if (!found)
      bad(std::string("the vertex element has no property ") + axis);
  }
  if (!face)
    bad("no \"element face\" in the header");
  if (std::none_of(face->properties.begin(), face->properties.end(), [](const PlyProperty &p) {
        return p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
      }))
    bad("the face element has no vertex_indices list");
  const std::uint64_t num_vertices = vertex->count;

  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  // ASCII: VTK reads each element instance from a line of its own, so the words are taken
  // line by line too (a line too short is a truncated element, whatever follows).
  std::istringstream ascii_lines(ascii ? bytes.substr(body) : std::string());
  std::istringstream tokens;
  std::size_t pos = body;
  // One integer (list count or index) or one skipped value; false at the end of the data.
  auto next_integer = [&](const std::string &type, std::int64_t &value) {
    if (!ascii)
      return ply_binary_integer(bytes, pos, type, big_endian, value);
    std::string token;
    if (!(tokens >> token))
      return false;
    char *end = nullptr;
    value = std::strtoll(token.c_str(), &end, 10);
    if (*end != '\0')
      bad("\"" + token + "\" where an integer was expected");
    return true;
  };
  // ASCII values must be numbers: vtkPLY's word splitter rewrites some words in place (a
  // value "0vertex_index" made it read through a wild pointer, found by fuzz_ply).
  auto skip_value = [&](const std::string &type) {
    if (ascii) {
      std::string token;
      if (!(tokens >> token))
        return false;
      char *end = nullptr;
      std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0')
        bad("\"" + token + "\" where a number was expected");
      return true;
    }
    pos += ply_type_size(type);
    return pos <= bytes.size();
  };

  for (const PlyElement &e : elements) {
    const bool faces = e.name == "face";
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (ascii) {
        std::string line;
        std::getline(ascii_lines, line);
        tokens.clear();
        tokens.str(line);
      }
      for (const PlyProperty &p : e.properties) {
        auto truncated = [&]() {
          std::ostringstream os;
          os << "PLY file is truncated: " << e.name << " " << i << " of " << e.count
             << " is incomplete";
          fail(path, os.str());
        };
        if (!p.is_list) {
          if (!skip_value(p.value_type))
            truncated();
          continue;
        }
        std::int64_t n = 0;
        if (!next_integer(p.count_type, n))
          truncated();
        if (n < 0)
          bad("negative list length");
        const bool indices = faces && (p.name == "vertex_indices" || p.name == "vertex_index");
        // VTK frees an empty face's index list twice (a list of 0); fewer than 3 is no face.
        if (indices && n < 3) {
          std::ostringstream os;
          os << "face " << i << " has " << n << " vertex indices (a face needs at least 3)";
          bad(os.str());
        }
        for (std::int64_t k = 0; k < n; ++k) {
          std::int64_t index = 0;
          if (indices ? !next_integer(p.value_type, index) : !skip_value(p.value_type))
            truncated();
          if (indices && (index < 0 || static_cast<std::uint64_t>(index) >= num_vertices)) {
            std::ostringstream os;
            os << "face " << i << " refers to vertex " << index << ", but there are "
               << num_vertices << " vertices";
            bad(os.str());
          }
        }
      }
    }
  }
  // Complete, but vtkPLYReader frees a face twice when the last line of an ASCII file has no
  // line end (found by fuzz_ply).
  if (ascii && bytes.size() > body && bytes.back() != '\n')
    fail(path, "PLY file is truncated: its last line has no line end");
}

// --- OBJ index check ----------------------------------------------------------------------
// vtkOBJReader range-checks none of a face's indices before it uses them: "f 1//1" in a file
// without "vn" lines, or "f 9/1 ..." with 3 vertices, reads through a null array or past the
// end of one. So every index of every face, line and point element is checked here, against
// what the file has defined up to that line (negative indices count back from there, as in
// VTK).
void check_obj_indices(const std::string &path, const std::string &bytes) {
  std::istringstream lines(bytes);
  std::string line;
  long long counts[3] = {0, 0, 0}; // v, vt, vn lines so far
  long long element = 0;           // f, l and p lines so far
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string keyword, corner;
    words >> keyword;
    if (keyword == "v" || keyword == "vt" || keyword == "vn") {
      ++counts[keyword == "v" ? 0 : keyword == "vt" ? 1 : 2];
      continue;
    }
    if (keyword != "f" && keyword != "l" && keyword != "p")
      continue;
    const long long i = element++;
    auto malformed = [&](const std::string &why) {
      std::ostringstream os;
      os << "mesh file is malformed: face " << i << " " << why;
      fail(path, os.str());
    };
    int form = -1; // VTK assumes that every corner of an element has the first one's form
    while (words >> corner) {
      // v, v/vt, v//vn or v/vt/vn: VTK takes a slash as the promise of the field after it.
      const int slashes = static_cast<int>(std::count(corner.begin(), corner.end(), '/'));
      if (slashes > 2)
        malformed("has a corner with more than two slashes: \"" + corner + "\"");
      const std::size_t slash1 = corner.find('/');
      const std::size_t slash2 = slashes == 2 ? corner.find('/', slash1 + 1) : std::string::npos;
      std::string fields[3] = {corner.substr(0, slash1)};
      if (slashes >= 1)
        fields[1] =
            corner.substr(slash1 + 1, slashes == 2 ? slash2 - slash1 - 1 : std::string::npos);
      if (slashes == 2)
        fields[2] = corner.substr(slash2 + 1);
      if (fields[0].empty() || (slashes == 1 && fields[1].empty()) ||
          (slashes == 2 && fields[2].empty()))
        malformed("has a corner with an index missing: \"" + corner + "\"");
      const int this_form = slashes + 3 * !fields[1].empty();
      if (form >= 0 && this_form != form)
        malformed("mixes the corner forms v, v/vt, v//vn and v/vt/vn: \"" + corner + "\"");
      form = this_form;
      static const char *names[3] = {"vertex", "texture coordinate", "normal"};
      static const char *plurals[3] = {"vertices", "texture coordinates", "normals"};
      for (int k = 0; k < 3; ++k) {
        if (fields[k].empty())
          continue;
        char *end = nullptr;
        errno = 0;
        const long long index = std::strtoll(fields[k].c_str(), &end, 10);
        const bool in_range =
            (index >= 1 && index <= counts[k]) || (index < 0 && index >= -counts[k]);
        if (*end != '\0' || errno != 0 || !in_range) {
          std::ostringstream os;
          os << "refers to " << names[k] << " " << fields[k] << " (1-based), but there are "
             << counts[k] << " " << (counts[k] == 1 ? names[k] : plurals[k]) << " before it";
          malformed(os.str());
        }
      }
    }
  }
}

vtkSmartPointer<vtkAbstractPolyDataReader> reader_for(const std::string &path,
                                                      const std::string &ext) {
  if (ext == ".stl") {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->MergingOff(); // merged below, exactly and in a documented way
    return reader;
  }
  if (ext == ".obj")
    return vtkSmartPointer<vtkOBJReader>::New();
  if (ext == ".ply")
    return vtkSmartPointer<vtkPLYReader>::New();
  fail(path, "unknown mesh file extension '" + ext + "' (expected .stl, .obj or .ply)");
}

// VTK messages look like "ERROR: In /build/.../vtkOBJReader.cxx, line 763\nvtkOBJReader
// (0x55d1...): Error reading file near line 8 ...": keep the part after the object address.
std::string readable_vtk_message(std::string text) {
  const std::size_t address = text.find("): ");
  if (address != std::string::npos && text.find("(0x") != std::string::npos)
    text = text.substr(address + 3);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.pop_back();
  for (char &c : text)
    if (c == '\n')
      c = ' ';
  return text;
}

void throw_if_vtk_complained(const std::string &path, const std::string &ext,
                             const std::vector<std::string> &messages) {
  if (messages.empty())
    return;
  std::ostringstream os;
  os << "cannot read mesh file ("
     << (ext == ".stl"   ? "STL"
         : ext == ".obj" ? "OBJ"
                         : "PLY")
     << "): VTK reported: " << readable_vtk_message(messages.front());
  if (messages.size() > 1)
    os << " (and " << messages.size() - 1 << " more messages)";
  fail(path, os.str());
}

void check_point_ids(const std::string &path, vtkCellArray *cells, vtkIdType num_points) {
  if (!cells)
    return;
  vtkNew<vtkIdList> ids;
  vtkIdType face = 0;
  for (cells->InitTraversal(); cells->GetNextCell(ids); ++face)
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      if (ids->GetId(k) < 0 || ids->GetId(k) >= num_points) {
        std::ostringstream os;
        os << "mesh file is malformed: face " << face << " refers to vertex " << ids->GetId(k) + 1
           << " (1-based), but there are " << num_points << " vertices";
        fail(path, os.str());
      }
}

// Triangles of `poly` as an indexed mesh with exactly equal points merged (first occurrence
// order, so the result does not depend on a hash).
TriangleMesh indexed_triangles(const std::string &path, vtkPolyData *poly) {
  TriangleMesh mesh;
  std::map<std::array<double, 3>, int> index_of;
  std::vector<int> merged(static_cast<std::size_t>(poly->GetNumberOfPoints()), -1);
  auto vertex = [&](vtkIdType id) {
    int &m = merged[static_cast<std::size_t>(id)];
    if (m < 0) {
      std::array<double, 3> p;
      poly->GetPoint(id, p.data());
      // VTK keeps floats: 1e39 in a text file becomes inf, "nan" stays NaN. Said here, with
      // the file's name (and before NaN, which compares false with everything, reaches the
      // map below and merges with whatever point it meets).
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
        std::ostringstream os;
        os << "a triangle corner has a coordinate that is not a finite 32-bit float (" << p[0]
           << ", " << p[1] << ", " << p[2] << ")";
        fail(path, os.str());
      }
      const auto [it, inserted] = index_of.emplace(p, mesh.num_vertices());
      if (inserted)
        mesh.vertices.emplace_back(p[0], p[1], p[2]);
      m = it->second;
    }
    return m;
  };
  vtkCellArray *polys = poly->GetPolys();
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);) {
    if (ids->GetNumberOfIds() != 3)
      continue; // cannot happen after vtkTriangleFilter
    mesh.triangles.push_back({vertex(ids->GetId(0)), vertex(ids->GetId(1)), vertex(ids->GetId(2))});
  }
  return mesh;
}

} // namespace

TriangleMesh read_mesh_file(const std::string &path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".stl" && ext != ".obj" && ext != ".ply")
    fail(path, "unknown mesh file extension '" + ext + "' (expected .stl, .obj or .ply)");
  const std::string bytes = file_bytes(path);
  if (bytes.empty())
    fail(path, "mesh file is empty");
  if (ext == ".stl")
    check_stl_complete(path, bytes);
  if (ext == ".ply")
    check_ply_complete(path, bytes);
  if (ext == ".obj")
    check_obj_indices(path, bytes);

  ScopedMessageCapture capture;
  vtkSmartPointer<vtkAbstractPolyDataReader> reader = reader_for(path, ext);
  reader->SetFileName(path.c_str());
  capture.observe(reader);
  capture.observe(reader->GetExecutive());
  reader->Update();
  throw_if_vtk_complained(path, ext, capture.messages());
  if (reader->GetErrorCode() != 0)
    fail(path, "cannot read mesh file: VTK reader failed (error code " +
                   std::to_string(reader->GetErrorCode()) + ")");
  vtkPolyData *raw = reader->GetOutput();
  // Before anything looks up a point: vtkOBJReader passes "f 1 2 9" with 3 vertices through.
  check_point_ids(path, raw->GetPolys(), raw->GetNumberOfPoints());
  check_point_ids(path, raw->GetStrips(), raw->GetNumberOfPoints());

  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->SetInputData(raw);
  capture.observe(triangulate);
  capture.observe(triangulate->GetExecutive());
  triangulate->Update();
  throw_if_vtk_complained(path, ext, capture.messages());

  TriangleMesh mesh = indexed_triangles(path, triangulate->GetOutput());
  if (mesh.triangles.empty())
    fail(path, "mesh file contains no triangles");
  return mesh;
}

} // namespace tri
