// Connected components of a point set under "closer than a link length" (contact_reduction.h,
// step 1: which raw contacts belong to one contact patch).
//
// Three algorithms with the same result -- the components are a property of the point set, and
// every root is the component's smallest index whatever the order of the unions:
//  * below kGridLinkThreshold points, every pair, the links as bit sets and the components
//    read off them (no sort, no union-find): the few raw contacts of an ordinary contact;
//  * a sweep along the axis of largest extent, pair tests within `link` along it (where the
//    grid's cell indices would not be exact): it tests every pair within `link` of each
//    other, quadratic for the dense raw contacts of two finely meshed faces pressed together
//    (two 4 mm cubes with edges of 2 epsilon: 66 % of a 0.45 s step);
//  * above kGridLinkThreshold points, a grid of cells of side link / sqrt(3): all points of one
//    cell are within `link` of each other (one union each, no test), and two cells can hold
//    linked points only if they are at most two cells apart along every axis; for each such pair
//    of cells the tests stop at the first linked pair of points, or are skipped when the cells
//    are already joined.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace tri {

constexpr int kGridLinkThreshold = 64;

// Scratch space, reused between calls to avoid allocations.
struct LinkScratch {
  std::vector<int> order, runs;
  std::vector<std::array<std::int64_t, 3>> cell;
};

// The union-find root of i (path halving).
int link_root(std::vector<int> &parent, int i);

// parent (resized to points.size()): union-find forest of the components of `points` under
// |p_i - p_j| <= link, each root the smallest index of its component. link > 0.
void link_points(const std::vector<Eigen::Vector3d> &points, double link, std::vector<int> &parent,
                 LinkScratch &scratch);

} // namespace tri
