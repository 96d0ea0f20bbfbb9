/// \file
/// Area lights: emitting triangles, and quads made of two of them.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "13_lights/light.h"

namespace rtk {

// [ch13-triangle-light]
/// A triangle that emits radiance L from one side (the guide's -trianglelight P U V L: the
/// triangle P, P+U, P+V). The emitting side is the one its normal
/// normalize(cross(v2 - v0, v1 - v0)) points to; with that rule the guide's
/// -quadlight on the Cornell box ceiling shines down into the box. Points are sampled
/// uniformly on the area, and the area density 1 / A becomes the solid-angle density
/// d^2 / (A cos theta_l) seen from the query point.
class TriangleLight final : public Light {
 public:
  /// A light on triangle (v0, v1, v2) with radiance `radiance`; throws std::invalid_argument
  /// for non-finite vertices, a zero area, or a negative or non-finite radiance.
  TriangleLight(Vec3f v0, Vec3f v1, Vec3f v2, Color radiance);

  std::optional<LightSample> sample_li(const LightQuery& q, Vec2f u) const override;
  float pdf_li(const LightQuery& q, Vec3f wi) const override;
  /// pi A L: a Lambertian emitter's exitance times its area.
  Color power(float scene_radius) const override;

  /// The radiance leaving the light toward direction w (w points away from the light):
  /// L on the emitting side, 0 behind. What a BSDF-sampled ray that hits the light sees.
  Color emitted(Vec3f w) const { return dot(w, normal_) > 0.0f ? radiance_ : Color{}; }
  /// The solid-angle density of sample_li for a query at p and a known point on the light:
  /// what an integrator that has already intersected the light needs for MIS.
  float pdf_hit(Vec3f p, Vec3f point_on_light) const;

  /// The triangle's vertices (the renderer adds them to the scene so that rays can hit them).
  const std::array<Vec3f, 3>& vertices() const { return v_; }
  /// The unit normal of the emitting side.
  Vec3f normal() const { return normal_; }
  /// The area.
  float area() const { return area_; }

 private:
  std::array<Vec3f, 3> v_;
  Vec3f normal_;
  float area_ = 0.0f;
  Color radiance_;
};
// [ch13-triangle-light]

/// The guide's -quadlight P U V L: the two triangles (P+U+V, P+U, P) and (P+U+V, P, P+V),
/// both emitting on the side of cross(U, V).
std::vector<std::shared_ptr<const TriangleLight>> make_quad_light(Vec3f p, Vec3f u, Vec3f v,
                                                                  Color radiance);

}  // namespace rtk
