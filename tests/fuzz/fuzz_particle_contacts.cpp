// libFuzzer target: find_triangle_contacts on two small triangle sets (particle_contacts.h).
// Every kernel, culled or not, must report the contacts of the unculled scalar brute force:
// the same (tri_a, tri_b) pairs in the same order, distances within the hybrid tolerance
// (1e-4 eps, as test_particle_contacts.cpp), the same intersecting verdict, unit normals.
// Culling must not change the brute force's result at all.
//
// Input: byte 0 = scale (bits 0-1) and coordinate encoding (bits 2-3, fuzz_common.h);
// byte 1 = triangles of a (1..8, low nibble) and of b (high nibble); byte 2 = eps in
// 1/1024 of the scale (eps_b = eps_a x (1 + byte 3 / 64)); byte 4 = Newton iterations and
// batch size; then the coordinates, a's triangles first.
#include "distance/particle_contacts.h"
#include "fuzz_common.h"
#include "triangle_contact_search.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace tri;
using tri_fuzz::require;
using tri_test::find_triangle_contacts;

namespace {

TriangleSoA read_triangles(tri_fuzz::ByteReader &in, int ntri, int mode, double scale) {
  TriangleSoA soa;
  soa.resize(ntri);
  for (int t = 0; t < ntri; ++t)
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d v;
      for (int c = 0; c < 3; ++c)
        v[c] = tri_fuzz::coordinate(in, mode, scale);
      soa.set_vertex(t, k, v);
    }
  return soa;
}

std::vector<TriangleContact> contacts(const TriangleSoA &a, double eps_a, const TriangleSoA &b,
                                      double eps_b, const ContactOptions &opt) {
  std::vector<TriangleContact> out;
  ContactStats stats;
  find_triangle_contacts(a, eps_a, b, eps_b, opt, out, stats);
  require(stats.contacts == static_cast<long long>(out.size()), "stats: contacts");
  require(stats.triangle_pairs_tested + stats.triangle_pairs_culled ==
              static_cast<long long>(a.num_triangles()) * b.num_triangles(),
          "stats: tested + culled != all pairs");
  return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  tri_fuzz::ByteReader in(data, size);
  const std::uint8_t head = in.byte(), counts = in.byte(), eps_byte = in.byte(),
                     eps_ratio = in.byte(), kernel_byte = in.byte();
  const double scale = tri_fuzz::scale_of(head);
  const int mode = (head >> 2) & 3;
  const int na = 1 + (counts & 7), nb = 1 + ((counts >> 4) & 7);
  const double eps_a = (1 + eps_byte) / 1024.0 * scale;
  const double eps_b = eps_a * (1 + eps_ratio / 64.0);
  static const int iteration_choices[4] = {1, 4, 6, 8};
  const int iterations = iteration_choices[kernel_byte & 3];
  const int batch = 1 + ((kernel_byte >> 2) & 15);
  const TriangleSoA a = read_triangles(in, na, mode, scale);
  const TriangleSoA b = read_triangles(in, nb, mode, scale);

  ContactOptions ref_opt;
  ref_opt.kernel = DistanceKernel::BruteForceScalar;
  ref_opt.cull = false;
  const auto ref = contacts(a, eps_a, b, eps_b, ref_opt);
  const double cutoff = eps_a + eps_b;
  const double tolerance = ref_opt.tolerance_ratio * std::min(eps_a, eps_b);
  const double rounding = 1e-12 * scale;

  // Per pair: the brute force's own error and touch band, for the allowances below.
  auto pair_allowances = [&](int ta, int tb) {
    Eigen::Vector3d x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = a.vertex(ta, k);
      y[k] = b.vertex(tb, k);
    }
    return std::make_pair(tri_fuzz::sliver_allowance(x, y), tri_fuzz::touch_band(x, y));
  };
  std::map<std::pair<int, int>, const TriangleContact *> ref_by_pair;
  for (const auto &c : ref) {
    require(tri_fuzz::finite(TrianglePairDistance{c.distance, c.point_a, c.point_b, c.normal,
                                                  c.intersecting, c.penetration_depth}),
            "brute force contact: non-finite");
    require(c.distance < cutoff, "brute force contact at or beyond the cutoff", c.distance, cutoff);
    ref_by_pair[{c.tri_a, c.tri_b}] = &c;
  }

  for (auto kernel :
       {DistanceKernel::BruteForce, DistanceKernel::Hybrid, DistanceKernel::BatchedHybrid})
    for (bool cull : {false, true}) {
      ContactOptions opt;
      opt.kernel = kernel;
      opt.cull = cull;
      opt.newton_iterations = iterations;
      opt.batch_size = batch;
      const auto got = contacts(a, eps_a, b, eps_b, opt);
      if (kernel == DistanceKernel::BruteForce) {
        // Same operations as the scalar reference and a cull that never drops a contact.
        require(got.size() == ref.size(), "brute force (block) contact count", got.size(),
                ref.size());
        for (std::size_t k = 0; k < ref.size(); ++k)
          require(got[k].tri_a == ref[k].tri_a && got[k].tri_b == ref[k].tri_b &&
                      got[k].distance == ref[k].distance &&
                      got[k].intersecting == ref[k].intersecting,
                  "brute force (block) differs from scalar", got[k].distance, ref[k].distance);
        continue;
      }
      std::map<std::pair<int, int>, const TriangleContact *> got_by_pair;
      for (std::size_t k = 0; k < got.size(); ++k) {
        const TriangleContact &c = got[k];
        if (k > 0)
          require(std::make_pair(got[k - 1].tri_a, got[k - 1].tri_b) <
                      std::make_pair(c.tri_a, c.tri_b),
                  "contacts not sorted by (tri_a, tri_b)");
        require(std::abs(c.normal.norm() - 1.0) <= 1e-12, "hybrid contact: normal not unit",
                c.normal.norm());
        require(c.point_a.allFinite() && c.point_b.allFinite() && c.penetration_depth >= 0,
                "hybrid contact: non-finite point or negative depth");
        got_by_pair[{c.tri_a, c.tri_b}] = &c;
      }
      // Pairs on only one side must sit on the cutoff within the brute force's own error.
      for (const auto &[key, c] : got_by_pair)
        if (!ref_by_pair.count(key)) {
          const double sliver = pair_allowances(key.first, key.second).first;
          Eigen::Vector3d x[3], y[3];
          for (int k = 0; k < 3; ++k) {
            x[k] = a.vertex(key.first, k);
            y[k] = b.vertex(key.second, k);
          }
          const double d = triangle_distance(x, y).distance;
          require(d < cutoff + rounding + sliver, "hybrid reports a pair brute force does not",
                  c->distance, d);
        }
      for (const auto &[key, r] : ref_by_pair) {
        const auto [sliver, band] = pair_allowances(key.first, key.second);
        const auto it = got_by_pair.find(key);
        if (it == got_by_pair.end()) {
          require(r->distance >= cutoff - rounding - sliver, "hybrid misses a brute-force contact",
                  NAN, r->distance);
          continue;
        }
        const TriangleContact &c = *it->second;
        require(std::abs(c.distance - r->distance) <= tolerance + rounding + sliver,
                "hybrid contact distance off brute force", c.distance, r->distance);
        require(c.intersecting == r->intersecting ||
                    std::max(c.distance, r->distance) <= band + tolerance + sliver,
                "hybrid contact: intersecting verdict differs", c.distance, r->distance);
      }
    }
  return 0;
}
