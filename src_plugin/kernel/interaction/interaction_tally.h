// Step statistics of many body interactions (particle pairs, particle-wall patches), and the
// one table that names them. The table is the single place where a counter's name, unit,
// meaning and cross-rank reduction are written: compute tri/stats takes its column order from
// it, the MPI reduction of the host layer packs and unpacks through it, the tool
// `tri-stats-columns` prints it (compute tri/stats' manual page and the deck tests take names
// from there), so reordering or adding a counter changes every reader at once.
#pragma once

#include "distance/particle_contacts.h"
#include "model/contact_force.h"

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace tri {

// Values summed by the host in a fixed order (no globals).
struct InteractionTally {
  long long body_pairs_checked = 0;    // bounding spheres overlapped: triangles were examined
  long long body_pairs_in_contact = 0; // at least one contact point
  long long contacts_before = 0;       // triangle-pair contacts
  long long contacts_after = 0;        // contact points after reduction
  long long penetrations = 0;          // interactions whose real surfaces intersect
  double max_overlap = 0.0;            // m, deepest soft-layer overlap
  double min_distance = std::numeric_limits<double>::infinity(); // m, closest triangle pair
  ContactStats distance;               // the distance kernel's own counters
  // Contacts deeper than the combined soft layer (penetration_depth.h): the count, the deepest
  // overlap in units of its layer, and the deepest depth past the layer as a fraction of what
  // the model resolves (> 1: the host stops the run).
  long long deep_contacts = 0;
  double max_overlap_layers = 0.0;
  double max_depth_of_limit = 0.0;
  double elastic_energy = 0.0; // J, summed in a fixed order (so the same on any thread count)
  long long body_pairs_passed = 0; // proven apart by the host's travel proof, never evaluated

  void add(const PairForceResult &r); // one interaction
  // n interactions the host passed over, proven apart by the travel proof (candidate_cache.h)
  // without evaluating them: what n apart_result()s would add (checked, separated), and counted.
  void add_passed(long long n) {
    body_pairs_checked += n;
    distance.bodies_separated += n;
    body_pairs_passed += n;
  }
  InteractionTally &operator+=(const InteractionTally &o);
};

enum class StatReduction { sum, max, min }; // how a column combines over threads and ranks

struct StatColumn {
  std::string name;    // what decks and tests call it: c_ID[k] is stats_columns()[k - 1]
  std::string unit;    // "1" for counts
  std::string meaning; // one line for the manual page and tri-stats-columns
  StatReduction reduction;
  // The field: a count (bin: the Newton histogram's bin, else 0) or a length; one is set.
  long long *(*count)(InteractionTally &t, int bin) = nullptr;
  double *(*length)(InteractionTally &t) = nullptr;
  int bin = 0;
  // Where that field lies in an InteractionTally, in bytes: taken from count or length once,
  // when the table is made, so that reading and writing a column is an inline load or store
  // (tallies are combined column by column several times a step, even in free flight).
  std::size_t offset = 0;

  double value(const InteractionTally &t) const { // counts as doubles (exact below 2^53)
    const char *field = reinterpret_cast<const char *>(&t) + offset;
    return count ? static_cast<double>(*reinterpret_cast<const long long *>(field))
                 : *reinterpret_cast<const double *>(field);
  }
  void assign(InteractionTally &t, double v) const {
    char *field = reinterpret_cast<char *>(&t) + offset;
    if (count)
      *reinterpret_cast<long long *>(field) = static_cast<long long>(v);
    else
      *reinterpret_cast<double *>(field) = v;
  }
};

// Every column of compute tri/stats, in its vector order.
const std::vector<StatColumn> &stats_columns();

// The column called `name`, 1-based as in c_ID[k]; 0 if there is none.
int stats_column_index(const std::string &name);

} // namespace tri
