#include "13_lights/environment_light.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "11_sampling/warp.h"

namespace rtk {

namespace {

// The local map frame: y up. Frame stores (s, t, n) = (map x, map z, map y).
Vec3f map_to_frame(Vec3f d) { return {d.x, d.z, d.y}; }
Vec3f frame_to_map(Vec3f l) { return {l.x, l.z, l.y}; }

// [ch13-environment-weights]
// The sampling weight of each texel: its luminance times the sine of its row's centre, the
// relative solid angle of texels in that row.
std::vector<float> texel_weights(const ImageTexture& image) {
  const int w = image.width(), h = image.height();
  std::vector<float> weights(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    const float sin_theta = std::sin(kPi * (y + 0.5f) / h);
    for (int x = 0; x < w; ++x) {
      const Color c = image.texel(x, y);
      if (!is_finite(c) || c.r < 0 || c.g < 0 || c.b < 0)
        throw std::invalid_argument("environment map texel (" + std::to_string(x) + ", " +
                                    std::to_string(y) + ") is negative or not finite");
      weights[static_cast<std::size_t>(y) * w + x] = luminance(c) * sin_theta;
    }
  }
  return weights;
}
// [ch13-environment-weights]

// [ch13-environment-dilate]
// Under bilinear interpolation a texel's radiance reaches halfway into its neighbours, so a
// black texel beside a bright one has light near its border. Each texel is weighed by the
// brightest of itself and its eight neighbours (the azimuth wraps, the rows stop at the
// poles), which gives every lit direction a density.
std::vector<float> dilate(const std::vector<float>& weights, int w, int h) {
  std::vector<float> out(weights.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float m = 0.0f;
      for (int dy = -1; dy <= 1; ++dy) {
        const int yy = std::clamp(y + dy, 0, h - 1);
        const float sin_ratio = std::sin(kPi * (y + 0.5f) / h) / std::sin(kPi * (yy + 0.5f) / h);
        for (int dx = -1; dx <= 1; ++dx)
          m = std::max(m, weights[static_cast<std::size_t>(yy) * w + (x + dx + w) % w] * sin_ratio);
      }
      out[static_cast<std::size_t>(y) * w + x] = m;
    }
  return out;
}
// [ch13-environment-dilate]

Distribution2D make_distribution(const std::shared_ptr<const ImageTexture>& image,
                                 EnvironmentMapping mapping) {
  if (!image) throw std::invalid_argument("environment light without an image");
  std::vector<float> weights = texel_weights(*image);
  if (mapping == EnvironmentMapping::embree11)
    weights = dilate(weights, image->width(), image->height());
  return Distribution2D(weights, image->width(), image->height());
}

}  // namespace

EnvironmentLight::EnvironmentLight(std::shared_ptr<const ImageTexture> image, Color scale,
                                   const Frame& frame, EnvironmentMapping mapping)
    : image_(std::move(image)),
      scale_(scale),
      frame_(frame),
      mapping_(mapping),
      distribution_(make_distribution(image_, mapping)) {
  if (!is_finite(scale) || scale.r < 0 || scale.g < 0 || scale.b < 0)
    throw std::invalid_argument("environment light scale must be finite and >= 0");
}

Vec3f EnvironmentLight::direction(Vec2f uv) const {
  const float theta = uv.y * kPi, phi = uv.x * 2.0f * kPi;
  const float s = std::sin(theta);
  // Embree 1.1's azimuth runs from +x toward -z: the same map, mirrored.
  const float z = mapping_ == EnvironmentMapping::embree11 ? -s * std::sin(phi) : s * std::sin(phi);
  return frame_.to_world(map_to_frame({s * std::cos(phi), std::cos(theta), z}));
}

Vec2f EnvironmentLight::coordinates(Vec3f w) const {
  Vec3f d = frame_to_map(frame_.to_local(w));
  if (mapping_ == EnvironmentMapping::embree11) d.z = -d.z;
  // The map's pole is its y axis, its azimuth measured from x toward z.
  const Vec3f polar{d.x, d.z, d.y};
  const float theta = spherical_theta(polar), phi = spherical_phi(polar);
  return {std::min(phi / (2.0f * kPi), 0x1.fffffep-1f), std::min(theta / kPi, 0x1.fffffep-1f)};
}

Color EnvironmentLight::le(Vec3f wi) const {
  if (!is_finite(wi)) return {};
  const Vec2f uv = coordinates(wi);
  if (mapping_ == EnvironmentMapping::embree11) {
    // Bilinear between texel centres: the azimuth wraps around, the rows stop at the poles.
    const int w = image_->width(), h = image_->height();
    const float x = uv.x * w - 0.5f, y = uv.y * h - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y), tx = x - fx, ty = y - fy;
    const int x0 = (static_cast<int>(fx) + w) % w, x1 = (x0 + 1) % w;
    const int y0 = std::clamp(static_cast<int>(fy), 0, h - 1), y1 = std::clamp(static_cast<int>(fy) + 1, 0, h - 1);
    const Color c = (image_->texel(x0, y0) * (1 - tx) + image_->texel(x1, y0) * tx) * (1 - ty) +
                    (image_->texel(x0, y1) * (1 - tx) + image_->texel(x1, y1) * tx) * ty;
    return c * scale_;
  }
  const int x = std::min(static_cast<int>(uv.x * image_->width()), image_->width() - 1);
  const int y = std::min(static_cast<int>(uv.y * image_->height()), image_->height() - 1);
  return image_->texel(x, y) * scale_;
}

// [ch13-environment-sample]
std::optional<LightSample> EnvironmentLight::sample_li(const LightQuery&, Vec2f u) const {
  float pdf_uv = 0.0f;
  const Vec2f uv = distribution_.sample(u, &pdf_uv);
  const float sin_theta = std::sin(uv.y * kPi);
  if (!(pdf_uv > 0.0f) || !(sin_theta > 0.0f)) return std::nullopt;
  const Vec3f wi = direction(uv);
  // The density is recomputed from wi, as pdf_li does: a point on a texel's border may round
  // into the neighbour, and MIS needs sample_li and pdf_li to agree exactly.
  const float pdf = pdf_li(LightQuery{}, wi);
  if (!(pdf > 0.0f)) return std::nullopt;
  return LightSample{wi, le(wi), pdf, std::numeric_limits<float>::infinity(), false};
}

float EnvironmentLight::pdf_li(const LightQuery&, Vec3f wi) const {
  if (!is_finite(wi)) return 0.0f;
  const Vec2f uv = coordinates(wi);
  const float sin_theta = std::sin(uv.y * kPi);
  if (!(sin_theta > 0.0f)) return 0.0f;
  return distribution_.pdf(uv) / (2.0f * kPi * kPi * sin_theta);
}
// [ch13-environment-sample]

Color EnvironmentLight::power(float scene_radius) const {
  // The radiance integrated over the sphere: each row of texels covers
  // (2 pi / w) (cos theta_0 - cos theta_1) per texel.
  const int w = image_->width(), h = image_->height();
  Color total;
  for (int y = 0; y < h; ++y) {
    const float solid_angle =
        (2.0f * kPi / w) * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
    for (int x = 0; x < w; ++x) total += image_->texel(x, y) * solid_angle;
  }
  return total * scale_ * (kPi * scene_radius * scene_radius);
}

std::shared_ptr<const ImageTexture> load_environment_image(const std::string& path,
                                                           ColorEncoding encoding) {
  return load_image_texture(path, encoding, WrapMode::repeat);
}

}  // namespace rtk
