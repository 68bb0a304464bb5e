// kernel_bench: throughput of the triangle contact kernels on touching particle pairs, in
// the setting of the paper's Table 1 (a particle-to-particle comparison of 40-triangle
// particles, and of 20-triangle ones): brute force scalar and SIMD, penalty, hybrid and
// batched hybrid, each with and without the box cull; the Newton histogram (the paper's
// Fig. 2, left), fallback rates and thread scaling. A program, not a test.
//
//   kernel_bench [--csv DIR] [--seconds S] [--pairs N]
//
// Prints the machine, compiler, thread count and command, then the tables. With --csv it
// also writes DIR/kernel_bench_{throughput,histogram,threads}.csv for plot_kernel_bench.py.
#include "distance/particle_contacts.h"
#include "distance/triangle_distance.h"
#include "test_particles.h"
#include "triangle_contact_search.h"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace tri;
using tri_test::find_triangle_contacts;

namespace {

struct Scene {
  TriangleSoA a, b;
};

double g_seconds = 0.3; // minimum measured time per figure

std::vector<Scene> touching_scenes(int ntri, int count, double size, double eps) {
  std::vector<Scene> scenes;
  std::mt19937_64 rng(1000 + ntri);
  for (int k = 0; k < count; ++k) {
    Scene s;
    s.a = to_soa(tri_test::test_particle(ntri, size, 10 * k + ntri));
    const TriangleSoA body = to_soa(tri_test::test_particle(ntri, size, 10 * k + ntri + 5));
    const Eigen::Vector3d dir(tri_test::uniform(rng, -1, 1), tri_test::uniform(rng, -1, 1),
                              tri_test::uniform(rng, -1, 1));
    // Gap eps: the soft layers overlap by half their width, a typical resting contact.
    s.b = tri_test::place_at_gap(s.a, body, dir, eps);
    scenes.push_back(std::move(s));
  }
  return scenes;
}

// Seconds per call of `work` (which handles all scenes once): best of 3 runs of enough
// repetitions to last g_seconds / 3 each.
double time_per_call(const std::function<void()> &work) {
  using clock = std::chrono::steady_clock;
  work(); // warm up caches and thread-local buffers
  int reps = 1;
  for (;;) {
    const auto t0 = clock::now();
    for (int r = 0; r < reps; ++r)
      work();
    const double dt = std::chrono::duration<double>(clock::now() - t0).count();
    if (dt > g_seconds / 3 || reps > (1 << 24)) {
      double best = dt / reps;
      for (int trial = 0; trial < 2; ++trial) {
        const auto t1 = clock::now();
        for (int r = 0; r < reps; ++r)
          work();
        best = std::min(best, std::chrono::duration<double>(clock::now() - t1).count() / reps);
      }
      return best;
    }
    reps *= 2;
  }
}

struct Variant {
  std::string name;
  DistanceKernel kernel;
};

const Variant kVariants[] = {
    {"brute force scalar", DistanceKernel::BruteForceScalar},
    {"brute force SIMD", DistanceKernel::BruteForce},
    {"penalty (unchecked)", DistanceKernel::Penalty},
    {"hybrid", DistanceKernel::Hybrid},
    {"batched hybrid", DistanceKernel::BatchedHybrid},
};

struct Figure {
  double us_per_particle_pair, mpairs_per_s, gflops, fallback_rate;
  ContactStats stats; // of one pass over the scenes
};

Figure measure(const std::vector<Scene> &scenes, double eps, const ContactOptions &opt) {
  ContactStats stats;
  std::vector<TriangleContact> out;
  for (const Scene &s : scenes) {
    out.clear();
    find_triangle_contacts(s.a, eps, s.b, eps, opt, out, stats);
  }
  const double t = time_per_call([&] {
    ContactStats scratch;
    for (const Scene &s : scenes) {
      out.clear();
      find_triangle_contacts(s.a, eps, s.b, eps, opt, out, scratch);
    }
  });
  const double all_pairs = static_cast<double>(scenes.front().a.num_triangles()) *
                           scenes.front().b.num_triangles() * scenes.size();
  double flops = 0.0;
  switch (opt.kernel) {
  case DistanceKernel::BruteForce:
  case DistanceKernel::BruteForceScalar:
    flops = double(stats.triangle_pairs_tested) * kBruteForceFlopsPerPair;
    break;
  default:
    flops = double(stats.penalty_pairs) * penalty_flops_per_pair(opt.newton_iterations) +
            double(stats.fallbacks) * kBruteForceFlopsPerPair;
  }
  Figure f;
  f.us_per_particle_pair = 1e6 * t / scenes.size();
  f.mpairs_per_s = all_pairs / t / 1e6;
  f.gflops = flops / t / 1e9;
  f.fallback_rate =
      stats.penalty_pairs ? double(stats.fallbacks) / double(stats.penalty_pairs) : 0.0;
  f.stats = stats;
  return f;
}

std::string machine() {
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line))
    if (line.rfind("model name", 0) == 0)
      return line.substr(line.find(':') + 2);
  return "unknown";
}

} // namespace

int main(int argc, char **argv) {
  std::string csv_dir;
  int scene_count = 32;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--csv") && i + 1 < argc)
      csv_dir = argv[++i];
    else if (!std::strcmp(argv[i], "--seconds") && i + 1 < argc)
      g_seconds = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--pairs") && i + 1 < argc)
      scene_count = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr, "usage: kernel_bench [--csv DIR] [--seconds S] [--pairs N]\n");
      return 2;
    }
  }
  const double size = 4e-3, eps = 1e-4; // DESIGN.md's deck: 4 mm rocks, 0.1 mm soft layer
  std::string command;
  for (int i = 0; i < argc; ++i)
    command += std::string(i ? " " : "") + argv[i];
  std::printf("kernel_bench: triangle contact kernels on touching particle pairs\n");
  std::printf("machine:  %s, %d hardware threads\n", machine().c_str(), omp_get_num_procs());
  std::printf("compiler: g++ %s\n", __VERSION__);
  std::printf("command:  %s\n", command.c_str());
  std::printf("setting:  %d particle pairs per size, convex bipyramid rocks of %.0f mm, "
              "epsilon %.2g m, gap epsilon (soft layers overlap by half)\n",
              scene_count, size * 1e3, eps);
  ContactOptions defaults;
  std::printf("hybrid:   %d Newton iterations, tolerance %.0e * epsilon, batch %d, "
              "penalty weight %.0e s^2, regularisation %.0e s^2\n\n",
              defaults.newton_iterations, defaults.tolerance_ratio, defaults.batch_size,
              defaults.penalty.penalty_weight, defaults.penalty.regularisation);

  std::ofstream throughput_csv, histogram_csv, threads_csv;
  if (!csv_dir.empty()) {
    throughput_csv.open(csv_dir + "/kernel_bench_throughput.csv");
    histogram_csv.open(csv_dir + "/kernel_bench_histogram.csv");
    threads_csv.open(csv_dir + "/kernel_bench_threads.csv");
    throughput_csv << "triangles,kernel,cull,us_per_particle_pair,mpairs_per_s,gflops,"
                      "fallback_rate,pairs_tested\n";
    histogram_csv << "set,iterations,pairs\n";
    threads_csv << "triangles,kernel,cull,mode,threads,us_per_particle_pair\n";
  }

  omp_set_num_threads(1);
  std::map<std::string, Figure> figures;
  for (int ntri : {40, 20}) {
    const auto scenes = touching_scenes(ntri, scene_count, size, eps);
    std::printf("== %d-triangle particles (%d x %d = %d triangle pairs per particle pair), "
                "one thread\n",
                ntri, ntri, ntri, ntri * ntri);
    std::printf("%-22s %-5s %12s %12s %9s %10s %12s\n", "kernel", "cull", "us/particle",
                "M pairs/s", "GFLOP/s", "fallback", "pairs tested");
    for (bool cull : {false, true})
      for (const Variant &v : kVariants) {
        ContactOptions opt;
        opt.kernel = v.kernel;
        opt.cull = cull;
        const Figure f = measure(scenes, eps, opt);
        figures[std::to_string(ntri) + v.name + (cull ? " cull" : "")] = f;
        std::printf("%-22s %-5s %12.2f %12.2f %9.2f %9.2f%% %12.1f\n", v.name.c_str(),
                    cull ? "yes" : "no", f.us_per_particle_pair, f.mpairs_per_s, f.gflops,
                    100 * f.fallback_rate, double(f.stats.triangle_pairs_tested) / scenes.size());
        if (throughput_csv)
          throughput_csv << ntri << ',' << v.name << ',' << cull << ',' << f.us_per_particle_pair
                         << ',' << f.mpairs_per_s << ',' << f.gflops << ',' << f.fallback_rate
                         << ',' << double(f.stats.triangle_pairs_tested) / scenes.size() << '\n';
      }
    std::printf("(M pairs/s counts all %d triangle pairs of a particle pair, culled or not; "
                "GFLOP/s counts the kernels' hand-counted flops of the pairs actually run)\n\n",
                ntri * ntri);
  }

  // Newton histogram: steps until the update is shorter than the tolerance, 32 allowed.
  std::printf("== Newton iterations to converge (step < tolerance), 40 triangles, up to %d\n",
              kMaxPenaltyIterations);
  const auto scenes40 = touching_scenes(40, scene_count, size, eps);
  for (bool cull : {false, true}) {
    ContactOptions opt;
    opt.kernel = DistanceKernel::Penalty;
    opt.newton_iterations = kMaxPenaltyIterations;
    opt.cull = cull;
    ContactStats stats;
    std::vector<TriangleContact> out;
    for (const Scene &s : scenes40)
      find_triangle_contacts(s.a, eps, s.b, eps, opt, out, stats);
    const std::string set = cull ? "pairs kept by the cull" : "all pairs";
    std::printf("%-24s", set.c_str());
    for (int k = 1; k <= 12; ++k)
      std::printf(" %d:%.1f%%", k, 100.0 * stats.newton_histogram[k] / stats.penalty_pairs);
    long long later = 0;
    for (int k = 13; k <= kMaxPenaltyIterations; ++k)
      later += stats.newton_histogram[k];
    std::printf(" 13-32:%.1f%% never:%.1f%%\n", 100.0 * later / stats.penalty_pairs,
                100.0 * stats.newton_histogram[0] / stats.penalty_pairs);
    if (histogram_csv)
      for (int k = 0; k <= kMaxPenaltyIterations; ++k)
        histogram_csv << set << ',' << k << ',' << stats.newton_histogram[k] << '\n';
  }

  // Fallback rate against the iteration count.
  std::printf("\n== Hybrid fallback rate and time against Newton iterations, 40 triangles, "
              "one thread\n%-10s %14s %14s %14s %14s\n",
              "iterations", "fallback", "us (no cull)", "fallback cull", "us (cull)");
  for (int it : {2, 3, 4, 5, 6, 8, 12}) {
    ContactOptions opt;
    opt.newton_iterations = it;
    opt.cull = false;
    const Figure f0 = measure(scenes40, eps, opt);
    opt.cull = true;
    const Figure f1 = measure(scenes40, eps, opt);
    std::printf("%-10d %13.2f%% %14.2f %13.2f%% %14.2f\n", it, 100 * f0.fallback_rate,
                f0.us_per_particle_pair, 100 * f1.fallback_rate, f1.us_per_particle_pair);
  }

  // Thread scaling inside one particle pair, and over particle pairs.
  const int max_threads = std::max(2, omp_get_num_procs());
  std::printf("\n== Thread scaling, 40 triangles, us per particle pair\n");
  std::printf("%-16s %-5s %-16s", "kernel", "cull", "parallel");
  for (int t = 1; t <= max_threads; t *= 2)
    std::printf(" %9d thr", t);
  std::printf("\n");
  struct Mode {
    const char *name;
    ContactParallelism p;
  };
  const Mode modes[] = {{"triangle pairs", ContactParallelism::TrianglePairs},
                        {"batches", ContactParallelism::Batches},
                        {"particle pairs", ContactParallelism::None}};
  for (DistanceKernel kernel : {DistanceKernel::Hybrid, DistanceKernel::BatchedHybrid})
    for (bool cull : {false, true})
      for (const Mode &m : modes) {
        const char *kname = kernel == DistanceKernel::Hybrid ? "hybrid" : "batched hybrid";
        std::printf("%-16s %-5s %-16s", kname, cull ? "yes" : "no", m.name);
        for (int t = 1; t <= max_threads; t *= 2) {
          omp_set_num_threads(t);
          ContactOptions opt;
          opt.kernel = kernel;
          opt.cull = cull;
          opt.parallel = m.p;
          double seconds;
          if (m.p == ContactParallelism::None) { // the caller's loop over particle pairs
            seconds = time_per_call([&] {
#pragma omp parallel
              {
                std::vector<TriangleContact> out;
                ContactStats stats;
#pragma omp for schedule(static)
                for (std::size_t k = 0; k < scenes40.size(); ++k) {
                  out.clear();
                  find_triangle_contacts(scenes40[k].a, eps, scenes40[k].b, eps, opt, out, stats);
                }
              }
            });
          } else {
            std::vector<TriangleContact> out;
            seconds = time_per_call([&] {
              ContactStats stats;
              for (const Scene &s : scenes40) {
                out.clear();
                find_triangle_contacts(s.a, eps, s.b, eps, opt, out, stats);
              }
            });
          }
          const double us = 1e6 * seconds / scenes40.size();
          std::printf(" %13.2f", us);
          if (threads_csv)
            threads_csv << 40 << ',' << kname << ',' << cull << ',' << m.name << ',' << t << ','
                        << us << '\n';
        }
        std::printf("\n");
      }
  omp_set_num_threads(1);

  // The speed floors the kernel must keep, as ratios within this run, and the reference
  // code's figures.
  const Figure &bf_scalar = figures["40brute force scalar"];
  const Figure &hybrid_nocull = figures["40hybrid"];
  const Figure &hybrid_cull = figures["40hybrid cull"];
  const Figure &batched_cull = figures["40batched hybrid cull"];
  std::printf("\n== Floors (40 triangles, one thread)\n");
  std::printf("hybrid without culling / brute force scalar throughput: %.2fx (floor 3x)\n",
              hybrid_nocull.mpairs_per_s / bf_scalar.mpairs_per_s);
  std::printf("touching pair, hybrid with culling: %.2f us (floor 25 us); batched: %.2f us\n",
              hybrid_cull.us_per_particle_pair, batched_cull.us_per_particle_pair);
  std::printf("reference code (DESIGN.md, same machine): brute force 2.9 M pairs/s, penalty "
              "6.2 M pairs/s, touching 40-triangle pair 412 us brute force, 298 us batched "
              "hybrid\n");
  std::printf("this code: brute force scalar %.2f M pairs/s, brute force SIMD %.2f, penalty "
              "%.2f; touching pair %.2f us brute force SIMD (no cull), %.2f us batched hybrid "
              "(cull)\n",
              bf_scalar.mpairs_per_s, figures["40brute force SIMD"].mpairs_per_s,
              figures["40penalty (unchecked)"].mpairs_per_s,
              figures["40brute force SIMD"].us_per_particle_pair,
              batched_cull.us_per_particle_pair);
  return 0;
}
