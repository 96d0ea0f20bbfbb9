/// \file
/// A linear RGB image in memory: what the renderer resolves its framebuffer into and what the
/// image files are written from and read into.
#pragma once

#include <cstddef>
#include <vector>

#include "01_base/color.h"

namespace rtk {

/// An image of linear RGB floats, row by row from the top row down.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  ///< width * height colours, pixel (x, y) at y * width + x

  Image() = default;
  /// A black image of the given size.
  Image(int w, int h)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}

  /// The pixel at column x, row y (row 0 at the top).
  Color& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// The pixel at column x, row y (row 0 at the top).
  const Color& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

}  // namespace rtk
