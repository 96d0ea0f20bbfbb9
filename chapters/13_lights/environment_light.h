/// \file
/// The HDR environment light (the guide's -hdrilight r g b file and the XML HDRILight): a
/// latitude-longitude image around the scene, importance-sampled by its brightness.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "11_sampling/distribution.h"
#include "11_sampling/frame.h"
#include "12_materials/texture.h"
#include "13_lights/light.h"

namespace rtk {

// [ch13-environment]
/// An environment map in latitude-longitude layout with +y up (the guide's camera convention):
/// a direction with polar angle theta from +y and azimuth phi from +x toward +z, i.e.
/// (sin theta cos phi, cos theta, sin theta sin phi) in the light's frame, looks up texel
/// column phi / (2 pi) * width and row theta / pi * height (row 0 is the zenith). Texels are
/// looked up without interpolation, so the radiance is piecewise constant over the same
/// cells as the sampling distribution.
///
/// Sampling draws a texel from a 2D piecewise-constant distribution proportional to
/// luminance * sin(theta) (a texel near a pole covers less of the sphere) and a direction
/// uniformly in it; the (u, v) density p(u, v) becomes p(u, v) / (2 pi^2 sin theta) per solid
/// angle, the Jacobian of (u, v) = (phi / 2 pi, theta / pi).
/// How directions meet the map. RTK's mapping is the one above, looked up without
/// interpolation. Embree 1.1's runs the azimuth the other way round (the map seen mirrored
/// left to right: phi from +x toward -z) and interpolates bilinearly between texel centres;
/// its sampling distribution then weighs each texel by the brightest of its neighbours, so
/// that every direction with radiance can be sampled.
enum class EnvironmentMapping { rtk, embree11 };

class EnvironmentLight final : public Light {
 public:
  /// A light from an image (linear radiance), scaled by `scale` (the guide's r g b), seen
  /// through `frame` (the light's axes in world space: frame.s, frame.n, frame.t are the
  /// map's x, y, z). Throws std::invalid_argument for a negative or non-finite texel or scale.
  EnvironmentLight(std::shared_ptr<const ImageTexture> image, Color scale,
                   const Frame& frame = Frame({1, 0, 0}, {0, 0, 1}, {0, 1, 0}),
                   EnvironmentMapping mapping = EnvironmentMapping::rtk);

  std::optional<LightSample> sample_li(const LightQuery& q, Vec2f u) const override;
  float pdf_li(const LightQuery& q, Vec3f wi) const override;
  Color le(Vec3f wi) const override;
  /// pi r^2 times the integral of the radiance over the sphere.
  Color power(float scene_radius) const override;
  bool is_infinite() const override { return true; }

  /// The world direction of map coordinates (u, v) in [0, 1]^2.
  Vec3f direction(Vec2f uv) const;
  /// The map coordinates of a world direction.
  Vec2f coordinates(Vec3f w) const;

 private:
  std::shared_ptr<const ImageTexture> image_;
  Color scale_;
  Frame frame_;  // s: map x, t: map z, n: map y (up)
  EnvironmentMapping mapping_;
  Distribution2D distribution_;
};
// [ch13-environment]

/// Loads the image of an environment light from a file (Radiance .hdr for real HDR maps;
/// 8-bit files are decoded as `encoding` says: sRGB by RTK's conventions, linear by Embree
/// 1.1's), through chapter 12's load_image_texture. Throws std::runtime_error naming the file
/// when it cannot be read.
std::shared_ptr<const ImageTexture> load_environment_image(const std::string& path,
                                                           ColorEncoding encoding = ColorEncoding::srgb);

}  // namespace rtk
