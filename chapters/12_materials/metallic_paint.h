/// \file
/// MetallicPaint: a car paint. A clear coat over a pigment in which small metal flakes float,
/// each tilted a little away from the surface: the glitter.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "11_sampling/warp.h"
#include "12_materials/bsdf_sample.h"
#include "12_materials/fresnel.h"
#include "12_materials/microfacet.h"

namespace rtk {

// [ch12-metallic-paint]
/// The guide's MetallicPaint: a smooth dielectric coat of index eta (a delta lobe weighted by
/// the Fresnel term, as in a smooth Plastic) over a layer of pigment and metal flakes. A flake
/// is a tiny mirror; the flakes' normals scatter around the surface normal with the GGX
/// distribution of width alpha (the guide's glitterSpread), so that, seen from afar, they
/// reflect a glossy lobe of colour `glitter` around the mirror direction. The flakes cover the
/// pigment: of the light that passes the coat, the fraction `glitter` meets a flake and the
/// rest the pigment, which scatters it diffusely with colour `shade`:
///   f = f_coat + (1 - F(cos_o)) (1 - F(cos_i)) [ (1 - glitter) shade / pi
///                                                + glitter D(h) G2(wo, wi) / (4 cos_o cos_i) ].
/// Every term is symmetric in wo and wi (reciprocity); the flake lobe reflects at most what
/// reaches it, so the layer's albedo is at most glitter + (1 - glitter) shade <= 1. The
/// refraction of the flakes' lobe at the coat is neglected (the lobe is as wide as it would be
/// without a coat), and so is light that the coat reflects back down. A sample picks the coat
/// with the Plastic's probability, then the flakes or the pigment in proportion to their
/// average colours. Without glitter this is the smooth Plastic.
struct MetallicPaint {
  Color shade{0.5f};                ///< the pigment's colour (shadeColor)
  Color glitter;                    ///< the flakes' colour (glitterColor); black: no flakes
  float eta = 1.45f;                ///< the coat's index of refraction
  GgxDistribution flakes{0.816f};  ///< the spread of the flakes' normals (glitterSpread 1)

  /// The probability of picking the pigment and flakes' lobe that holds the flakes.
  float flake_probability() const {
    const float g = average(glitter), d = average((Color(1.0f) - glitter) * shade);
    return g + d > 0.0f ? g / (g + d) : 0.0f;
  }
  /// The probability of picking the coat's mirror reflection.
  float coat_probability(float cos_o) const {
    const float f = fresnel_dielectric(cos_o, eta);
    const float under = average(glitter) + average((Color(1.0f) - glitter) * shade);
    const float total = f + (1.0f - f) * under;
    return total > 0.0f ? f / total : 0.0f;
  }

  Color eval(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return {};
    wo = to_upper(wo), wi = to_upper(wi);
    const float t = (1.0f - fresnel_dielectric(wo.z, eta)) * (1.0f - fresnel_dielectric(wi.z, eta));
    Color f = (Color(1.0f) - glitter) * shade * kInvPi;
    if (!is_black(glitter)) {
      const Vec3f h = normalize(wo + wi);
      f += glitter * (flakes.d(h) * flakes.g2(wo, wi) / (4.0f * wo.z * wi.z));
    }
    return f * t;
  }

  float pdf(Vec3f wo, Vec3f wi) const {
    if (!same_hemisphere(wo, wi)) return 0.0f;
    wo = to_upper(wo), wi = to_upper(wi);
    const float p_under = 1.0f - coat_probability(wo.z), p_flake = flake_probability();
    float pdf = (1.0f - p_flake) * wi.z * kInvPi;
    if (p_flake > 0.0f) {
      const Vec3f h = normalize(wo + wi);
      const float wo_h = dot(wo, h);
      if (wo_h > 0.0f) pdf += p_flake * flakes.pdf_visible(wo, h) / (4.0f * wo_h);
    }
    return p_under * pdf;
  }

  std::optional<BsdfSample> sample(Vec3f wo, float u_lobe, Vec2f u) const {
    if (wo.z == 0.0f) return std::nullopt;
    const bool flipped = wo.z < 0.0f;
    const Vec3f wo_up = to_upper(wo);
    const float p_coat = coat_probability(wo_up.z);
    if (u_lobe < p_coat) {
      const float f = fresnel_dielectric(wo_up.z, eta);
      return BsdfSample{reflect_local(wo), Color(f / wo_up.z), Color(f / p_coat), p_coat, true};
    }
    // The lobe number, reused: uniform again in [0, 1) among the layer's two lobes.
    const float u_under = (u_lobe - p_coat) / (1.0f - p_coat);
    Vec3f wi = u_under < flake_probability() ? reflect(wo_up, flakes.sample_visible(wo_up, u))
                                             : sample_cosine_hemisphere(u);
    if (wi.z <= 0.0f) return std::nullopt;
    const Color f = eval(wo_up, wi);
    const float pdf = this->pdf(wo_up, wi);
    if (!(pdf > 0.0f)) return std::nullopt;
    if (flipped) wi.z = -wi.z;
    return BsdfSample{wi, f, f * (std::fabs(wi.z) / pdf), pdf, false};
  }
};
// [ch12-metallic-paint]

}  // namespace rtk
