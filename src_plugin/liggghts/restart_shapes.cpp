// The global restart record of fix tri/particles; see restart_shapes.h.
#include "restart_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace tri_liggghts {
namespace {

constexpr char kMagic[8] = {'t', 'r', 'i', '/', 'r', 's', 't', '3'};
// The record before the layer field: every layer outside the meshes.
constexpr char kMagicLayerOutside[8] = {'t', 'r', 'i', '/', 'r', 's', 't', '2'};

template <class T> void put(std::vector<char> &out, const T &v) {
  const char *p = reinterpret_cast<const char *>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

template <class T> T get(const char *&p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  p += sizeof(T);
  return v;
}

bool close(double a, double b) {
  return std::fabs(a - b) <= 1e-9 * std::max(std::fabs(a), std::fabs(b));
}

// Two values with just enough significant digits that they print differently (%g's 6 at
// least; 6 when they are equal).
std::pair<std::string, std::string> distinct(double a, double b) {
  char sa[40], sb[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(sa, sizeof sa, "%.*g", digits, a);
    std::snprintf(sb, sizeof sb, "%.*g", digits, b);
    if (std::strcmp(sa, sb) != 0)
      return {sa, sb};
  }
  std::snprintf(sa, sizeof sa, "%g", a);
  std::snprintf(sb, sizeof sb, "%g", b);
  return {sa, sb};
}

// "'rock40': 40 triangles, volume 3.1e-09 m^3"; where name, triangles and volume agree with
// `other` (the shape it is compared with), also the bounding radius and the moments, each
// with the digits that show the difference.
std::string describe(const ShapeRecord &s, const ShapeRecord &other) {
  std::string d = "'" + s.name + "': " + std::to_string(s.triangles) + " triangles, volume " +
                  distinct(s.volume, other.volume).first + " m^3";
  if (s.name != other.name || s.triangles != other.triangles || !close(s.volume, other.volume))
    return d;
  if (!close(s.bounding_radius, other.bounding_radius))
    d += ", bounding radius " + distinct(s.bounding_radius, other.bounding_radius).first + " m";
  bool moments = false;
  for (int k = 0; k < 3; ++k)
    moments = moments || !close(s.inertia_per_density[k], other.inertia_per_density[k]);
  if (moments) {
    d += ", principal moments per density";
    for (int k = 0; k < 3; ++k)
      d += " " + distinct(s.inertia_per_density[k], other.inertia_per_density[k]).first;
    d += " m^5";
  }
  return d;
}

bool same(const ShapeRecord &a, const ShapeRecord &b) {
  bool eq = a.name == b.name && a.triangles == b.triangles && close(a.volume, b.volume) &&
            close(a.bounding_radius, b.bounding_radius);
  for (int k = 0; k < 3; ++k)
    eq = eq && close(a.inertia_per_density[k], b.inertia_per_density[k]);
  return eq;
}

std::string names(const std::vector<ShapeRecord> &shapes) {
  std::string n;
  for (const ShapeRecord &s : shapes)
    n += (n.empty() ? "" : ", ") + s.name;
  return n;
}

} // namespace

ParticlesRecord make_record(const std::vector<tri::Shape> &shapes, double epsilon, double density,
                            bool layer_inside) {
  ParticlesRecord r;
  r.epsilon = epsilon;
  r.layer_inside = layer_inside;
  r.density = density;
  for (const tri::Shape &s : shapes) {
    ShapeRecord sr;
    sr.name = s.name;
    sr.triangles = s.soa.num_triangles();
    sr.volume = s.volume;
    sr.bounding_radius = s.bounding_radius;
    for (int k = 0; k < 3; ++k)
      sr.inertia_per_density[k] = s.inertia_per_density[k];
    r.shapes.push_back(sr);
  }
  return r;
}

std::vector<char> encode(const ParticlesRecord &r) {
  std::vector<char> out(kMagic, kMagic + sizeof kMagic);
  put(out, r.epsilon);
  put(out, r.density);
  put(out, static_cast<std::int64_t>(r.layer_inside ? 1 : 0));
  put(out, static_cast<std::int64_t>(r.shapes.size()));
  for (const ShapeRecord &s : r.shapes) {
    put(out, static_cast<std::int64_t>(s.name.size()));
    out.insert(out.end(), s.name.begin(), s.name.end());
    put(out, static_cast<std::int64_t>(s.triangles));
    put(out, s.volume);
    put(out, s.bounding_radius);
    for (double m : s.inertia_per_density)
      put(out, m);
  }
  return out;
}

ParticlesRecord decode(const char *buf) {
  const bool layer_field = std::memcmp(buf, kMagic, sizeof kMagic) == 0;
  if (!layer_field && std::memcmp(buf, kMagicLayerOutside, sizeof kMagic) != 0)
    throw std::runtime_error(
        "the restart file was written by an earlier liggghts-tri, whose restart files carry no "
        "shape record and cannot be read by this version: rerun the deck that wrote it");
  const char *p = buf + sizeof kMagic;
  ParticlesRecord r;
  r.epsilon = get<double>(p);
  r.density = get<double>(p);
  r.layer_inside = layer_field && get<std::int64_t>(p) != 0;
  // Bounds against a damaged file (a count or length read from garbage); far above real use.
  const char *damaged = "the restart file's fix tri/particles record is damaged";
  const auto n = get<std::int64_t>(p);
  if (n < 0 || n > 1000000)
    throw std::runtime_error(damaged);
  for (std::int64_t k = 0; k < n; ++k) {
    ShapeRecord s;
    const auto len = get<std::int64_t>(p);
    if (len < 0 || len > 100000)
      throw std::runtime_error(damaged);
    s.name.assign(p, static_cast<std::size_t>(len));
    p += len;
    s.triangles = get<std::int64_t>(p);
    s.volume = get<double>(p);
    s.bounding_radius = get<double>(p);
    for (double &m : s.inertia_per_density)
      m = get<double>(p);
    r.shapes.push_back(s);
  }
  return r;
}

std::string differences(const ParticlesRecord &file, const ParticlesRecord &deck) {
  std::vector<std::string> d;
  auto scalar = [&d](const char *what, double a, double b) {
    if (a == b)
      return;
    auto [sa, sb] = distinct(a, b);
    d.push_back(std::string(what) + " " + sa + " in the restart file, " + sb + " in this deck");
  };
  scalar("epsilon", file.epsilon, deck.epsilon);
  scalar("density", file.density, deck.density);
  auto where = [](bool inside) { return inside ? "'layer inside'" : "'layer outside'"; };
  if (file.layer_inside != deck.layer_inside)
    d.push_back(std::string("the soft layer ") + where(file.layer_inside) +
                " in the restart file" +
                (file.layer_inside ? "" : " (every file before the layer moved inside)") + ", " +
                where(deck.layer_inside) + " in this deck (give fix tri/particles " +
                where(file.layer_inside) + " to continue it)");
  const std::size_t nf = file.shapes.size(), nd = deck.shapes.size();
  if (nf != nd)
    d.push_back(std::to_string(nf) + " shape" + (nf == 1 ? "" : "s") + " in the restart file (" +
                names(file.shapes) + "), " + std::to_string(nd) + " in this deck (" +
                names(deck.shapes) + ")");
  for (std::size_t k = 0; k < std::min(nf, nd); ++k) {
    const ShapeRecord &a = file.shapes[k], &b = deck.shapes[k];
    if (!same(a, b))
      d.push_back("shape " + std::to_string(k + 1) + " " + describe(a, b) +
                  " in the restart file; " + describe(b, a) + " in this deck");
  }
  std::string all;
  for (const std::string &s : d)
    all += (all.empty() ? "" : "; ") + s;
  return all;
}

} // namespace tri_liggghts
