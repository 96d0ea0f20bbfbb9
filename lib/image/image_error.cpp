#include "image/image_error.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rtk {

double relative_rms_error(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw std::invalid_argument("the image is " + std::to_string(image.width) + " x " +
                                std::to_string(image.height) + ", the reference " +
                                std::to_string(reference.width) + " x " +
                                std::to_string(reference.height));
  // Sums in double: a megapixel of float squares would lose the small differences.
  double error = 0, norm = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    const Color& a = image.pixels[i];
    const Color& r = reference.pixels[i];
    for (int c = 0; c < 3; ++c) {
      const double av = a[c], rv = r[c];
      if (!std::isfinite(rv))
        throw std::invalid_argument("the reference has a value that is not finite at pixel (" +
                                    std::to_string(i % reference.width) + ", " +
                                    std::to_string(i / reference.width) + ")");
      if (!std::isfinite(av))
        throw std::invalid_argument("the image has a value that is not finite at pixel (" +
                                    std::to_string(i % image.width) + ", " +
                                    std::to_string(i / image.width) + ")");
      error += (av - rv) * (av - rv);
      norm += rv * rv;
    }
  }
  if (!(norm > 0)) throw std::invalid_argument("the reference is black");
  return std::sqrt(error / norm);
}

}  // namespace rtk
