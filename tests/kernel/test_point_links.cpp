// point_links: the components are those of the definition (every pair within the link length
// joined), whichever algorithm runs, and every root is its component's smallest index.
#include "contact/point_links.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace {

using Eigen::Vector3d;

// The definition, by brute force: label = smallest index of the component.
std::vector<int> reference_labels(const std::vector<Vector3d> &p, double link) {
  const int n = static_cast<int>(p.size());
  std::vector<int> label(n);
  for (int i = 0; i < n; ++i)
    label[i] = i;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if ((p[i] - p[j]).squaredNorm() <= link * link && label[j] < label[i]) {
          label[i] = label[j];
          changed = true;
        }
  }
  return label;
}

std::vector<int> labels_of(const std::vector<Vector3d> &p, double link) {
  std::vector<int> parent;
  tri::LinkScratch scratch;
  tri::link_points(p, link, parent, scratch);
  std::vector<int> label(p.size());
  for (int i = 0; i < static_cast<int>(p.size()); ++i)
    label[i] = tri::link_root(parent, i);
  return label;
}

// Clouds below and above the grid threshold: random points (many small components), dense
// patches (a few large ones), points on a plane (a face-to-face contact), a line of points
// exactly `link` apart (the boundary case of <=), and far-away outliers.
TEST(PointLinks, ComponentsMatchTheDefinition) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double link = 0.1;
  for (const int n : {2, 10, 12, 13, 40, 63, 64, 65, 200, 700}) {
    for (int kind = 0; kind < 4; ++kind) {
      std::vector<Vector3d> p(n);
      for (int i = 0; i < n; ++i) {
        switch (kind) {
        case 0: // sparse cloud
          p[i] = Vector3d(u(rng), u(rng), u(rng));
          break;
        case 1: // two dense patches far apart
          p[i] = Vector3d(0.2 * u(rng) + (i % 2 ? 5.0 : 0.0), 0.2 * u(rng), 0.2 * u(rng));
          break;
        case 2: // a flat patch, with an outlier every 50 points
          p[i] = i % 50 == 49 ? Vector3d(30.0 + i, 0, 0) : Vector3d(u(rng), u(rng), 1e-3 * u(rng));
          break;
        default: // a chain exactly `link` apart, in a shuffled order
          p[i] = Vector3d(1.0 + link * ((i * 37) % n), 0.5, -0.25);
          break;
        }
      }
      EXPECT_EQ(labels_of(p, link), reference_labels(p, link)) << "n " << n << " kind " << kind;
    }
  }
}

// Far from the origin (a wall mesh's coordinates): cells computed from the cloud's own corner.
TEST(PointLinks, FarFromTheOrigin) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1e-3);
  std::vector<Vector3d> p(300);
  for (Vector3d &q : p)
    q = Vector3d(1e3 + u(rng), -2e3 + u(rng), 7.0 + 0.01 * u(rng));
  const double link = 1e-4;
  EXPECT_EQ(labels_of(p, link), reference_labels(p, link));
}

} // namespace
