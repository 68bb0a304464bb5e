// Triangle-pair candidates kept between steps; the proof is in the header.
#include "distance/candidate_cache.h"

#include "distance/separating_axis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

void CandidateCache::record(const RigidPose *rigid, const TriangleSoA &t, Pose &out) {
  out.rigid = rigid != nullptr;
  if (rigid) {
    out.pose = *rigid;
    out.vertices.clear();
    return;
  }
  const std::size_t n = t.x.size();
  out.vertices.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    out.vertices[3 * i] = t.x[i];
    out.vertices[3 * i + 1] = t.y[i];
    out.vertices[3 * i + 2] = t.z[i];
  }
}

double CandidateCache::displacement(const Pose &then, const RigidPose *rigid, const TriangleSoA &t,
                                    double &magnitude, const Eigen::Vector3d *along) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  if (then.rigid != (rigid != nullptr))
    return kUnbounded;
  if (rigid) {
    const RigidPose &p0 = then.pose;
    if (!same_frame(p0, *rigid))
      return kUnbounded;
    magnitude = std::max(rigid->x.cwiseAbs().maxCoeff(), p0.x.cwiseAbs().maxCoeff()) +
                rigid->radius;
    const Eigen::Vector3d shift = rigid->x - p0.x;
    return (along ? along->dot(shift) : shift.norm()) + turn_bound(p0, *rigid);
  }
  const std::size_t n = t.x.size();
  if (then.vertices.size() != 3 * n || (along && n == 0))
    return kUnbounded;
  double d2 = 0.0, m = 0.0, most = -kUnbounded;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = t.x[i] - then.vertices[3 * i], dy = t.y[i] - then.vertices[3 * i + 1],
                 dz = t.z[i] - then.vertices[3 * i + 2];
    d2 = std::max(d2, dx * dx + dy * dy + dz * dz);
    if (along)
      most = std::max(most, along->x() * dx + along->y() * dy + along->z() * dz);
    m = std::max(m, std::max(std::fabs(t.x[i]), std::max(std::fabs(t.y[i]), std::fabs(t.z[i]))));
  }
  magnitude = m + std::sqrt(d2);
  return along ? most : std::sqrt(d2);
}

double CandidateCache::moved(const Pose &a, const RigidPose *pose_a, const TriangleSoA &ta,
                             const Pose &b, const RigidPose *pose_b, const TriangleSoA &tb,
                             double length, double relative_from) {
  double magnitude_a = 0.0, magnitude_b = 0.0;
  double d = displacement(a, pose_a, ta, magnitude_a) + displacement(b, pose_b, tb, magnitude_b);
  // Two particles: their relative motion may be far smaller (header). Finite d: both poses
  // are rigid and of the same frames as then.
  if (std::isfinite(d) && d >= relative_from && a.rigid && b.rigid)
    d = std::min(d, relative_motion_bound(relative_pose(a.pose, b.pose),
                                          relative_pose(*pose_a, *pose_b), pose_a->radius,
                                          pose_b->radius));
  return d + kSeparationSlackRatio * (magnitude_a + magnitude_b + std::fabs(length));
}

bool CandidateCache::covers(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                            const TriangleSoA &b, double cutoff) const {
  if (!valid_ || cutoff != cutoff_)
    return false;
  // false for NaN or an unbounded motion
  return moved(a_, pose_a, a, b_, pose_b, b, cutoff + reach_, 0.5 * reach_) < reach_;
}

double CandidateCache::skip_from(const RigidPose *pose_a, const TriangleSoA &a,
                                 const RigidPose *pose_b, const TriangleSoA &b, double cutoff) {
  base_motion_ =
      moved(base_a_, pose_a, a, base_b_, pose_b, b, cutoff + reach_, kSkipRelativeFrom * cutoff);
  return std::isfinite(base_motion_) ? cutoff + base_motion_
                                     : std::numeric_limits<double>::infinity();
}

void CandidateCache::rebase(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                            const TriangleSoA &b, const TrianglePairDistance *results) {
  // A skipped pair keeps its bound less the motion: a bound for any pair, had it run or not.
  const double shift =
      std::isfinite(base_motion_) ? base_motion_ : std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < lower_.size(); ++k)
    lower_[k] = results[k].distance == std::numeric_limits<double>::infinity()
                    ? lower_[k] - shift
                    : results[k].lower_bound;
  record(pose_a, a, base_a_);
  record(pose_b, b, base_b_);
  base_motion_ = 0.0;
}

bool CandidateCache::worth_keeping() {
  if (valid_ && uses_ == 0) {
    pause_ = kPausedSearches;
    valid_ = false;
  }
  if (pause_ > 0) {
    --pause_;
    return false;
  }
  return true;
}

bool CandidateCache::proves_apart(const RigidPose *pose_a, const TriangleSoA &a,
                                  const RigidPose *pose_b, const TriangleSoA &b, double cutoff,
                                  double *proven) const {
  if (!gap_valid_)
    return false;
  if (gap_axis_ == Eigen::Vector3d::Zero()) { // the gap can only have shrunk
    const double now = gap_ - moved(gap_a_, pose_a, a, gap_b_, pose_b, b, gap_);
    if (proven)
      *proven = now;
    return gap_ >= cutoff && now >= cutoff;
  }
  // a's vertices advancing along n close the gap, b's along -n.
  double magnitude_a = 0.0, magnitude_b = 0.0;
  const Eigen::Vector3d back = -gap_axis_;
  const double closing = displacement(gap_a_, pose_a, a, magnitude_a, &gap_axis_) +
                         displacement(gap_b_, pose_b, b, magnitude_b, &back);
  const double slack = kSeparationSlackRatio * (magnitude_a + magnitude_b + std::fabs(gap_));
  if (proven)
    *proven = gap_ - closing - slack;
  return gap_ - closing - slack >= cutoff; // false for NaN or an unbounded motion
}

void CandidateCache::keep_gap(const RigidPose *pose_a, const TriangleSoA &a,
                              const RigidPose *pose_b, const TriangleSoA &b, double gap,
                              const Eigen::Vector3d &axis) {
  gap_valid_ = std::isfinite(gap) && axis.allFinite();
  if (!gap_valid_)
    return;
  record(pose_a, a, gap_a_);
  record(pose_b, b, gap_b_);
  gap_ = gap;
  gap_axis_ = axis;
}

void CandidateCache::keep(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                          const TriangleSoA &b, double cutoff, double reach,
                          const TrianglePairIndex *pairs, int count,
                          const TrianglePairDistance *results) {
  record(pose_a, a, a_);
  record(pose_b, b, b_);
  cutoff_ = cutoff;
  reach_ = reach;
  uses_ = 0;
  base_a_ = a_;
  base_b_ = b_;
  base_motion_ = 0.0;
  pairs_.clear();
  lower_.clear();
  if (!results) {
    pairs_.assign(pairs, pairs + count);
    lower_.assign(pairs_.size(), -std::numeric_limits<double>::infinity());
  } else {
    // The slack of `moved` for no motion: the rounding of the coordinates.
    const double beyond = cutoff + reach +
                          moved(a_, pose_a, a, b_, pose_b, b, cutoff + reach,
                                std::numeric_limits<double>::infinity());
    for (int k = 0; k < count; ++k)
      if (!(results[k].lower_bound >= beyond)) {
        pairs_.push_back(pairs[k]);
        lower_.push_back(results[k].lower_bound);
      }
  }
  valid_ = true;
}

std::size_t CandidateCache::bytes() const {
  return pairs_.capacity() * sizeof(TrianglePairIndex) + lower_.capacity() * sizeof(double) +
         (a_.vertices.capacity() + b_.vertices.capacity() + base_a_.vertices.capacity() +
          base_b_.vertices.capacity() + gap_a_.vertices.capacity() +
          gap_b_.vertices.capacity()) *
             sizeof(double);
}

} // namespace tri
