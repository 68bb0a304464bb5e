#include "distance/particle_contacts.h"

#include "distance/distance_kernels.h"
#include "distance/separating_axis.h"
#include "distance/triangle_boxes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace tri {

ContactStats &ContactStats::operator+=(const ContactStats &o) {
  triangle_pairs_culled += o.triangle_pairs_culled;
  contacts += o.contacts;
  bodies_separated += o.bodies_separated;
  candidates_kept += o.candidates_kept;
  contacts_carried += o.contacts_carried;
  HybridCounters::operator+=(o);
  return *this;
}

std::size_t ContactWorkspace::bytes() const {
  auto boxes = [](const TriangleBoxes &b) {
    return (b.lo_x.capacity() + b.lo_y.capacity() + b.lo_z.capacity() + b.hi_x.capacity() +
            b.hi_y.capacity() + b.hi_z.capacity()) *
           sizeof(double);
  };
  const std::size_t cull_bytes =
      (cull.index_a.capacity() + cull.index_b.capacity() + cull.keep.capacity()) * sizeof(int) +
      (cull.lo_x.capacity() + cull.lo_y.capacity() + cull.lo_z.capacity() + cull.hi_x.capacity() +
       cull.hi_y.capacity() + cull.hi_z.capacity()) *
          sizeof(double);
  const std::size_t frame_bytes =
      (frame_a.x.capacity() + frame_a.y.capacity() + frame_a.z.capacity() + frame_b.x.capacity() +
       frame_b.y.capacity() + frame_b.z.capacity()) *
      sizeof(double);
  return boxes(boxes_a) + boxes(boxes_b) + boxes(frame_boxes_a) + boxes(frame_boxes_b) +
         cull_bytes + frame_bytes + pairs.capacity() * sizeof(TrianglePairIndex) +
         results.capacity() * sizeof(TrianglePairDistance);
}

namespace {

// Fills ws.pairs[0, count) with the candidate pairs in row-major order; returns count.
// Culling: each triangle box computed once per call; the two-stage cull of
// triangle_boxes.h (keeps exactly the pairs of the full box cull).
// The tight cull (ContactOptions::tight_cull): world boxes, boxes in a frame whose first axis
// joins the centres of the two whole boxes (where tilted triangles have tight extents), then
// the separating-axis test of each surviving pair; each stage alone keeps every pair closer
// than its margin.
int tight_candidates(const TriangleSoA &a, const TriangleSoA &b, double margin,
                     ContactWorkspace &ws, const std::uint8_t *skip_b) {
  const TriangleBoxes &wa = ws.boxes_a, &wb = ws.boxes_b;
  Eigen::Vector3d axis, magnitude;
  for (int d = 0; d < 3; ++d) {
    axis[d] = 0.5 * ((wb.all_lo[d] + wb.all_hi[d]) - (wa.all_lo[d] + wa.all_hi[d]));
    magnitude[d] = std::max(std::max(std::fabs(wa.all_lo[d]), std::fabs(wa.all_hi[d])),
                            std::max(std::fabs(wb.all_lo[d]), std::fabs(wb.all_hi[d])));
  }
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length))
    return cull_triangle_pairs(wa, wb, margin, ws.cull, ws.pairs);
  // Rotated coordinates and plane distances carry rounding of a few ulps of the largest
  // coordinate: the slack of separating_axis.h covers it many times over.
  const double slack = kSeparationSlackRatio * (2.0 * magnitude.maxCoeff() + margin);
  const double frame_margin = margin + slack;
  const Eigen::Vector3d m = axis / length, u = m.unitOrthogonal(), w = m.cross(u);
  Eigen::Matrix3d frame;
  frame.row(0) = m;
  frame.row(1) = u;
  frame.row(2) = w;
  transform_soa(a, frame, Eigen::Vector3d::Zero(), ws.frame_a);
  transform_soa(b, frame, Eigen::Vector3d::Zero(), ws.frame_b);
  compute_triangle_boxes(ws.frame_a, ws.frame_boxes_a);
  compute_triangle_boxes(ws.frame_b, ws.frame_boxes_b);
  int count = cull_triangle_pairs_two_frames(wa, wb, ws.frame_boxes_a, ws.frame_boxes_b, margin,
                                             frame_margin, ws.cull, ws.pairs, skip_b);
  return separating_axis_filter(a, b, frame_margin, ws.pairs.data(), count);
}

int collect_candidates(const TriangleSoA &a, const TriangleSoA &b, double margin, bool cull,
                       bool tight, ContactWorkspace &ws, const std::uint8_t *skip_b) {
  const int na = a.num_triangles(), nb = b.num_triangles();
  const long long all = static_cast<long long>(na) * nb;
  if (!cull && all <= kMaxUnculledPairs) {
    if (ws.pairs.size() < static_cast<std::size_t>(all))
      ws.pairs.resize(static_cast<std::size_t>(all));
    TrianglePairIndex *pairs = ws.pairs.data();
    int k = 0;
    for (int i = 0; i < na; ++i)
      for (int j = 0; j < nb; ++j)
        pairs[k++] = {i, j};
    return k;
  }
  compute_triangle_boxes(a, ws.boxes_a);
  compute_triangle_boxes(b, ws.boxes_b);
  if (tight)
    return tight_candidates(a, b, margin, ws, skip_b);
  return cull_triangle_pairs(ws.boxes_a, ws.boxes_b, margin, ws.cull, ws.pairs);
}

// Runs the chosen kernel on pairs [first, last) of the list; `first` is a batch boundary.
void run_kernel(const TriangleSoA &a, const TriangleSoA &b, const ContactOptions &opt,
                const HybridSettings &hs, const TrianglePairIndex *pairs,
                TrianglePairDistance *results, int first, int last, HybridCounters &counters) {
  const int n = last - first;
  if (n <= 0)
    return;
  switch (opt.kernel) {
  case DistanceKernel::BruteForce:
    return brute_force_distances(a, b, pairs + first, n, results + first);
  case DistanceKernel::BruteForceScalar:
    return brute_force_scalar_distances(a, b, pairs + first, n, results + first);
  case DistanceKernel::Penalty:
    return penalty_distances(a, b, pairs + first, n, hs, results + first, counters);
  case DistanceKernel::Hybrid:
    return hybrid_distances(a, b, pairs + first, n, hs, 0, results + first, counters);
  case DistanceKernel::BatchedHybrid:
    return hybrid_distances(a, b, pairs + first, n, hs, opt.batch_size, results + first, counters);
  }
}

HybridSettings hybrid_settings(const ContactOptions &opt, double eps_a, double eps_b) {
  HybridSettings hs;
  hs.newton_iterations = opt.newton_iterations;
  hs.retry_iterations = opt.retry_iterations;
  hs.penalty = opt.penalty;
  // A wall has no layer of its own (its mesh is its contact surface): the particle's sets the
  // scale. A tolerance of 0 would certify no penalty result, and every wall pair would fall
  // back to brute force.
  const double thinner =
      eps_a > 0.0 && eps_b > 0.0 ? std::min(eps_a, eps_b) : std::max(eps_a, eps_b);
  hs.tolerance = opt.tolerance_ratio * thinner;
  hs.cutoff = eps_a + eps_b;
  return hs;
}

void check_options(const ContactOptions &opt) {
  if (!penalty_iterations_supported(opt.newton_iterations))
    throw std::invalid_argument("distance kernel: unsupported newton_iterations");
  if (opt.batch_size < 1)
    throw std::invalid_argument("distance kernel: batch_size must be >= 1");
}

} // namespace

double certified_tolerance(const ContactOptions &opt, double eps_a, double eps_b) {
  switch (opt.kernel) {
  case DistanceKernel::BruteForce:
  case DistanceKernel::BruteForceScalar:
    return 0.0;
  case DistanceKernel::Hybrid:
  case DistanceKernel::BatchedHybrid:
    return hybrid_settings(opt, eps_a, eps_b).tolerance;
  case DistanceKernel::Penalty:
    break;
  }
  return std::numeric_limits<double>::infinity(); // unchecked
}

int find_candidate_pairs(const TriangleSoA &a, const TriangleSoA &b, double margin,
                         const ContactOptions &opt, ContactWorkspace &ws,
                         const std::uint8_t *skip_b) {
  return collect_candidates(a, b, margin, opt.cull, opt.tight_cull, ws, skip_b);
}

void distances_among_candidates(const TriangleSoA &a, double eps_a, const TriangleSoA &b,
                                double eps_b, const ContactOptions &opt,
                                const TrianglePairIndex *pairs, int count, ContactStats &stats,
                                ContactWorkspace &ws) {
  check_options(opt);
  ws.tested = count;
  stats.triangle_pairs_tested += count;
  stats.triangle_pairs_culled +=
      static_cast<long long>(a.num_triangles()) * b.num_triangles() - count;
  ws.results.resize(static_cast<std::size_t>(count));
  const HybridSettings hs = hybrid_settings(opt, eps_a, eps_b);

  TrianglePairDistance *results = ws.results.data();
  HybridCounters counters;
  // Work is split only at multiples of `unit`, so batches stay whole and blocks full.
  const int unit = opt.kernel == DistanceKernel::BatchedHybrid ? opt.batch_size : kPairLanes;
  switch (shares_among_threads(opt, count) ? opt.parallel : ContactParallelism::None) {
  case ContactParallelism::None:
    run_kernel(a, b, opt, hs, pairs, results, 0, count, counters);
    break;
  case ContactParallelism::TrianglePairs: {
    const int units = (count + unit - 1) / unit;
#pragma omp parallel
    {
      int nthreads = 1, thread = 0;
#ifdef _OPENMP
      nthreads = omp_get_num_threads();
      thread = omp_get_thread_num();
#endif
      const int first = std::min(
          count, static_cast<int>(static_cast<long long>(units) * thread / nthreads) * unit);
      const int last = std::min(
          count, static_cast<int>(static_cast<long long>(units) * (thread + 1) / nthreads) * unit);
      HybridCounters mine;
      run_kernel(a, b, opt, hs, pairs, results, first, last, mine);
#pragma omp critical(tri_contact_counters)
      counters += mine;
    }
    break;
  }
  case ContactParallelism::Batches: {
    const int batch = opt.batch_size;
    const int batches = (count + batch - 1) / batch;
#pragma omp parallel
    {
      HybridCounters mine;
#pragma omp for schedule(static)
      for (int k = 0; k < batches; ++k)
        run_kernel(a, b, opt, hs, pairs, results, k * batch, std::min(count, (k + 1) * batch),
                   mine);
#pragma omp critical(tri_contact_counters)
      counters += mine;
    }
    break;
  }
  }
  static_cast<HybridCounters &>(stats) += counters;
}

bool shares_among_threads(const ContactOptions &opt, int count) {
  return opt.parallel != ContactParallelism::None && count >= kMinSharedPairs;
}

bool can_queue_candidates(const ContactOptions &opt, int count) {
  return opt.kernel == DistanceKernel::Hybrid && !shares_among_threads(opt, count);
}

HybridJob queue_candidates(const TriangleSoA &a, double eps_a, const TriangleSoA &b, double eps_b,
                           const ContactOptions &opt, const TrianglePairIndex *pairs, int count,
                           ContactStats &stats, const double *lower, double skip_from) {
  check_options(opt);
  stats.triangle_pairs_tested += count;
  stats.triangle_pairs_culled +=
      static_cast<long long>(a.num_triangles()) * b.num_triangles() - count;
  return HybridJob{&a, &b, pairs, count, hybrid_settings(opt, eps_a, eps_b), nullptr, lower,
                   skip_from};
}

void contacts_from_results(const TrianglePairIndex *pairs, const TrianglePairDistance *results,
                           int count, double cutoff, std::vector<TriangleContact> &out,
                           ContactStats &stats) {
  for (int k = 0; k < count; ++k) {
    const TrianglePairDistance &r = results[k];
    if (!is_triangle_contact(r, cutoff))
      continue;
    out.push_back({pairs[k].a, pairs[k].b, r.distance, r.point_a, r.point_b, r.normal,
                   r.intersecting, r.penetration_depth, certified_exact(r), certified_apart(r)});
    ++stats.contacts;
  }
}

int count_triangle_contacts(const TrianglePairDistance *results, int count, double cutoff) {
  int n = 0;
  for (int k = 0; k < count; ++k)
    n += is_triangle_contact(results[k], cutoff);
  return n;
}

} // namespace tri
