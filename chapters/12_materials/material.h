/// \file
/// Materials: what a scene file names ("Matte", "Plastic", "Metal", ...) turned into a BSDF
/// model, with textures and an optional emission.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "12_materials/bsdf.h"
#include "12_materials/texture.h"

namespace rtk {

/// One parameter of a material as a scene file gives it (the XML `<int>`, `<float>`,
/// `<float2>`, `<float3>` and `<texture>` elements, or an MTL line).
using ParameterValue =
    std::variant<int, float, Vec2f, Color, std::string, std::shared_ptr<const Texture>>;

/// Named parameters of a material. Getters convert where it is safe (an int or a float where a
/// colour is expected is a grey; a colour where a texture is expected is a constant texture)
/// and throw std::invalid_argument naming the parameter otherwise. The list remembers which
/// parameters were read, so that the ones nobody read can be reported.
class ParameterList {
 public:
  /// Sets (or replaces) a parameter.
  void set(const std::string& name, ParameterValue value) { values_[name] = std::move(value); }
  /// Whether a parameter is present.
  bool has(const std::string& name) const { return values_.count(name) != 0; }

  /// A scalar (int or float).
  float get_float(const std::string& name, float fallback) const;
  /// A colour (float3, or a scalar meaning grey).
  Color get_color(const std::string& name, Color fallback) const;
  /// A float2.
  Vec2f get_float2(const std::string& name, Vec2f fallback) const;
  /// A texture, or a constant texture made from a colour or scalar; null if absent and no
  /// fallback colour is given.
  std::shared_ptr<const Texture> get_texture(const std::string& name) const;

  /// The names of the parameters no getter has asked for, in alphabetical order.
  std::vector<std::string> unused() const;

 private:
  const ParameterValue* find(const std::string& name) const;
  std::map<std::string, ParameterValue> values_;
  mutable std::set<std::string> used_;
};

/// Receives the warnings of make_material (a parameter ignored, a material approximated).
using WarningHandler = std::function<void(const std::string&)>;

// [ch12-material]
/// A surface's appearance: a BSDF model with constant parameters, optionally a texture that
/// replaces its diffuse colour (Lambertian reflectance, Plastic pigment) point by point, and
/// the radiance the surface emits (non-zero for area lights).
struct Material {
  std::string name = "Matte";             ///< the model the scene's material became (for messages)
  BsdfModel prototype = Lambertian{};     ///< the BSDF model with its constant parameters
  std::shared_ptr<const Texture> albedo;  ///< the diffuse colour's texture, or null
  Color emission;                         ///< emitted radiance (OBJ Ke, or "emission")
  float opacity = 1.0f;                   ///< the share of the surface that is there (OBJ d)
  std::shared_ptr<const Texture> opacity_map;  ///< OBJ map_d: opacity point by point, or null
  std::shared_ptr<const Texture> bump;         ///< OBJ map_Bump: a height field, or null
  float bump_scale = 1.0f;                     ///< OBJ -bm: heights are scale * texture value

  /// The BSDF at a point with shading frame `frame` and texture coordinates `uv`. Inline: the
  /// path tracer makes one at every hit, and most materials have no texture.
  Bsdf make_bsdf(const Frame& frame, Vec2f uv) const {
    if (!albedo) return Bsdf(frame, prototype);
    BsdfModel model = prototype;
    const Color c = albedo->eval(uv);
    if (auto* l = std::get_if<Lambertian>(&model)) l->reflectance = c;
    if (auto* p = std::get_if<Plastic>(&model)) p->pigment = c;
    if (auto* v = std::get_if<Velvet>(&model)) v->reflectance = c;
    if (auto* q = std::get_if<MetallicPaint>(&model)) q->shade = c;
    return Bsdf(frame, model);
  }
  /// Whether the surface emits light.
  bool is_emissive() const { return !is_black(emission); }
  /// Whether light may pass through the surface without meeting it (d < 1 or a map_d).
  bool transparent() const { return opacity < 1.0f || opacity_map != nullptr; }
  /// The opacity at `uv`, in [0, 1]: opacity times the map's value (the mean of its channels).
  float opacity_at(Vec2f uv) const;
  /// The shading normal `n` tilted by the bump map at `uv`, for a surface whose position
  /// changes by dpdu and dpdv per unit of u and v; `n` itself without a bump map.
  Vec3f bumped_normal(Vec3f n, Vec3f dpdu, Vec3f dpdv, Vec2f uv) const;
};
// [ch12-material]

/// Builds a material from the name and parameters used by the Embree scene files (names are
/// matched without regard to case):
///   - Matte: reflectance (colour or texture);  MatteTextured: Kd (texture), s0, ds;
///   - Mirror: reflectance (or reflectivity);
///   - Metal: eta, k (colours), roughness (0: polished), reflectance (a colour on the Fresnel term);
///   - Dielectric / Glass: etaInside, etaOutside, transmission;
///   - ThinDielectric / ThinGlass: eta, transmission, thickness;
///   - Plastic: pigmentColor, eta, roughness;
///   - Velvet: reflectance (colour or texture), backScattering, horizonScatteringColor,
///     horizonScatteringFallOff (velvet.h);
///   - MetallicPaint: shadeColor (colour or texture), eta, glitterColor (the flakes' share
///     of the light, 0 to 1; default 0: no flakes), glitterSpread (the flakes' tilt, read
///     like a roughness; default 1) (metallic_paint.h);
///   - OBJ (the MTL keys): Kd or map_Kd; Ks > 0 becomes a Plastic whose roughness is 1 / Ns
///     (a warning says that Ks's magnitude is replaced by the Fresnel term); Tf
///     is ignored with a warning, Ka without one (as Embree 1.1 did); Ke is the emission;
///     d (or 1 - Tr) is the opacity and map_d its texture; map_Bump (or bump) a height
///     texture, scaled by bump_scale (the -bm option).
/// Any material may carry "emission" (a colour). An unknown name becomes a grey Matte, and
/// every parameter that was not used is reported, both through `warn`. Invalid values (a
/// negative index of refraction, a NaN) throw std::invalid_argument.
Material make_material(std::string_view name, const ParameterList& params,
                       const WarningHandler& warn = {});

}  // namespace rtk
