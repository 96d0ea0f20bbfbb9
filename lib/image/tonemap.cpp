#include "image/tonemap.h"

#include <algorithm>
#include <cmath>

namespace rtk {

float ToneMap::apply(float linear) const {
  if (!(linear > 0.0f)) return 0.0f;  // negative, zero and NaN
  if (linear >= 1.0f) return 1.0f;    // includes +infinity
  const float g = gamma > 0.0f && std::isfinite(gamma) ? gamma : 1.0f;
  return g == 1.0f ? linear : std::clamp(std::pow(linear, 1.0f / g), 0.0f, 1.0f);
}

uint8_t ToneMap::to_8bit(float linear) const {
  return static_cast<uint8_t>(apply(linear) * 255.0f + 0.5f);
}

}  // namespace rtk
