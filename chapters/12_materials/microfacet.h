/// \file
/// The GGX (Trowbridge-Reitz) microfacet distribution with Smith masking and sampling of the
/// visible normals. Isotropic; directions in the local frame, upper hemisphere.
#pragma once

#include <algorithm>
#include <cmath>

#include "01_base/vec3.h"
#include "11_sampling/vec2.h"
#include "11_sampling/warp.h"

namespace rtk {

/// Converts the guide's `roughness` parameter (Metal, Plastic) to a GGX width alpha. Embree's
/// materials read roughness as the reciprocal of a power-cosine exponent e; Walter, Marschner,
/// Li and Torrance ("Microfacet Models for Refraction through Rough Surfaces", EGSR 2007,
/// section 5.2) match e to a Beckmann width by alpha = sqrt(2 / (e + 2)), which we use for
/// GGX as well: alpha = sqrt(2 r / (1 + 2 r)). Roughness 0 stays 0: a smooth (delta) surface.
inline float roughness_to_alpha(float roughness) {
  if (!(roughness > 0.0f)) return 0.0f;
  return std::sqrt(2.0f * roughness / (1.0f + 2.0f * roughness));
}

/// The isotropic GGX distribution of microfacet normals (Walter et al. 2007; Trowbridge and
/// Reitz 1975) of width alpha > 0.
struct GgxDistribution {
  float alpha = 0.1f;

  // [ch12-ggx]
  /// The density of microfacet normals per unit projected area: D(m), with
  /// integral of D(m) cos(theta_m) over the hemisphere = 1.
  float d(Vec3f m) const {
    if (m.z <= 0.0f) return 0.0f;
    const float cos2 = m.z * m.z, a2 = alpha * alpha;
    const float t = cos2 * (a2 - 1.0f) + 1.0f;  // = cos^2 (a^2 + tan^2), with no tan to overflow
    return a2 / (kPi * t * t);
  }

  /// Smith's Lambda for GGX: the ratio of the masked to the visible projected microfacet area.
  float lambda(Vec3f w) const {
    const float cos2 = w.z * w.z;
    if (cos2 >= 1.0f) return 0.0f;
    const float tan2 = (1.0f - cos2) / cos2;
    return 0.5f * (std::sqrt(1.0f + alpha * alpha * tan2) - 1.0f);
  }

  /// The fraction of microfacets visible from w: G1 = 1 / (1 + Lambda(w)).
  float g1(Vec3f w) const { return 1.0f / (1.0f + lambda(w)); }

  /// The height-correlated masking-shadowing function G2 = 1 / (1 + Lambda(wo) + Lambda(wi))
  /// (Heitz, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs", JCGT
  /// 3(2), 2014). Symmetric in wo and wi, so BRDFs built on it are reciprocal.
  float g2(Vec3f wo, Vec3f wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }
  // [ch12-ggx]

  // [ch12-vndf]
  /// A microfacet normal visible from wo (wo.z > 0), with density pdf_visible(wo, m): Heitz,
  /// "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4), 2018). Stretch wo into the
  /// configuration where alpha = 1, sample the projected half-disk there, and unstretch.
  Vec3f sample_visible(Vec3f wo, Vec2f u) const {
    // Section 1: the view direction in the hemisphere configuration.
    const Vec3f vh = normalize(Vec3f{alpha * wo.x, alpha * wo.y, wo.z});
    // Section 2: an orthonormal basis around it (with a fallback when vh is the pole).
    const float len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3f t1 =
        len2 > 0.0f ? Vec3f{-vh.y, vh.x, 0.0f} * (1.0f / std::sqrt(len2)) : Vec3f{1, 0, 0};
    const Vec3f t2 = cross(vh, t1);
    // Section 3: a uniform point of the disk, its lower half squashed by the projection.
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * safe_sqrt(1.0f - p1 * p1) + s * r * std::sin(phi);
    // Section 4: back onto the hemisphere, then unstretch to the ellipsoid's normal.
    const Vec3f nh = p1 * t1 + p2 * t2 + safe_sqrt(1.0f - p1 * p1 - p2 * p2) * vh;
    return normalize(Vec3f{alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)});
  }

  /// The density of sample_visible: D_wo(m) = G1(wo) max(0, wo.m) D(m) / wo.z.
  float pdf_visible(Vec3f wo, Vec3f m) const {
    if (wo.z <= 0.0f) return 0.0f;
    return g1(wo) * std::max(0.0f, dot(wo, m)) * d(m) / wo.z;
  }
  // [ch12-vndf]
};

}  // namespace rtk
