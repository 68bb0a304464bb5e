// Connected components of points under a link length; the design is in the header.
#include "contact/point_links.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

namespace tri {
namespace {

using Eigen::Vector3d;
using Cell = std::array<std::int64_t, 3>;

// Up to this many points every pair is tested, the links kept as bit sets: n^2 / 2 distances
// are cheaper than a sort, and the points of one contact are mostly within `link` of each
// other (the sweep tests those pairs too). Below the grid's threshold.
constexpr int kAllPairsLinkLimit = 63;
static_assert(kAllPairsLinkLimit < kGridLinkThreshold, "the grid takes over above");

// Union by smaller index: every root is its component's smallest index.
void unite(std::vector<int> &parent, int i, int j) {
  i = link_root(parent, i);
  j = link_root(parent, j);
  if (i < j)
    parent[j] = i;
  else if (j < i)
    parent[i] = j;
}

void sweep(const std::vector<Vector3d> &p, double link, const Vector3d &extent,
           std::vector<int> &parent, std::vector<int> &order) {
  const int n = static_cast<int>(p.size());
  int axis = 0;
  extent.maxCoeff(&axis);
  order.resize(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    return p[i][axis] != p[j][axis] ? p[i][axis] < p[j][axis] : i < j;
  });
  const double link2 = link * link;
  for (int s = 0; s < n; ++s)
    for (int t = s + 1; t < n; ++t) {
      if (p[order[t]][axis] - p[order[s]][axis] > link)
        break;
      if ((p[order[t]] - p[order[s]]).squaredNorm() <= link2)
        unite(parent, order[s], order[t]);
    }
}

void grid(const std::vector<Vector3d> &p, double link, const Vector3d &lo, double side,
          std::vector<int> &parent, LinkScratch &s) {
  const int n = static_cast<int>(p.size());
  s.cell.resize(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      s.cell[i][k] = static_cast<std::int64_t>(std::floor((p[i][k] - lo[k]) / side));
  s.order.resize(n);
  std::iota(s.order.begin(), s.order.end(), 0);
  std::sort(s.order.begin(), s.order.end(), [&](int i, int j) {
    return s.cell[i] != s.cell[j] ? s.cell[i] < s.cell[j] : i < j;
  });
  // Runs of equal cells in `order`: run r is order[runs[r] .. runs[r + 1]).
  s.runs.clear();
  for (int t = 0; t < n; ++t)
    if (t == 0 || s.cell[s.order[t]] != s.cell[s.order[t - 1]])
      s.runs.push_back(t);
  const int num_runs = static_cast<int>(s.runs.size());
  s.runs.push_back(n);
  for (int r = 0; r < num_runs; ++r)
    for (int t = s.runs[r] + 1; t < s.runs[r + 1]; ++t)
      unite(parent, s.order[s.runs[r]], s.order[t]);
  const double link2 = link * link;
  auto find_run = [&](const Cell &c) {
    int lo_r = 0, hi_r = num_runs;
    while (lo_r < hi_r) {
      const int mid = (lo_r + hi_r) / 2;
      if (s.cell[s.order[s.runs[mid]]] < c)
        lo_r = mid + 1;
      else
        hi_r = mid;
    }
    return lo_r < num_runs && s.cell[s.order[s.runs[lo_r]]] == c ? lo_r : -1;
  };
  for (int a = 0; a < num_runs; ++a) {
    const Cell ca = s.cell[s.order[s.runs[a]]];
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dz = -2; dz <= 2; ++dz) {
          const Cell cb = {ca[0] + dx, ca[1] + dy, ca[2] + dz};
          if (!(ca < cb))
            continue; // each pair of cells once
          const int b = find_run(cb);
          if (b < 0 ||
              link_root(parent, s.order[s.runs[a]]) == link_root(parent, s.order[s.runs[b]]))
            continue;
          bool joined = false;
          for (int t = s.runs[a]; t < s.runs[a + 1] && !joined; ++t)
            for (int u = s.runs[b]; u < s.runs[b + 1] && !joined; ++u)
              if ((p[s.order[t]] - p[s.order[u]]).squaredNorm() <= link2) {
                unite(parent, s.order[t], s.order[u]);
                joined = true;
              }
        }
  }
}

} // namespace

int link_root(std::vector<int> &parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

void link_points(const std::vector<Vector3d> &points, double link, std::vector<int> &parent,
                 LinkScratch &scratch) {
  const int n = static_cast<int>(points.size());
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), 0);
  if (n < 2)
    return;
  if (n <= kAllPairsLinkLimit) {
    // A contact of a few triangle pairs (most of them): every pair, no sort, the links as bit
    // sets; each component's points point at its smallest index, its root.
    using Bits = std::uint64_t;
    static_assert(kAllPairsLinkLimit <= 64, "a point's links fit in 64 bits");
    const double link2 = link * link;
    Bits linked[kAllPairsLinkLimit];
    for (int i = 0; i < n; ++i)
      linked[i] = Bits{1} << i;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if ((points[i] - points[j]).squaredNorm() <= link2) {
          linked[i] |= Bits{1} << j;
          linked[j] |= Bits{1} << i;
        }
    Bits done = 0;
    for (int i = 0; i < n; ++i) {
      if (done >> i & 1u)
        continue;
      // The component of i: its members' links, until no member is left unvisited. No member
      // lies below i (it would have been done with its own, smaller, root).
      Bits component = linked[i], visited = Bits{1} << i;
      while (component != visited) {
        const int k = __builtin_ctzll(component & ~visited);
        visited |= Bits{1} << k;
        component |= linked[k];
      }
      for (Bits rest = component; rest; rest &= rest - 1)
        parent[__builtin_ctzll(rest)] = i;
      done |= component;
    }
    return;
  }
  Vector3d lo = Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vector3d &q : points) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  // Slightly under link / sqrt(3), so that rounding never puts two points of one cell farther
  // apart than `link`.
  const double side = link / std::sqrt(3.0) * (1.0 - 1e-9);
  const bool grid_fits = (hi - lo).maxCoeff() / side < 1e15; // cell indices stay exact
  if (n >= kGridLinkThreshold && grid_fits)
    grid(points, link, lo, side, parent, scratch);
  else
    sweep(points, link, hi - lo, parent, scratch.order);
}

} // namespace tri
