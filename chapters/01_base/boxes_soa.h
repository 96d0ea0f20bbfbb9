/// \file
/// Boxes in structure-of-arrays layout: what a wide BVH node is, and what the slab test reads.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "01_base/aligned.h"
#include "01_base/box3.h"

namespace rtk {

/// Axis-aligned boxes as six float arrays (lower x, y, z and upper x, y, z), so that W boxes'
/// planes along one axis load as one vector. The arrays are padded with empty boxes (lower = +inf,
/// upper = -inf, which no ray hits) to a multiple of kPadding, and start on a cache
/// line, so any SIMD width up to 16 loads whole, aligned groups.
struct BoxesSoA {
  /// The padding granule: the widest vector, sixteen floats.
  static constexpr size_t kPadding = 16;

  size_t count = 0;                          ///< the number of real boxes
  std::array<aligned_vector<float>, 3> lower;  ///< lower[axis][i], padded_count() entries
  std::array<aligned_vector<float>, 3> upper;  ///< upper[axis][i], padded_count() entries

  BoxesSoA() = default;
  /// Transposes the boxes into the six arrays.
  explicit BoxesSoA(std::span<const Box3f> boxes) : count(boxes.size()) {
    const size_t padded = (count + kPadding - 1) / kPadding * kPadding;
    const Box3f empty;
    for (int axis = 0; axis < 3; ++axis) {
      lower[axis].assign(padded, empty.lower[axis]);
      upper[axis].assign(padded, empty.upper[axis]);
      for (size_t i = 0; i < count; ++i) {
        lower[axis][i] = boxes[i].lower[axis];
        upper[axis][i] = boxes[i].upper[axis];
      }
    }
  }

  /// The number of boxes including the padding (a multiple of kPadding).
  size_t padded_count() const { return lower[0].size(); }
  /// The planes of one side (0 lower, 1 upper) along one axis.
  const float* planes(int side, int axis) const {
    return side ? upper[axis].data() : lower[axis].data();
  }
  /// Box i, as it was given.
  Box3f box(size_t i) const {
    return {{lower[0][i], lower[1][i], lower[2][i]}, {upper[0][i], upper[1][i], upper[2][i]}};
  }
};

}  // namespace rtk
