// Shared by the distance fuzz targets: turning fuzzer bytes into bounded coordinates, the
// error allowances of the brute-force reference, and the trap that reports a finding.
#pragma once

#include "distance/triangle_distance.h"
#include "geometry/distance_primitives.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tri_fuzz {

// A mismatch must stop the process: libFuzzer then saves the input as a crash artefact.
inline void require(bool ok, const char *what, double got = NAN, double want = NAN) {
  if (!ok) {
    std::fprintf(stderr, "fuzz check failed: %s (got %.17g, reference %.17g)\n", what, got, want);
    __builtin_trap();
  }
}

// Reads fuzzer bytes front to back; past the end it yields zeros, so every input decodes.
class ByteReader {
public:
  ByteReader(const std::uint8_t *data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  template <class T> T value() {
    unsigned char raw[sizeof(T)] = {};
    for (auto &c : raw)
      c = byte();
    T v;
    std::memcpy(&v, raw, sizeof v);
    return v;
  }

private:
  const std::uint8_t *data_;
  std::size_t size_, pos_ = 0;
};

// Coordinates in [-scale, scale]. Coarse grids make the exact coincidences (shared vertices,
// coplanar faces, parallel edges, touching pairs) that the kernels treat specially; raw
// doubles reach everything in between. `mode` picks the encoding.
inline double coordinate(ByteReader &in, int mode, double scale) {
  switch (mode) {
  case 0: // 1/32 grid
    return static_cast<std::int8_t>(in.byte()) / 128.0 * scale;
  case 1: // 1/32768 grid
    return static_cast<std::int16_t>(in.value<std::uint16_t>()) / 32768.0 * scale;
  default: { // any double, folded into range; non-finite values become 0
    const double v = in.value<double>();
    if (!std::isfinite(v))
      return 0.0;
    // Below 1e-12 of the scale, 0: squared lengths of 1e-300 underflow and would test the
    // floating-point format rather than the kernels (the supported scales are 1e-6 .. 1e3).
    const double folded = std::fmod(v, 1.0);
    return std::abs(folded) < 1e-12 ? 0.0 : folded * scale;
  }
  }
}

inline double scale_of(std::uint8_t selector) {
  static const double scales[4] = {1e-6, 1e-3, 1.0, 1e3}; // the kernel tests' range
  return scales[selector & 3];
}

// Longest edge of the pair.
inline double longest_edge(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  double l = 0.0;
  for (int k = 0; k < 3; ++k)
    l = std::max({l, (a[(k + 1) % 3] - a[k]).norm(), (b[(k + 1) % 3] - b[k]).norm()});
  return l;
}

// The brute force's own error beyond rounding (triangle_distance.h, kSliverRatio in
// distance_primitives.h), either sign: a sliver face is replaced by its edges (up to
// kSliverRatio x the longest edge), and a face just above the sliver cut has a normal
// rounded by ~1e-16 / (|n| / l^2), which moves its feet off the plane by that much x l.
inline double sliver_allowance(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  const auto relative_error = [](const Eigen::Vector3d t[3]) {
    const tri::geom::P3 p[3] = {{t[0].x(), t[0].y(), t[0].z()},
                                {t[1].x(), t[1].y(), t[1].z()},
                                {t[2].x(), t[2].y(), t[2].z()}};
    const tri::geom::Face f = tri::geom::face_of(p);
    if (!f.ok)
      return 2 * tri::geom::kSliverRatio;
    return 4e-16 * f.l2 / std::sqrt(tri::geom::dot(f.n, f.n));
  };
  return std::max(relative_error(a), relative_error(b)) * longest_edge(a, b);
}

// Closest pair within the touch tolerance is reported as touching; near that line the
// intersecting flag of two correct computations may differ by rounding.
inline double touch_band(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  return 4 * tri::kTouchRatio * longest_edge(a, b);
}

// TRI_FUZZ_PRINT=1 prints each decoded input, to turn a crash file into a test case.
inline bool print_inputs() {
  static const bool on = std::getenv("TRI_FUZZ_PRINT") != nullptr;
  return on;
}
inline void print_triangle(const char *name, const Eigen::Vector3d t[3]) {
  std::fprintf(stderr, "%s:", name);
  for (int k = 0; k < 3; ++k)
    std::fprintf(stderr, " {%.17g, %.17g, %.17g}", t[k].x(), t[k].y(), t[k].z());
  std::fprintf(stderr, "\n");
}

inline bool finite(const tri::TrianglePairDistance &d) {
  return std::isfinite(d.distance) && d.point_a.allFinite() && d.point_b.allFinite() &&
         d.normal.allFinite() && std::isfinite(d.penetration_depth);
}

} // namespace tri_fuzz
