/// \file
/// Procedural test scenes of any size, deterministic for a given seed: each one stresses a
/// different part of a BVH (uniform density, overlap, flat layouts, long thin triangles).
#pragma once

#include <cstdint>

#include "01_base/triangle_mesh.h"

namespace rtk::test {

/// A closed sphere: a UV sphere with `rings` x `segments` quads split into triangles, poles
/// closed by fans, all vertices shared (so the mesh is watertight as an index structure).
TriangleMesh make_sphere(int rings, int segments, Vec3f center = {0, 0, 0}, float radius = 1.0f);

/// `count` random triangles of random size (up to `max_size`) in the unit cube: heavy overlap.
TriangleMesh make_random_soup(int count, uint64_t seed, float max_size = 0.1f);

/// A height field over [0,1]^2 with `n` x `n` quads: many small triangles in a flat layer.
TriangleMesh make_terrain(int n, uint64_t seed);

/// `count` long thin triangles spanning the unit cube diagonally (slivers): boxes that are
/// mostly empty, the case where object splits do badly and spatial splits help.
TriangleMesh make_slivers(int count, uint64_t seed);

/// Adds a triangle with three collinear (or equal) vertices: it has no area and is never hit.
void add_degenerate_triangles(TriangleMesh& mesh, int count, uint64_t seed);

}  // namespace rtk::test
