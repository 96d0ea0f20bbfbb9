#include "image/framebuffer.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

Framebuffer::Framebuffer(int width, int height) : width_(width), height_(height) {
  if (width < 0 || height < 0 || width > 32768 || height > 32768)
    throw std::invalid_argument("framebuffer size " + std::to_string(width) + " x " +
                                std::to_string(height) + " is not in [0, 32768]^2");
  sum_.assign(static_cast<std::size_t>(width) * height, Color());
  weight_.assign(static_cast<std::size_t>(width) * height, 0.0f);
}

Framebuffer::Framebuffer(const Framebuffer& o)
    : width_(o.width_),
      height_(o.height_),
      sum_(o.sum_),
      weight_(o.weight_),
      invalid_(o.invalid_samples()) {}

Framebuffer& Framebuffer::operator=(const Framebuffer& o) {
  width_ = o.width_;
  height_ = o.height_;
  sum_ = o.sum_;
  weight_ = o.weight_;
  invalid_ = o.invalid_samples();
  return *this;
}

void Framebuffer::add_sample(int x, int y, Color radiance, float weight) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_)
    throw std::out_of_range("framebuffer pixel out of range");
  if (!is_finite(radiance) || !std::isfinite(weight)) {
    invalid_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  sum_[index(x, y)] += radiance * weight;
  weight_[index(x, y)] += weight;
}

Image Framebuffer::resolve() const {
  Image image(width_, height_);
  for (std::size_t i = 0; i < sum_.size(); ++i)
    image.pixels[i] = weight_[i] != 0.0f ? sum_[i] / weight_[i] : Color();
  return image;
}

void Framebuffer::clear() {
  sum_.assign(sum_.size(), Color());
  weight_.assign(weight_.size(), 0.0f);
  invalid_ = 0;
}

}  // namespace rtk
