// The slab test's entry points, compiled once per ISA: a ray against a set of boxes, W boxes
// per step, for the widths of kSlabWidths.
#include "01_base/slab.h"

#include <stdexcept>
#include <string>

#include "01_base/slab_kernels.h"

namespace rtk::RTK_ISA {

namespace {

void check(int width, const BoxesSoA& boxes) {
  if (width != 1 && width != 4 && width != 8 && width != 16)
    throw std::invalid_argument("slab kernels: width " + std::to_string(width) +
                                " (choose 1, 4, 8 or 16)");
  const size_t n = boxes.padded_count();
  bool consistent = n % BoxesSoA::kPadding == 0 && boxes.count <= n;
  for (int axis = 0; axis < 3; ++axis)
    consistent = consistent && boxes.lower[axis].size() == n && boxes.upper[axis].size() == n;
  if (!consistent)
    throw std::invalid_argument("slab kernels: the box arrays are not padded to a multiple of 16");
}

template <int W>
void intersect_all(const Ray& ray, const BoxesSoA& boxes, uint8_t* hit, float* entry) {
  const SlabRay<W> r = make_slab_ray<W>(ray);
  for (size_t first = 0; first < boxes.padded_count(); first += W) {
    vfloat<W> t;
    const uint32_t mask = movemask(intersect_slabs(r, boxes, first, t));
    t.storeu(entry + first);
    for (int i = 0; i < W; ++i) hit[first + i] = (mask >> i) & 1;
  }
}

// [ch01-slab-kernel-loop]
template <int W>
uint64_t count_hits(std::span<const Ray> rays, const BoxesSoA& boxes) {
  uint64_t hits = 0;
  for (const Ray& ray : rays) {
    const SlabRay<W> r = make_slab_ray<W>(ray);
    for (size_t first = 0; first < boxes.padded_count(); first += W) {
      vfloat<W> t;
      hits += pop_count(movemask(intersect_slabs(r, boxes, first, t)));
    }
  }
  return hits;
}
// [ch01-slab-kernel-loop]

}  // namespace

void intersect_boxes(int width, const Ray& ray, const BoxesSoA& boxes, uint8_t* hit,
                     float* entry) {
  check(width, boxes);
  switch (width) {
    case 1: return intersect_all<1>(ray, boxes, hit, entry);
    case 4: return intersect_all<4>(ray, boxes, hit, entry);
    case 8: return intersect_all<8>(ray, boxes, hit, entry);
    default: return intersect_all<16>(ray, boxes, hit, entry);
  }
}

// [ch01-slab-entry]
uint64_t count_box_hits(int width, std::span<const Ray> rays, const BoxesSoA& boxes) {
  check(width, boxes);
  switch (width) {
    case 1: return count_hits<1>(rays, boxes);
    case 4: return count_hits<4>(rays, boxes);
    case 8: return count_hits<8>(rays, boxes);
    default: return count_hits<16>(rays, boxes);
  }
}
// [ch01-slab-entry]

}  // namespace rtk::RTK_ISA
