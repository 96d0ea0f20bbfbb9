/// \file
/// The HDR framebuffer: per pixel, a running sum of weighted radiance samples and of their
/// weights. Progressive rendering adds frames to it; the image is the ratio.
#pragma once

#include <atomic>
#include <vector>

#include "image/image.h"

namespace rtk {

// [image-framebuffer]
/// Accumulates radiance samples per pixel: sum(w_i L_i) and sum(w_i). With filter importance
/// sampling (chapter 11) every weight is 1 and the pixel value is the plain mean; a splatting
/// filter would pass its filter values. Distinct pixels are distinct memory, so threads that
/// render disjoint tiles may add to one framebuffer without locks.
class Framebuffer {
 public:
  /// A framebuffer of width x height pixels, all empty; throws std::invalid_argument for a
  /// negative size or one above 2^15 on a side.
  Framebuffer(int width, int height);
  /// A copy of the samples so far.
  Framebuffer(const Framebuffer& other);
  /// Replaces the samples with a copy of another framebuffer's.
  Framebuffer& operator=(const Framebuffer& other);

  /// Adds one sample of radiance `radiance` with weight `weight` to pixel (x, y). Samples that
  /// are not finite (a NaN from a bug upstream, an infinite firefly) are counted in
  /// invalid_samples() and dropped, so one bad path cannot blacken or whiten a pixel forever.
  void add_sample(int x, int y, Color radiance, float weight = 1.0f);

  /// The mean radiance of each pixel (black where no sample has arrived).
  Image resolve() const;
  /// Forgets every sample (a moved camera restarts progressive refinement).
  void clear();

  /// The width in pixels.
  int width() const { return width_; }
  /// The height in pixels.
  int height() const { return height_; }
  /// The total weight of pixel (x, y).
  float weight(int x, int y) const { return weight_[index(x, y)]; }
  /// How many samples were dropped for not being finite.
  long long invalid_samples() const { return invalid_.load(std::memory_order_relaxed); }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }
  int width_, height_;
  std::vector<Color> sum_;
  std::vector<float> weight_;
  std::atomic<long long> invalid_{0};  // the one counter that tiles share
};
// [image-framebuffer]

}  // namespace rtk
