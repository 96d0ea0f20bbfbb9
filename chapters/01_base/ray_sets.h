/// \file
/// Ray generators for tests: deterministic for a seed, and aimed at the cases that break
/// traversal code (rays from inside, misses, grazing rays, zero direction components).
#pragma once

#include <cstdint>
#include <vector>

#include "01_base/box3.h"
#include "01_base/ray.h"

namespace rtk::test {

// [ch01-ray-sets]
/// Rays from random points in a box enlarged by half its size toward random points inside the
/// box, so that most hit something and some start inside the geometry.
std::vector<Ray> random_rays(const Box3f& bounds, int count, uint64_t seed);

/// Rays whose direction has one or two zero components (with both signs of zero), starting
/// inside and outside the box, some exactly on the box's planes.
std::vector<Ray> axis_aligned_rays(const Box3f& bounds, int count, uint64_t seed);

/// Rays that start outside the box and pass just beside it or touch its faces and edges.
std::vector<Ray> grazing_rays(const Box3f& bounds, int count, uint64_t seed);

/// Rays that are not rays: NaN or infinite components, zero direction, tnear > tfar.
std::vector<Ray> invalid_rays();

/// All of the above, with random finite [tnear, tfar] intervals on a quarter of them.
std::vector<Ray> mixed_rays(const Box3f& bounds, int count, uint64_t seed);
// [ch01-ray-sets]

}  // namespace rtk::test
