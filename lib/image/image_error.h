/// \file
/// How far an image is from a converged one: the figure that equal-time comparisons of
/// renderers (and of samplers) are made with.
#pragma once

#include "image/image.h"

namespace rtk {

// [image-error]
/// The relative root-mean-square error of `image` against `reference`:
/// sqrt(sum (a - r)^2 / sum r^2) over every pixel and channel. Dividing by the reference's own
/// RMS makes the figure independent of the scene's brightness, so that two renderers whose
/// images differ in exposure can each be compared with their own converged image. Throws
/// std::invalid_argument when the sizes differ, when either image holds a value that is not
/// finite, or when the reference is black (the ratio has no meaning then).
double relative_rms_error(const Image& image, const Image& reference);
// [image-error]

}  // namespace rtk
