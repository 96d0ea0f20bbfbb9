/// \file
/// The light interface: what a path tracer with next-event estimation and multiple
/// importance sampling asks of a light.
#pragma once

#include <limits>
#include <optional>

#include "01_base/vec3.h"
#include "01_base/color.h"
#include "11_sampling/vec2.h"

namespace rtk {

/// The point a light is sampled for. `n` is the surface normal there, or zero for a point
/// with no preferred hemisphere (a transmissive surface, a medium): lights that can use the
/// normal (the ambient light's cosine sampling) then fall back to the whole sphere.
struct LightQuery {
  Vec3f p;
  Vec3f n{0, 0, 0};
};

// [ch13-light-sample]
/// One sampled light direction. `distance` is how far the shadow ray must reach: to the
/// sampled point of an area light, the point light's position, or infinity for lights at
/// infinity. For a delta light (point, directional) `pdf` is 1 and `L` already holds the
/// full contribution (intensity / d^2, or irradiance); such samples take no part in MIS.
struct LightSample {
  Vec3f wi;          ///< unit direction toward the light
  Color L;           ///< radiance (or its delta equivalent) arriving along -wi
  float pdf = 0.0f;  ///< solid-angle density of wi, or 1 for delta lights
  float distance = std::numeric_limits<float>::infinity();  ///< distance to the sampled point
  bool delta = false;                                       ///< whether the light is a delta light
};
// [ch13-light-sample]

// [ch13-light]
/// A light source. The renderer holds a list of them; each is sampled for direct lighting
/// (sample_li), evaluated for rays that reach it by BSDF sampling (le for lights at
/// infinity, TriangleLight::emitted for area lights hit by a ray), and weighted by pdf_li in
/// multiple importance sampling.
class Light {
 public:
  virtual ~Light() = default;

  /// A direction toward the light from the query point, from a 2D sample; nothing when the
  /// light cannot reach the point (behind an area light, zero radiance everywhere).
  virtual std::optional<LightSample> sample_li(const LightQuery& q, Vec2f u) const = 0;

  /// The solid-angle density with which sample_li returns wi (0 for delta lights and for
  /// directions that miss the light).
  virtual float pdf_li(const LightQuery& q, Vec3f wi) const = 0;

  /// The radiance arriving from direction wi along a ray that escapes the scene (non-zero only
  /// for lights at infinity).
  virtual Color le(Vec3f /*wi*/) const { return {}; }

  /// An estimate of the emitted power (flux), for choosing lights in proportion to it. Lights
  /// at infinity deliver power onto the scene's bounding sphere of radius `scene_radius`.
  virtual Color power(float scene_radius) const = 0;

  /// Whether the light is a delta light (sample_li's pdf is a probability, pdf_li is 0).
  virtual bool is_delta() const { return false; }
  /// Whether the light is at infinity (rays that escape the scene see it through le).
  virtual bool is_infinite() const { return false; }
};
// [ch13-light]

}  // namespace rtk
