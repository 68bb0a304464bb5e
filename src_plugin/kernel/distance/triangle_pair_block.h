// A block of kPairLanes triangle pairs gathered into lane-major arrays, the unit of work of
// the vectorised kernels (brute_force_block, penalty_block): lane l of every array belongs to
// pair l, so one SIMD register holds the same coordinate of 8 pairs (AVX-512) of the block.
//
// Why 16 lanes, two registers' worth: a Newton step of the penalty is one long chain of
// dependent operations (an LDL^T with four divisions), so a block of one register's width
// waits on latency; two independent registers per operation overlap, and the first penalty
// run of a settled pile took 5 % of a step instead of 8.5 % (32 lanes gained nothing more).
// Each lane's result is the same bits at any width (tested: half blocks, splits, jobs).
//
// Layout: c[k][l] with k = 9 * side + 3 * vertex + axis, side 0 = triangle of particle a,
// side 1 = triangle of particle b, vertex 0..2, axis 0..2 (x, y, z). Lengths in the
// caller's unit. Kernels always process full blocks: callers pad unused lanes with a copy
// of a used one, so every pair runs through the same instructions whatever its position,
// which is what makes results independent of the thread count.
#pragma once

#include "geometry/triangle_soa.h"

#include <Eigen/Core>

namespace tri {

constexpr int kPairLanes = 16;

struct alignas(64) TrianglePairBlock {
  double c[18][kPairLanes];

  // Copies triangle ta of a and triangle tb of b into lane l.
  void set_lane(int l, const TriangleSoA &a, int ta, const TriangleSoA &b, int tb) {
    const std::size_t ia = 3 * static_cast<std::size_t>(ta);
    const std::size_t ib = 3 * static_cast<std::size_t>(tb);
    for (int v = 0; v < 3; ++v) {
      c[3 * v + 0][l] = a.x[ia + v];
      c[3 * v + 1][l] = a.y[ia + v];
      c[3 * v + 2][l] = a.z[ia + v];
      c[9 + 3 * v + 0][l] = b.x[ib + v];
      c[9 + 3 * v + 1][l] = b.y[ib + v];
      c[9 + 3 * v + 2][l] = b.z[ib + v];
    }
  }
  void set_lane(int l, const Eigen::Vector3d ta[3], const Eigen::Vector3d tb[3]) {
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) {
        c[3 * v + k][l] = ta[v][k];
        c[9 + 3 * v + k][l] = tb[v][k];
      }
  }
  void copy_lane(int from, int to) {
    for (int k = 0; k < 18; ++k)
      c[k][to] = c[k][from];
  }
  void get_lane(int l, Eigen::Vector3d ta[3], Eigen::Vector3d tb[3]) const {
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) {
        ta[v][k] = c[3 * v + k][l];
        tb[v][k] = c[9 + 3 * v + k][l];
      }
  }
};

} // namespace tri
