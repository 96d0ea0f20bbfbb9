/// \file
/// The BSDF at a surface point: one of chapter 12's models, placed in the point's shading
/// frame. This is what the path tracer (next chapters) asks for at every hit.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <variant>

#include "11_sampling/frame.h"
#include "12_materials/dielectric.h"
#include "12_materials/lambertian.h"
#include "12_materials/metallic_paint.h"
#include "12_materials/plastic.h"
#include "12_materials/rough_conductor.h"
#include "12_materials/specular.h"
#include "12_materials/velvet.h"

namespace rtk {

/// Every scattering model of chapter 12. A closed set in a variant rather than a class
/// hierarchy: a BSDF is made at every hit, and a variant needs no allocation there.
using BsdfModel = std::variant<Lambertian, Mirror, SmoothConductor, RoughConductor,
                               SmoothDielectric, ThinDielectric, Plastic, Velvet, MetallicPaint>;

/// Calls f with the model a BsdfModel holds: a chain of index tests that the compiler inlines
/// into the caller (std::visit's dispatch over nine models is not inlined by GCC, which costs a
/// call per BSDF query).
template <size_t I = 0, class F>
inline decltype(auto) dispatch_model(const BsdfModel& model, F&& f) {
  if constexpr (I + 1 == std::variant_size_v<BsdfModel>) {
    return f(*std::get_if<I>(&model));
  } else {
    if (model.index() == I) return f(*std::get_if<I>(&model));
    return dispatch_model<I + 1>(model, std::forward<F>(f));
  }
}

/// Whether a model scatters only into delta lobes (mirror, smooth metal, glass): light
/// sampling is useless there, and an integrator skips it.
inline bool is_delta_only(const BsdfModel& model) {
  return std::holds_alternative<Mirror>(model) || std::holds_alternative<SmoothConductor>(model) ||
         std::holds_alternative<SmoothDielectric>(model) ||
         std::holds_alternative<ThinDielectric>(model);
}

/// Whether a model lets light through the surface (the integrator must then not require the
/// light to be on the side of wo).
inline bool is_transmissive(const BsdfModel& model) {
  return std::holds_alternative<SmoothDielectric>(model) ||
         std::holds_alternative<ThinDielectric>(model);
}

/// Whether a model's sample() reads its 1D lobe choice: the models with two lobes to choose
/// between (a coat and a base, reflection and refraction). The others ignore it, and an
/// integrator need not compute the number.
inline bool reads_lobe_choice(const BsdfModel& model) {
  return std::holds_alternative<Plastic>(model) || std::holds_alternative<SmoothDielectric>(model) ||
         std::holds_alternative<ThinDielectric>(model) || std::holds_alternative<MetallicPaint>(model);
}

/// Whether a model's sample() reads its 2D point: the models with a lobe that is not a delta.
inline bool reads_direction_sample(const BsdfModel& model) {
  return std::holds_alternative<Lambertian>(model) || std::holds_alternative<RoughConductor>(model) ||
         std::holds_alternative<Plastic>(model) || std::holds_alternative<Velvet>(model) ||
         std::holds_alternative<MetallicPaint>(model);
}

// [ch12-bsdf]
/// A BSDF in world space: a model and the shading frame it lives in. Directions passed in
/// and out are world-space unit vectors pointing away from the surface. Every query goes
/// through dispatch_model, which the compiler inlines, rather than std::visit, which it does not.
class Bsdf {
 public:
  /// A model placed in a frame whose n is the shading normal.
  Bsdf(const Frame& frame, const BsdfModel& model) : frame_(frame), model_(model) {}

  /// f(wo, wi), without the cosine; zero for delta lobes.
  Color eval(Vec3f wo, Vec3f wi) const {
    const Vec3f lo = frame_.to_local(wo), li = frame_.to_local(wi);
    return dispatch_model(model_, [&](const auto& m) { return m.eval(lo, li); });
  }
  /// The solid-angle density with which sample() returns wi (non-delta lobes only).
  float pdf(Vec3f wo, Vec3f wi) const {
    const Vec3f lo = frame_.to_local(wo), li = frame_.to_local(wi);
    return dispatch_model(model_, [&](const auto& m) { return m.pdf(lo, li); });
  }
  /// A sampled direction (world space) from a 1D lobe choice and a 2D sample.
  std::optional<BsdfSample> sample(Vec3f wo, float u_lobe, Vec2f u) const {
    const Vec3f lo = frame_.to_local(wo);
    std::optional<BsdfSample> s =
        dispatch_model(model_, [&](const auto& m) { return m.sample(lo, u_lobe, u); });
    if (s) s->wi = frame_.to_world(s->wi);
    return s;
  }

  /// Whether all lobes are deltas.
  bool delta_only() const { return is_delta_only(model_); }
  /// Whether light passes through (lights behind the surface can then contribute).
  bool transmissive() const { return is_transmissive(model_); }
  /// The shading frame.
  const Frame& frame() const { return frame_; }
  /// The model.
  const BsdfModel& model() const { return model_; }

 private:
  Frame frame_;
  BsdfModel model_;
};
// [ch12-bsdf]

}  // namespace rtk
