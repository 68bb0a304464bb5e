#include "contact_settings.h"

#include "error.h"

#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <cstring>

namespace tri_liggghts {
namespace {

[[noreturn]] void fail(LAMMPS_NS::Error *error, const std::string &style, const std::string &msg) {
  const std::string text = style + ": " + msg;
  error->all(FLERR, text.c_str());
  std::abort();
}

bool on_off(const std::string &key, const char *value, LAMMPS_NS::Error *error,
            const std::string &style) {
  if (std::strcmp(value, "on") == 0 || std::strcmp(value, "yes") == 0)
    return true;
  if (std::strcmp(value, "off") == 0 || std::strcmp(value, "no") == 0)
    return false;
  fail(error, style, "'" + key + "' expects on or off, got '" + value + "'");
}

int positive_int(const std::string &key, const char *value, LAMMPS_NS::Error *error,
                 const std::string &style) {
  char *end = nullptr;
  const long n = std::strtol(value, &end, 10);
  if (*end != '\0' || n <= 0 || n > 1000000)
    fail(error, style, "'" + key + "' expects a positive integer, got '" + value + "'");
  return static_cast<int>(n);
}

} // namespace

int pair_loop_threads(PairLoop loop, std::size_t num_pairs) {
  if (loop != PairLoop::particle_pairs)
    return 1;
  const int max_threads = omp_get_max_threads();
  return num_pairs >= 8 * static_cast<std::size_t>(max_threads) ? max_threads : 1;
}

namespace {

// The keywords of the contact search (which kernel, how parallel, what is kept between steps).
void parse_search_keyword(const std::string &key, const char *value, ContactSettings &s,
                          const std::string &style, LAMMPS_NS::Error *error) {
  const std::string v = value;
  tri::ContactOptions &d = s.interaction.distance;
  if (key == "kernel") {
    if (v == "bf")
      d.kernel = tri::DistanceKernel::BruteForce;
    else if (v == "penalty")
      d.kernel = tri::DistanceKernel::Penalty;
    else if (v == "hybrid")
      d.kernel = tri::DistanceKernel::Hybrid;
    else if (v == "batched")
      d.kernel = tri::DistanceKernel::BatchedHybrid;
    else
      fail(error, style, "'kernel' expects bf, penalty, hybrid or batched, got '" + v + "'");
  } else if (key == "newton_iters") {
    d.newton_iterations = positive_int(key, value, error, style);
    if (!tri::penalty_iterations_supported(d.newton_iterations))
      fail(error, style, "'newton_iters " + v + "' is not one of the compiled iteration counts "
                         "(1-8, 10, 12, 16, 24, 32)");
  } else if (key == "batch") {
    d.batch_size = positive_int(key, value, error, style);
  } else if (key == "parallel") {
    if (v == "pairs") {
      s.loop = PairLoop::particle_pairs;
      d.parallel = tri::ContactParallelism::None;
    } else if (v == "triangles") {
      s.loop = PairLoop::inside_pair;
      d.parallel = tri::ContactParallelism::TrianglePairs;
    } else if (v == "batches") {
      s.loop = PairLoop::inside_pair;
      d.parallel = tri::ContactParallelism::Batches;
    } else if (v == "none") {
      s.loop = PairLoop::inside_pair;
      d.parallel = tri::ContactParallelism::None;
    } else {
      fail(error, style, "'parallel' expects pairs, triangles, batches or none, got '" + v + "'");
    }
  } else if (key == "cull") {
    if (v == "boxes") {
      d.cull = true;
      d.tight_cull = false;
    } else if (v == "yes" || v == "no" || v == "on" || v == "off") {
      d.cull = on_off(key, value, error, style);
      d.tight_cull = true;
    } else {
      fail(error, style, "'cull' expects yes, boxes or no, got '" + v + "'");
    }
  } else if (key == "coherence") {
    char *end = nullptr;
    const double r = v == "no" || v == "off" ? 0.0 : std::strtod(value, &end);
    if (end && (*end != '\0' || !(r > 0.0) || !(r <= 10.0)))
      fail(error, style, "'coherence' expects no or a reach in (0, 10] times the contact cutoff, "
                         "got '" + v + "'");
    s.interaction.coherence = r;
  } else if (key == "separation") {
    s.separation = on_off(key, value, error, style);
  } else if (key == "keep_contacts") {
    char *end = nullptr;
    const double t = v == "no" || v == "off" ? 0.0 : std::strtod(value, &end);
    if (end && (*end != '\0' || !(t > 0.0) || !(t <= 1e-2)))
      fail(error, style, "'keep_contacts' expects no or a tolerance in (0, 0.01] times the "
                         "combined soft layer, got '" + v + "'");
    s.interaction.kept_tolerance = t;
  }
}

// The keywords of the contact model (reduction, friction, damping, material model).
void parse_model_keyword(const std::string &key, const char *value, ContactSettings &s,
                         const std::string &style, LAMMPS_NS::Error *error) {
  const std::string v = value;
  tri::ContactCoefficients &c = s.interaction.coefficients;
  if (key == "reduction") {
    if (v == "clusters")
      s.interaction.reduction = tri::ReductionMethod::clusters;
    else if (v == "paper")
      s.interaction.reduction = tri::ReductionMethod::paper_min_width;
    else if (v == "none")
      s.interaction.reduction = tri::ReductionMethod::none;
    else
      fail(error, style, "'reduction' expects clusters, paper or none, got '" + v + "'");
  } else if (key == "tangential") {
    if (v == "history")
      c.tangential = tri::TangentialModel::history;
    else if (v == "no_history")
      c.tangential = tri::TangentialModel::no_history;
    else
      fail(error, style, "'tangential' expects history or no_history, got '" + v + "'");
  } else if (key == "absolute_damping") {
    c.absolute_damping = on_off(key, value, error, style);
  } else if (key == "limitForce") {
    c.limit_force = on_off(key, value, error, style);
  } else if (key == "tangential_damping") {
    c.tangential_damping = on_off(key, value, error, style);
  } else if (key == "model") {
    if (v == "hooke/stiffness")
      s.model = tri::MaterialModel::hooke_stiffness;
    else if (v == "hooke")
      s.model = tri::MaterialModel::hooke;
    else if (v == "hertz")
      s.model = tri::MaterialModel::hertz;
    else
      fail(error, style, "'model' expects hooke/stiffness, hooke or hertz, got '" + v + "'");
  }
}

} // namespace

bool parse_contact_keyword(int narg, char **arg, int *i, ContactSettings &s,
                           const std::string &style, LAMMPS_NS::Error *error) {
  const std::string key = arg[*i];
  static const char *search[] = {"kernel", "newton_iters", "batch",     "parallel",
                                 "cull",   "separation",   "coherence", "keep_contacts"};
  static const char *model[] = {"reduction", "tangential", "absolute_damping", "limitForce",
                                "tangential_damping", "model"};
  auto listed = [&key](const auto &keys) {
    return std::any_of(std::begin(keys), std::end(keys), [&key](const char *k) { return key == k; });
  };
  const bool is_search = listed(search), is_model = listed(model);
  if (!is_search && !is_model)
    return false;
  if (*i + 1 >= narg)
    fail(error, style, "missing value after '" + key + "'");
  if (is_search)
    parse_search_keyword(key, arg[*i + 1], s, style, error);
  else
    parse_model_keyword(key, arg[*i + 1], s, style, error);
  *i += 2;
  return true;
}

} // namespace tri_liggghts
