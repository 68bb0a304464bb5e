// The time-step rule for mesh particles, the analogue of LIGGGHTS's `fix check/timestep/gran`
// (which compares dt with the Rayleigh and Hertz times of spheres). Our normal force is a
// linear spring-dashpot, so the contact time is that of the spring:
//   t_c = pi sqrt(meff / kn)   (undamped half period; damping only lengthens it),
// taken for the SMALLEST effective mass of every pair of types (and particle type and wall
// type) that can touch. A contact needs several steps: velocity Verlet on a spring is
// unstable beyond dt = 2 / omega = (2 / pi) t_c = 0.64 t_c, and at t_c / 5 its energy error
// within one contact is already about (omega dt)^2 / 4 = 10 %. The rule:
//   ERROR    dt > t_c / 5   (kErrorFraction: fewer than 5 steps per contact)
//   WARNING  dt > t_c / 10  (kWarnFraction: fewer than 10 steps per contact)
//   WARNING  approach per step v_ref dt > epsilon / 2  (kApproachFraction: a contact met at
//            v_ref crosses more than half a soft layer per step; the run-safety check stops a
//            run at a whole epsilon once it happens in contact)
//   WARNING  peak overlap v_ref sqrt(meff / kn) (largest meff) > the two soft layers: at v_ref
//            the real surfaces would meet
// v_ref is the fastest approach the host can name (twice the fastest particle for particle
// pairs, the fastest particle for walls, at least the characteristic velocity). With an
// adaptive time step the ERROR rule tests the smallest step it may take and the contact
// WARNING the largest. Pure functions; the host prints and stops.
#pragma once

namespace tri {

constexpr double kWarnFraction = 0.1;     // of the contact time
constexpr double kErrorFraction = 0.2;    // of the contact time
constexpr double kApproachFraction = 0.5; // of epsilon per step

// pi sqrt(meff / kn) (s); infinite when kn = 0.
double linear_contact_time(double kn, double meff);

struct TimestepFigures {
  double dt_error = 0.0;       // s, the step the ERROR rule tests (dt, or dtmin if adaptive)
  double dt_warn = 0.0;        // s, the step the WARNING rules test (dt, or dtmax if adaptive)
  double contact_time = 0.0;   // s, the shortest t_c
  double approach_speed = 0.0; // m/s, v_ref (0: unknown)
  double epsilon = 0.0;        // m, the particles' soft layer
  double peak_overlap = 0.0;   // m, the deepest expected overlap at v_ref (0: unknown)
  double layers = 0.0;         // m, the soft layers of that contact (2 epsilon for two particles)
};

struct TimestepVerdict {
  double contact_fraction = 0.0;  // dt_warn / t_c
  double error_fraction = 0.0;    // dt_error / t_c
  double approach_fraction = 0.0; // v_ref dt_warn / epsilon
  double overlap_fraction = 0.0;  // peak_overlap / layers
  bool error = false;             // error_fraction > kErrorFraction
  bool warn_contact = false;      // contact_fraction > kWarnFraction (and no error)
  bool warn_approach = false;     // approach_fraction > kApproachFraction
  bool warn_overlap = false;      // overlap_fraction > 1
};

TimestepVerdict judge_timestep(const TimestepFigures &f);

} // namespace tri
