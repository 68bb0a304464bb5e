#include "interaction/kept_contacts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

// Offsets of a kept point's values (kKeptContactPointDoubles of them), a's body frame.
enum PointField {
  kPoint = 0,
  kNormal = 3,
  kOverlap = 6,
  kEnergyOverlap,
  kMinDistance,
  kMerged,
  kLabels, // tri_a, tri_b and kind in one exact integer (pack_labels)
  kPatchArea,
  kPatchMeanRadius,
  kFaceWeight,
  kDampingPoint,
  kSecondMoment = kDampingPoint + 3, // xx, yy, zz, xy, xz, yz
  kPointEnd = kSecondMoment + 6
};

void write_symmetric(const Matrix3d &m, double *out) {
  out[0] = m(0, 0);
  out[1] = m(1, 1);
  out[2] = m(2, 2);
  out[3] = m(0, 1);
  out[4] = m(0, 2);
  out[5] = m(1, 2);
}
Matrix3d read_symmetric(const double *in) {
  Matrix3d m;
  m << in[0], in[3], in[4], in[3], in[1], in[5], in[4], in[5], in[2];
  return m;
}
static_assert(kPointEnd == kKeptContactPointDoubles, "kept point layout");

// Triangle indices below 2^24 (a mesh of 16 million triangles), -1 included; kinds below 8:
// the sum stays below 2^53, so the double holds it exactly.
constexpr double kLabelBase = 33554432.0; // 2^25
double pack_labels(const ContactPoint &c, int tri_b) {
  return (c.tri_a + 1) + kLabelBase * ((tri_b + 1) + kLabelBase * static_cast<int>(c.kind));
}
void unpack_labels(double v, ContactPoint &c) {
  const auto packed = static_cast<long long>(v);
  const auto base = static_cast<long long>(kLabelBase);
  c.tri_a = static_cast<int>(packed % base) - 1;
  c.tri_b = static_cast<int>((packed / base) % base) - 1;
  c.kind = static_cast<ContactKind>(packed / (base * base));
}

RelativePose read_relative(const double *kept) {
  return {Vector3d(kept[1], kept[2], kept[3]), Quaterniond(kept[4], kept[5], kept[6], kept[7])};
}

void write_point(const ContactPoint &c, const Matrix3d &to_a, const Vector3d &origin,
                 const int *ids_b, double *out) {
  const Vector3d p = to_a * (c.point - origin), n = to_a * c.normal;
  const Vector3d d = c.patch_area > 0.0 ? Vector3d(to_a * (c.damping_point - origin)) : p;
  for (int k = 0; k < 3; ++k) {
    out[kPoint + k] = p[k];
    out[kNormal + k] = n[k];
    out[kDampingPoint + k] = d[k];
  }
  out[kPatchArea] = c.patch_area;
  out[kPatchMeanRadius] = c.patch_mean_radius;
  out[kFaceWeight] = c.face_weight;
  write_symmetric(to_a * c.patch_second_moment * to_a.transpose(), out + kSecondMoment);
  out[kOverlap] = c.overlap;
  out[kEnergyOverlap] = c.energy_overlap;
  out[kMinDistance] = c.min_distance;
  out[kMerged] = c.num_merged;
  out[kLabels] = pack_labels(c, ids_b && c.tri_b >= 0 ? ids_b[c.tri_b] : c.tri_b);
}

// b's motion relative to a since the points were kept, in a's frame: `turn`, and `moved`, where
// b's material at a point of a's frame is now.
struct RelativeMotion {
  Matrix3d turn;
  Eigen::Isometry3d moved;
};

// A kept point carried by that motion into a's frame, then placed in the world by a's pose
// (`to_world`, `origin`). The dashpot's point goes as the point does: midway between where
// a's and b's material at it went.
ContactPoint carry_point(const double *in, const RelativeMotion &m, const Matrix3d &to_world,
                         const Vector3d &origin) {
  ContactPoint c;
  const Vector3d p(in + kPoint), n0(in + kNormal);
  const Vector3d pb = m.moved * p;
  const Vector3d n = (n0 + m.turn * n0).normalized();
  const double apart = (pb - p).dot(n);
  const Vector3d d(in + kDampingPoint);
  c.point = to_world * (0.5 * (p + pb)) + origin;
  c.damping_point = to_world * (0.5 * (d + m.moved * d)) + origin;
  c.patch_area = in[kPatchArea];
  c.patch_mean_radius = in[kPatchMeanRadius];
  c.face_weight = in[kFaceWeight];
  c.patch_second_moment = to_world * read_symmetric(in + kSecondMoment) * to_world.transpose();
  c.normal = to_world * n;
  c.overlap = in[kOverlap] - apart;
  c.energy_overlap = in[kEnergyOverlap] - apart;
  c.min_distance = std::max(0.0, in[kMinDistance] + apart);
  c.num_merged = static_cast<int>(in[kMerged]);
  unpack_labels(in[kLabels], c);
  return c;
}

} // namespace

void clear_kept_contacts(double *kept) { std::fill(kept, kept + kKeptContactDoubles, 0.0); }

bool keep_after_measuring(double *kept) {
  if (kept[0] < 0.0) { // skipping after a miss
    kept[0] += 1.0;
    return false;
  }
  if (kept[0] > 0.0 && kept[kKeptContactHeader - 1] == 0.0) { // kept, never carried: a miss
    clear_kept_contacts(kept);
    kept[0] = -kKeptSkipAfterMiss;
    return false;
  }
  return true;
}

void keep_contacts(const RigidPose &a, const RigidPose &b, const std::vector<ContactPoint> &points,
                   double *kept, const int *ids_b) {
  const int n = static_cast<int>(points.size());
  const bool keepable =
      n > 0 && n <= kKeptContactPoints &&
      std::none_of(points.begin(), points.end(), [](const ContactPoint &c) {
        return c.intersecting || c.kind == ContactKind::deep || !std::isfinite(c.overlap) ||
               !c.point_is_material;
      });
  if (!keepable) {
    if (kept_state(kept))
      clear_kept_contacts(kept);
    return;
  }
  const RelativePose rel = relative_pose(a, b);
  kept[0] = n;
  kept[kKeptContactHeader - 1] = 0.0; // not carried yet
  for (int k = 0; k < 3; ++k)
    kept[1 + k] = rel.t[k];
  kept[4] = rel.r.w();
  kept[5] = rel.r.x();
  kept[6] = rel.r.y();
  kept[7] = rel.r.z();
  const Matrix3d to_a = Quaterniond(a.q).conjugate().toRotationMatrix();
  for (int k = 0; k < kKeptContactPoints; ++k) {
    double *out = kept + kKeptContactHeader + k * kKeptContactPointDoubles;
    if (k < n)
      write_point(points[k], to_a, a.x, ids_b, out);
    else
      std::fill_n(out, kKeptContactPointDoubles, 0.0);
  }
}

double kept_contacts_motion(const double *kept, const RigidPose &a, const RigidPose &b) {
  if (!contacts_kept(kept))
    return std::numeric_limits<double>::infinity();
  // A static wall (radius 0, its frame the world's) is bounded by the particle's motion alone.
  return relative_motion_bound(read_relative(kept), relative_pose(a, b), a.radius, b.radius);
}

void carry_kept_contacts(const double *kept, const RigidPose &a, const RigidPose &b,
                         std::vector<ContactPoint> &points, const int *ids_b, int count_b) {
  points.clear();
  const int n = static_cast<int>(kept[0]);
  const RelativePose then = read_relative(kept), now = relative_pose(a, b);
  // b's material at a point p of a's frame was at turn_then^-1 (p - t_then) in b's frame; it is
  // now at turn_now of that plus t_now.
  RelativeMotion m;
  m.turn = (now.r * then.r.conjugate()).normalized().toRotationMatrix();
  m.moved.linear() = m.turn;
  m.moved.translation() = now.t - m.turn * then.t;
  const Matrix3d to_world = Quaterniond(a.q).toRotationMatrix();
  for (int k = 0; k < n; ++k) {
    points.push_back(
        carry_point(kept + kKeptContactHeader + k * kKeptContactPointDoubles, m, to_world, a.x));
    if (ids_b) { // back from the kept id to b's index now
      const int id = points.back().tri_b;
      points.back().tri_b = static_cast<int>(std::find(ids_b, ids_b + count_b, id) - ids_b);
    }
  }
}

bool kept_triangles_present(const double *kept, const int *ids_b, int count_b) {
  const int n = static_cast<int>(kept[0]);
  for (int k = 0; k < n; ++k) {
    ContactPoint c;
    unpack_labels(kept[kKeptContactHeader + k * kKeptContactPointDoubles + kLabels], c);
    if (c.tri_b >= 0 && std::find(ids_b, ids_b + count_b, c.tri_b) == ids_b + count_b)
      return false;
  }
  return true;
}

} // namespace tri
