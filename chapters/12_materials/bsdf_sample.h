/// \file
/// What sampling a BSDF returns, and the conventions every BSDF model of chapter 12 follows.
///
/// Conventions: directions are unit vectors in the local shading frame (z is the shading
/// normal) and both point away from the surface: wo toward the viewer, wi toward the light.
/// Every model has
///   - `Color eval(wo, wi)`: the BSDF value f(wo, wi), without the cosine; the non-delta part
///     only (0 for purely specular models);
///   - `float pdf(wo, wi)`: the solid-angle density with which `sample` produces wi, again
///     the non-delta part only (what multiple importance sampling needs);
///   - `std::optional<BsdfSample> sample(wo, u_lobe, u)`: a direction from one 1D number
///     (which lobe) and one 2D number (where in it); nothing when the sample is absorbed (a
///     microfacet reflection below the horizon, a black reflectance).
/// Opaque models are two-sided (they reflect on the side wo is on); dielectrics are not:
/// the normal points to the outside.
#pragma once

#include <cmath>

#include "01_base/vec3.h"
#include "01_base/color.h"
#include "11_sampling/vec2.h"

namespace rtk {

// [ch12-bsdf-sample]
/// A sampled direction. For a delta lobe, `f` and `pdf` are the factors of the Dirac
/// distributions that cancel: f = reflectance / |cos|, pdf = the lobe's selection
/// probability. `weight` = f |cos(wi)| / pdf is what the path throughput is multiplied by;
/// it is computed by the model, where it is exact even when f and pdf are large.
struct BsdfSample {
  Vec3f wi;            ///< the sampled direction (local frame in a model, world in a Bsdf)
  Color f;             ///< the BSDF value for (wo, wi)
  Color weight;        ///< f |cos(theta_i)| / pdf
  float pdf = 0.0f;    ///< the density (solid angle) or, for a delta lobe, the lobe probability
  bool delta = false;  ///< whether wi came from a Dirac delta lobe (no light sampling, no MIS)
};
// [ch12-bsdf-sample]

/// Whether two local directions lie on the same side of the surface.
constexpr bool same_hemisphere(Vec3f a, Vec3f b) { return a.z * b.z > 0.0f; }

/// Flips a local direction onto the upper hemisphere (opaque models are two-sided).
constexpr Vec3f to_upper(Vec3f w) { return w.z < 0.0f ? Vec3f{w.x, w.y, -w.z} : w; }

}  // namespace rtk
