// Per-triangle axis-aligned bounding boxes of a TriangleSoA, and the box-overlap cull that
// removes triangle pairs that cannot be in contact before any distance kernel runs.
//
// Layout: structure of arrays, one entry per triangle (index t of TriangleSoA), 64-byte
// aligned, in the same length unit as the triangles (metres in the simulation).
// Boundary meaning: two boxes "overlap with margin m" when on every axis the gap between
// them is <= m. The gap between boxes never exceeds the Euclidean distance between the
// triangles they contain, so a pair of triangles closer than m always survives the cull;
// the cull may keep pairs that are farther apart (boxes are conservative).
//
// Two-stage cull (cull_triangle_pairs): stage 1 tests every triangle box of a against the
// whole box of b and every triangle box of b against the whole box of a (each grown by the
// margin on the side where the pair test grows it); stage 2 runs the pair test only among
// the survivors of both. Since a triangle box lies inside its whole box and x -> fl(x + m)
// is monotone, every pair the full pair test keeps survives stage 1, so the two-stage
// cull keeps exactly the pairs of the full cull (same floating-point comparisons), in the
// same order (a index, then b index, ascending).
#pragma once

#include "distance/distance_kernels.h"
#include "geometry/aligned_vector.h"
#include "geometry/triangle_soa.h"

#include <cstdint>
#include <vector>

namespace tri {

struct TriangleBoxes {
  AlignedVector<double> lo_x, lo_y, lo_z; // per-triangle minimum corner
  AlignedVector<double> hi_x, hi_y, hi_z; // per-triangle maximum corner
  // Box of all triangles (componentwise min of lo / max of hi); filled by
  // compute_triangle_boxes. Empty set: lo = +inf, hi = -inf (overlaps nothing).
  double all_lo[3] = {0, 0, 0}, all_hi[3] = {0, 0, 0};

  int num_triangles() const { return static_cast<int>(lo_x.size()); }
};

// Fills `boxes` (resized; capacity kept, so repeated calls do not allocate) with the
// bounding box of every triangle of `soa`, and their whole box. Vectorised over triangles.
void compute_triangle_boxes(const TriangleSoA &soa, TriangleBoxes &boxes);

// keep[j] = 1 if box i of `a` and box j of `b` overlap with margin `margin` (see above),
// else 0, for j = 0 .. b.num_triangles()-1. Vectorised over j. `keep` must hold
// b.num_triangles() bytes. Returns the number of kept boxes. (The single-row full cull;
// cull_triangle_pairs keeps the same pairs at a fraction of the cost.)
int overlapping_boxes(const TriangleBoxes &a, int i, const TriangleBoxes &b, double margin,
                      std::uint8_t *keep);

// Stage 1, a side: writes to `index` (ascending) every i whose box in `a` overlaps the box
// [lo, hi] (the whole box of b) with margin `margin`, growing a's box as the pair test
// does. Returns the count. `index` must hold a.num_triangles() ints.
int boxes_near_box_as_a(const TriangleBoxes &a, const double lo[3], const double hi[3],
                        double margin, int *index);
// Stage 1, b side: the same for the boxes of `b` against [lo, hi] (the whole box of a),
// growing [lo, hi] as the pair test grows a's boxes.
int boxes_near_box_as_b(const double lo[3], const double hi[3], const TriangleBoxes &b,
                        double margin, int *index);

// Scratch of cull_triangle_pairs (reuse it across calls: nothing is allocated once grown).
struct CullScratch {
  AlignedVector<int> index_a, index_b;     // stage-1 survivors
  AlignedVector<double> lo_x, lo_y, lo_z;  // boxes of b's survivors, compacted
  AlignedVector<double> hi_x, hi_y, hi_z;
  AlignedVector<std::int32_t> keep;        // stage-2 mask of one row
};

// Two-stage cull of all pairs (i of a, j of b): writes to `pairs` every pair whose boxes
// overlap with margin `margin`, exactly the pairs overlapping_boxes keeps, in row-major
// order (i, then j ascending). Returns the number of pairs written: the first entries of
// `pairs`, which grows as needed (never shrinks, so a reused vector stops allocating). Its
// size follows the pairs kept, not na * nb: two touching 1e5-triangle shapes keep about 1e5
// pairs of 1e10.
int cull_triangle_pairs(const TriangleBoxes &a, const TriangleBoxes &b, double margin,
                        CullScratch &scratch, std::vector<TrianglePairIndex> &pairs);

// The same cull in two frames at once: `a`, `b` are the world-frame boxes,
// `fa`, `fb` the boxes of the same triangles in a second orthonormal frame (rotated
// coordinates, e.g. with its first axis along the line between the bodies, where world boxes
// of tilted triangles are loose). A pair is kept only if its boxes overlap with `margin` in
// the world frame and with `frame_margin` in the second frame; each test alone keeps every
// pair closer than its margin (a box gap along any unit axis is at most the distance), so the
// intersection does too. Stage 1 tests each triangle against the other body's whole box in
// both frames, stage 2 the pairs of survivors; kept pairs in row-major order, as above.
// frame_margin must cover the rounding of the rotated coordinates (particle_contacts.cpp adds
// separating_axis.h's slack).
// `skip_b` (optional, b.num_triangles() entries): b's triangles already known to be farther
// than the margin from all of a (nonzero: dropped in stage 1).
int cull_triangle_pairs_two_frames(const TriangleBoxes &a, const TriangleBoxes &b,
                                   const TriangleBoxes &fa, const TriangleBoxes &fb, double margin,
                                   double frame_margin, CullScratch &scratch,
                                   std::vector<TrianglePairIndex> &pairs,
                                   const std::uint8_t *skip_b = nullptr);

// Unit normals of every triangle (SoA: n_x[t], n_y[t], n_z[t]) and the plane offsets
// n . v0; a degenerate triangle gets a zero normal (it then separates nothing). (The plane
// test of wall triangles, body_interaction.cpp.)
struct TrianglePlanes {
  AlignedVector<double> n_x, n_y, n_z, offset;
};
void compute_triangle_planes(const TriangleSoA &soa, TrianglePlanes &planes);

// Separating-axis filter: drops pair k of pairs[0, count) when the two triangles are proven
// farther apart than `margin` along one of the 11 axes of the separating-axis test (the two
// face normals, the nine cross products of an edge of each): all vertices of one project more
// than margin (times the axis length) beyond all vertices of the other. A projection gap
// never exceeds the distance, so no pair closer than `margin` is dropped. Vectorised across
// pairs (blocks of kPairLanes, as the distance kernels); keeps the order of the survivors;
// returns their count. `margin` must cover rounding (particle_contacts.cpp adds the slack of
// separating_axis.h).
int separating_axis_filter(const TriangleSoA &a, const TriangleSoA &b, double margin,
                           TrianglePairIndex *pairs, int count);

} // namespace tri
