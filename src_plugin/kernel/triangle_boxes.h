// Per-triangle axis-aligned bounding boxes of a TriangleSoA, and the box-overlap cull that
// removes triangle pairs that cannot be in contact before any distance kernel runs.
//
// Layout: structure of arrays, one entry per triangle (index t of TriangleSoA), 64-byte
// aligned, in the same length unit as the triangles (metres in the simulation).
// Boundary meaning: two boxes "overlap with margin m" when on every axis the gap between
// them is <= m. The gap between boxes never exceeds the Euclidean distance between the
// triangles they contain, so a pair of triangles closer than m always survives the cull;
// the cull may keep pairs that are farther apart (boxes are conservative).
#pragma once

#include "aligned_vector.h"
#include "triangle_soa.h"

#include <cstdint>

namespace tri {

struct TriangleBoxes {
  AlignedVector<double> lo_x, lo_y, lo_z; // per-triangle minimum corner
  AlignedVector<double> hi_x, hi_y, hi_z; // per-triangle maximum corner

  int num_triangles() const { return static_cast<int>(lo_x.size()); }
};

// Fills `boxes` (resized; capacity kept, so repeated calls do not allocate) with the
// bounding box of every triangle of `soa`. Vectorised over triangles.
void compute_triangle_boxes(const TriangleSoA &soa, TriangleBoxes &boxes);

// keep[j] = 1 if box i of `a` and box j of `b` overlap with margin `margin` (see above),
// else 0, for j = 0 .. b.num_triangles()-1. Vectorised over j. `keep` must hold
// b.num_triangles() bytes. Returns the number of kept boxes.
int overlapping_boxes(const TriangleBoxes &a, int i, const TriangleBoxes &b, double margin,
                      std::uint8_t *keep);

} // namespace tri
