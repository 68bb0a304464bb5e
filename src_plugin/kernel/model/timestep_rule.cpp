// The time-step rule; thresholds and reasons in the header.
#include "model/timestep_rule.h"

#include <cmath>
#include <limits>

namespace tri {

double linear_contact_time(double kn, double meff) {
  if (!(kn > 0.0))
    return std::numeric_limits<double>::infinity();
  return 3.14159265358979323846 * std::sqrt(meff / kn);
}

TimestepVerdict judge_timestep(const TimestepFigures &f) {
  TimestepVerdict v;
  if (f.contact_time > 0.0 && std::isfinite(f.contact_time)) {
    v.contact_fraction = f.dt_warn / f.contact_time;
    v.error_fraction = f.dt_error / f.contact_time;
  }
  if (f.epsilon > 0.0)
    v.approach_fraction = f.approach_speed * f.dt_warn / f.epsilon;
  if (f.layers > 0.0)
    v.overlap_fraction = f.peak_overlap / f.layers;
  v.error = v.error_fraction > kErrorFraction;
  v.warn_contact = !v.error && v.contact_fraction > kWarnFraction;
  v.warn_approach = v.approach_fraction > kApproachFraction;
  v.warn_overlap = v.overlap_fraction > 1.0;
  return v;
}

} // namespace tri
