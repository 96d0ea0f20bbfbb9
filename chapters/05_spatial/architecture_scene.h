/// \file
/// A procedural "architecture" scene for chapter 5: a hall of axis-aligned floor, walls and
/// pillars crossed by long thin diagonal beams and slanted roof planes. The beams and roof
/// triangles have long, mostly empty boxes that overlap everything else, the case in which
/// object splits cannot separate anything and spatial splits can (real buildings, such as the
/// Sponza atrium, have the same mix of axis-aligned walls and long diagonal pieces).
#pragma once

#include <cstdint>

#include "01_base/triangle_mesh.h"

namespace rtk {

/// A hall of size 10 x 4 x 10 with `pillars` x `pillars` box pillars on the floor (12 triangles
/// each), `beams` diagonal beams of square section (12 triangles each, from one random point
/// near a wall to another near the opposite wall) and a roof of two slanted planes, each a strip
/// of `roof_strips` long thin quads. Deterministic for a seed. Triangles:
/// 2 + 8 + 12 * pillars^2 + 12 * beams + 4 * roof_strips.
TriangleMesh make_architecture(int pillars, int beams, int roof_strips, uint64_t seed);

}  // namespace rtk
