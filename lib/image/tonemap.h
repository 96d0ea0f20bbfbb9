/// \file
/// Tone mapping for 8-bit files and displays: linear radiance to display values.
#pragma once

#include <cstdint>

#include "01_base/color.h"

namespace rtk {

// [image-tonemap]
/// The guide's tone mapper (-gamma g; its default is 1, no correction): a display value is
/// clamp(c^(1/g), 0, 1), quantised to 8 bits by rounding. Values above 1 are clamped, not
/// compressed: a linear renderer's overexposed pixels should look overexposed. Negative
/// values and NaN become 0, +infinity becomes 255. (The guide's -vignetting is the camera's:
/// chapter 11.)
struct ToneMap {
  float gamma = 1.0f;  ///< display gamma; 2.2 approximates an sRGB monitor

  /// One channel to 8 bits.
  uint8_t to_8bit(float linear) const;
  /// One channel to a display value in [0, 1] (before quantisation).
  float apply(float linear) const;
};
// [image-tonemap]

}  // namespace rtk
