#include "particle_options.h"

#include "error.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>

namespace tri_liggghts {
namespace {

class ArgReader {
public:
  ArgReader(int narg, char **arg, int first, LAMMPS_NS::Error *error)
      : narg_(narg), arg_(arg), i_(first), error_(error) {}

  bool done() const { return i_ >= narg_; }
  std::string peek() const { return done() ? std::string() : std::string(arg_[i_]); }
  std::string word(const std::string &what) {
    if (done())
      fail("missing " + what + " at the end of the command");
    return arg_[i_++];
  }
  double real(const std::string &keyword) {
    const std::string s = word("value after '" + keyword + "'");
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
      fail("'" + keyword + "' expects a number, got '" + s + "'");
    return v;
  }
  long long integer(const std::string &keyword) {
    const std::string s = word("value after '" + keyword + "'");
    char *end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (end == s.c_str() || *end != '\0' || errno == ERANGE)
      fail("'" + keyword + "' expects an integer, got '" + s + "'");
    return v;
  }
  [[noreturn]] void fail(const std::string &message) {
    const std::string text = "Fix tri/particles: " + message;
    error_->all(FLERR, text.c_str());
    std::abort(); // error->all does not return
  }

private:
  int narg_;
  char **arg_;
  int i_;
  LAMMPS_NS::Error *error_;
};

ShapeSpec parse_shape(ArgReader &in) {
  ShapeSpec s;
  s.name = in.word("shape name after 'shape'");
  const std::string kind = in.word("'random' or 'file' after 'shape " + s.name + "'");
  if (kind == "file") {
    s.from_file = true;
    s.path = in.word("file name after 'shape " + s.name + " file'");
    if (in.peek() == "scale") {
      in.word("scale");
      s.scale = in.real("scale");
      if (!(s.scale > 0.0))
        in.fail("'scale' of shape " + s.name + " must be > 0");
    }
    return s;
  }
  if (kind != "random")
    in.fail("shape " + s.name + ": expected 'random' or 'file', got '" + kind + "'");
  bool have_ntri = false, have_size = false, have_seed = false;
  for (;;) {
    const std::string key = in.peek();
    if (key == "ntri") {
      in.word(key);
      const long long n = in.integer("ntri");
      if (n < 4 || n % 2 != 0 || n > 100000)
        in.fail("shape " + s.name + ": 'ntri' must be an even number from 4 to 100000, got " +
                std::to_string(n));
      s.ntri = static_cast<int>(n);
      have_ntri = true;
    } else if (key == "size") {
      in.word(key);
      s.size = in.real("size");
      if (!(s.size > 0.0))
        in.fail("shape " + s.name + ": 'size' must be > 0");
      have_size = true;
    } else if (key == "seed") {
      in.word(key);
      const long long seed = in.integer("seed");
      if (seed < 0)
        in.fail("shape " + s.name + ": 'seed' must be >= 0");
      s.seed = static_cast<std::uint64_t>(seed);
      have_seed = true;
    } else if (key == "aspect") {
      in.word(key);
      s.aspect_middle = in.real("aspect");
      s.aspect_short = in.real("aspect");
      if (!(s.aspect_middle > 0.0 && s.aspect_middle <= 1.0 && s.aspect_short > 0.0 &&
            s.aspect_short <= s.aspect_middle))
        in.fail("shape " + s.name + ": 'aspect B C' needs 0 < C <= B <= 1");
    } else {
      break;
    }
  }
  if (!have_ntri || !have_size || !have_seed)
    in.fail("shape " + s.name + " random needs 'ntri', 'size' and 'seed'");
  return s;
}

double epsilon_value(ArgReader &in) {
  if (in.done())
    in.word("value after 'epsilon'");
  const std::string s = in.peek();
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    in.fail("'epsilon' expects a number (m) or 'auto', got '" + s + "'");
  in.word("epsilon");
  if (!(v > 0.0))
    in.fail("'epsilon' must be > 0");
  return v;
}

int check_timestep_value(ArgReader &in) {
  const std::string s = in.word("'setup', 'off' or a number of steps after 'check_timestep'");
  if (s == "setup")
    return 0;
  if (s == "off")
    return -1;
  char *end = nullptr;
  errno = 0;
  const long long n = std::strtoll(s.c_str(), &end, 10);
  if (end == s.c_str() || *end != '\0' || errno == ERANGE || n <= 0 || n > 1000000000)
    in.fail("'check_timestep' expects setup, off or a positive number of steps, got '" + s + "'");
  return static_cast<int>(n);
}

} // namespace

ParticleOptions parse_particle_options(int narg, char **arg, int first, LAMMPS_NS::Error *error) {
  ArgReader in(narg, arg, first, error);
  ParticleOptions o;
  bool have_density = false, have_epsilon = false;
  std::set<std::string> names;
  std::vector<std::pair<std::string, std::string>> templates; // shapes may come later
  while (!in.done()) {
    const std::string key = in.word("keyword");
    if (key == "shape") {
      ShapeSpec s = parse_shape(in);
      if (!names.insert(s.name).second)
        in.fail("shape name '" + s.name + "' is used twice");
      o.shapes.push_back(s);
    } else if (key == "assign") {
      const std::string mode = in.word("'random SEED' or 'type' after 'assign'");
      if (mode == "type") {
        o.assign_by_type = true;
      } else if (mode == "random") {
        const long long seed = in.integer("assign random");
        if (seed < 0)
          in.fail("'assign random' seed must be >= 0");
        o.assign_by_type = false;
        o.assign_seed = static_cast<std::uint64_t>(seed);
      } else {
        in.fail("'assign' expects 'random SEED' or 'type', got '" + mode + "'");
      }
    } else if (key == "density") {
      o.density = in.real("density");
      if (!(o.density > 0.0))
        in.fail("'density' must be > 0");
      have_density = true;
    } else if (key == "epsilon") {
      if (in.peek() == "auto") {
        in.word("auto");
        o.epsilon_auto = true;
        o.epsilon = 0.0;
      } else {
        o.epsilon = epsilon_value(in);
        o.epsilon_auto = false;
      }
      have_epsilon = true;
    } else if (key == "layer") {
      const std::string where = in.word("'inside' or 'outside' after 'layer'");
      if (where != "inside" && where != "outside")
        in.fail("'layer' expects 'inside' or 'outside', got '" + where + "'");
      o.layer_inside = where == "inside";
    } else if (key == "check_timestep") {
      o.check_timestep_every = check_timestep_value(in);
    } else if (key == "orient") {
      const std::string mode = in.word("'random SEED', 'none' or 'file' after 'orient'");
      if (mode == "none" || mode == "file") {
        o.orient_random = false;
        o.orient_file = mode == "file";
      } else if (mode == "random") {
        const long long seed = in.integer("orient random");
        if (seed < 0)
          in.fail("'orient random' seed must be >= 0");
        o.orient_random = true;
        o.orient_file = false;
        o.orient_seed = static_cast<std::uint64_t>(seed);
      } else {
        in.fail("'orient' expects 'random SEED', 'none' or 'file', got '" + mode + "'");
      }
    } else if (key == "template") {
      const std::string id = in.word("fix particletemplate/sphere ID after 'template'");
      const std::string shape = in.word("shape name after 'template " + id + "'");
      for (const auto &t : templates)
        if (t.first == id)
          in.fail("'template " + id + "' is given twice");
      templates.emplace_back(id, shape);
    } else {
      in.fail("unknown keyword '" + key + "'");
    }
  }
  if (o.shapes.empty())
    in.fail("at least one 'shape' is required");
  if (!have_density)
    in.fail("'density' is required");
  if (!have_epsilon)
    o.epsilon_auto = true; // resolved from the contact material (material_scales.h)
  for (const auto &[id, shape] : templates) {
    int index = -1;
    for (std::size_t k = 0; k < o.shapes.size(); ++k)
      if (o.shapes[k].name == shape)
        index = static_cast<int>(k);
    if (index < 0)
      in.fail("'template " + id + " " + shape + "': no shape is named '" + shape + "'");
    o.templates.emplace_back(id, index);
  }
  return o;
}

} // namespace tri_liggghts
