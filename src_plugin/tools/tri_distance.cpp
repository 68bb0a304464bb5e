// tri-distance: distance and closest points of triangle pairs, for debugging the kernel and
// for comparing it with other codes.
//
//   tri-distance [--kernel bf|penalty|hybrid] [--iterations N] [--tolerance R] [FILE]
//
// Input (FILE or stdin): one pair per line, 18 numbers: the three vertices of triangle a
// (ax0 ay0 az0 ax1 ... az2), then those of triangle b. Blank lines and lines starting
// with '#' are skipped. Output: one line per pair, "distance pax pay paz pbx pby pbz"
// (closest point on a, then on b; for intersecting triangles both are a common point), with
// 17 significant digits, in the input's unit.
// --kernel: bf (brute force, default), penalty (unchecked), hybrid (penalty, brute force
// where the penalty cannot certify its result to R times the pair's longest edge).
// --iterations: Newton steps of penalty and hybrid (default 4). --tolerance: R (1e-9).
#include "distance/distance_kernels.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace {

int usage(const char *why) {
  std::cerr << "tri-distance: " << why << "\n"
            << "usage: tri-distance [--kernel bf|penalty|hybrid] [--iterations N] "
               "[--tolerance R] [FILE]\n";
  return 2;
}

} // namespace

int main(int argc, char **argv) {
  std::string kernel = "bf", file;
  tri::HybridSettings settings;
  double relative_tolerance = 1e-9;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--kernel" && has_value) {
      kernel = argv[++i];
    } else if (arg == "--iterations" && has_value) {
      settings.newton_iterations = std::atoi(argv[++i]);
    } else if (arg == "--tolerance" && has_value) {
      relative_tolerance = std::atof(argv[++i]);
    } else if (arg == "-h" || arg == "--help") {
      usage("distances of triangle pairs");
      return 0;
    } else if (!arg.empty() && arg[0] != '-' && file.empty()) {
      file = arg;
    } else {
      return usage(("unknown or incomplete argument '" + arg + "'").c_str());
    }
  }
  if (kernel != "bf" && kernel != "penalty" && kernel != "hybrid")
    return usage(("unknown kernel '" + kernel + "'").c_str());
  if (!tri::penalty_iterations_supported(settings.newton_iterations))
    return usage("unsupported --iterations (use 1..8, 10, 12, 16, 24 or 32)");
  if (!(relative_tolerance > 0))
    return usage("--tolerance must be positive");

  std::ifstream in_file;
  if (!file.empty()) {
    in_file.open(file);
    if (!in_file) {
      std::cerr << "tri-distance: cannot read '" << file << "'\n";
      return 1;
    }
  }
  std::istream &in = file.empty() ? std::cin : in_file;

  tri::TriangleSoA a, b;
  a.resize(1);
  b.resize(1);
  const tri::TrianglePairIndex pair{0, 0};
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#')
      continue;
    std::istringstream words(line);
    double v[18];
    int n = 0;
    while (n < 18 && words >> v[n])
      ++n;
    std::string rest;
    if (n != 18 || (words >> rest)) {
      std::cerr << "tri-distance: line " << line_number << ": expected 18 numbers\n";
      return 1;
    }
    double l2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int next = (k + 1) % 3;
      a.set_vertex(0, k, {v[3 * k], v[3 * k + 1], v[3 * k + 2]});
      b.set_vertex(0, k, {v[9 + 3 * k], v[9 + 3 * k + 1], v[9 + 3 * k + 2]});
      for (int side = 0; side < 2; ++side) {
        const double *t = v + 9 * side;
        const double dx = t[3 * next] - t[3 * k], dy = t[3 * next + 1] - t[3 * k + 1],
                     dz = t[3 * next + 2] - t[3 * k + 2];
        l2 = std::max(l2, dx * dx + dy * dy + dz * dz);
      }
    }
    settings.tolerance = relative_tolerance * std::sqrt(l2);
    tri::TrianglePairDistance r;
    tri::HybridCounters counters;
    if (kernel == "bf")
      tri::brute_force_distances(a, b, &pair, 1, &r);
    else if (kernel == "penalty")
      tri::penalty_distances(a, b, &pair, 1, settings, &r, counters);
    else
      tri::hybrid_distances(a, b, &pair, 1, settings, 0, &r, counters);
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", r.distance, r.point_a.x(),
                r.point_a.y(), r.point_a.z(), r.point_b.x(), r.point_b.y(), r.point_b.z());
  }
  return 0;
}
