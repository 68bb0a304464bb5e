// Every style of Debian's LIGGGHTS 3.8 (as `liggghts -h` lists them), classified by what it
// does beside fix tri/particles. The one source of:
//   - the refusals: fix tri/particles stops a run at init with an ERROR for every refused fix,
//     compute and pair style of its deck (incompatible_styles.cpp), and pair tri/gran names a
//     refused pair gran sub-model keyword (cohesion, rolling_friction, surface);
//   - the compatibility matrix of src_plugin/doc/from_spheres.md (tri-style-matrix --markdown);
//   - the test that runs one short deck per style (tests/decks/test_style_matrix.py) and fails
//     on a style of `liggghts -h` that this table does not classify.
// The table is plain data: no LIGGGHTS header, so the tool can print it without LIGGGHTS.
#pragma once

#include <cstddef>

namespace tri_liggghts {

// The sections of `liggghts -h`, in its order. The pair gran sub-models are keywords of pair
// gran, listed by LIGGGHTS as styles of their own.
enum class StyleKind {
  atom_style,
  run_style,
  pair_style,
  gran_model,      // pair gran model ...
  gran_tangential, // pair gran tangential ...
  gran_cohesion,   // pair gran cohesion ...
  gran_rolling,    // pair gran rolling_friction ...
  gran_surface,    // pair gran surface ...
  fix,
  compute,
  region,
  dump,
  command,
};

enum class StyleClass {
  works,      // as with spheres; `note` may add a remark
  meaning,    // runs, with the meaning `note` states (the particle as a point at its centre of
              // mass, or as a sphere of its contact reach)
  refused,    // an ERROR at run (or at the command): `note` says why ("it ..."), `instead`
              // what to use
  irrelevant, // belongs to models mesh particles do not take part in (SPH, CFD coupling,
              // molecules, bonds); `note` says which. Runs or stops with LIGGGHTS's own ERROR.
};

struct StyleRow {
  StyleKind kind;
  const char *style;
  StyleClass cls;
  const char *note;
  const char *instead; // refused: what to use ("" where the message builds it); else ""
};

struct StyleTable {
  const StyleRow *rows;
  std::size_t size;
  const StyleRow *begin() const { return rows; }
  const StyleRow *end() const { return rows + size; }
};

StyleTable style_matrix();

// The row of a style, or nullptr when the table does not have it.
const StyleRow *find_style(StyleKind kind, const char *style);

// "fix", "compute", "pair_style", "pair gran cohesion", ...: how a deck writes the kind.
const char *kind_name(StyleKind kind);
const char *class_name(StyleClass cls);

} // namespace tri_liggghts
