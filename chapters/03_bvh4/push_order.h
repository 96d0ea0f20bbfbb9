/// \file
/// The order in which a traversal pushes the children a ray enters: nearest on top, so that it
/// is popped first, and among equal entry distances the lower slot on top. The insertion sort
/// that defines the order, and the forms of it that avoid branches; free of any ISA, so that
/// the tests can hold the fast forms to the definition directly.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "01_base/platform.h"
#include "02_bvh2/node_ref.h"

namespace rtk {

/// One traversal stack entry: a node to visit and its entry distance when it was pushed.
struct BvhStackEntry {
  NodeRef ref;
  float dist;
};

/// Sorts freshly pushed entries (pushed in slot order) so that the nearest is on top, popped
/// first. Among equal distances the lower slot goes on top, as in the 2-hit path, so that
/// switching that path off changes no visit.
RTK_INLINE void sort_pushed(BvhStackEntry* first, BvhStackEntry* end) {
  for (BvhStackEntry* i = first + 1; i < end; ++i) {
    const BvhStackEntry e = *i;
    BvhStackEntry* j = i;
    for (; j > first && j[-1].dist <= e.dist; --j) *j = j[-1];
    *j = e;
  }
}

/// The order of a pushed child as one integer: its distance's bits, turned so that signed
/// integer order is float order, above its slot, so that among equal distances the lower slot
/// counts as nearer, as in sort_pushed. (+ 0 turns -0 into +0: equal as floats, not as bits.)
RTK_INLINE int64_t push_key(float dist, int slot) {
  const int32_t bits = std::bit_cast<int32_t>(dist + 0.0f);
  const int32_t ordered = bits ^ static_cast<int32_t>(static_cast<uint32_t>(bits >> 31) >> 1);
  return (static_cast<int64_t>(ordered) << 32) | slot;
}

// [ch03-three-hit]
/// Pushes the children in slots i0 < i1 < i2, entered at distances d[slot], farthest first and
/// returns the nearest, in sort_pushed's order. Their keys are ordered by minimum and maximum,
/// which compile to conditional moves, where the insertion sort's comparisons would be
/// mispredicted on incoherent rays; the keys differ in their slots, so the middle one is what
/// the other two leave of the xor of all three.
RTK_INLINE NodeRef push_three(const NodeRef* children, const float* d, int i0, int i1, int i2,
                              BvhStackEntry*& sp) {
  const int64_t a = push_key(d[i0], i0), b = push_key(d[i1], i1), c = push_key(d[i2], i2);
  const int64_t near = std::min(std::min(a, b), c), far = std::max(std::max(a, b), c);
  const int64_t middle = a ^ b ^ c ^ near ^ far;
  const auto far_slot = static_cast<uint32_t>(far), middle_slot = static_cast<uint32_t>(middle);
  sp[0] = {children[far_slot], d[far_slot]};
  sp[1] = {children[middle_slot], d[middle_slot]};
  sp += 2;
  return children[static_cast<uint32_t>(near)];
}
// [ch03-three-hit]

}  // namespace rtk
