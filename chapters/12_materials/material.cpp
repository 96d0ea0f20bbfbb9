#include "12_materials/material.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "12_materials/microfacet.h"

namespace rtk {

// Parameters ---------------------------------------------------------------------------------

const ParameterValue* ParameterList::find(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return nullptr;
  used_.insert(name);
  return &it->second;
}

namespace {
[[noreturn]] void wrong_type(const std::string& name, const char* expected) {
  throw std::invalid_argument("material parameter '" + name + "' must be " + expected);
}
}  // namespace

float ParameterList::get_float(const std::string& name, float fallback) const {
  const ParameterValue* v = find(name);
  if (!v) return fallback;
  if (const float* f = std::get_if<float>(v)) return *f;
  if (const int* i = std::get_if<int>(v)) return static_cast<float>(*i);
  wrong_type(name, "a number");
}

Color ParameterList::get_color(const std::string& name, Color fallback) const {
  const ParameterValue* v = find(name);
  if (!v) return fallback;
  if (const Color* c = std::get_if<Color>(v)) return *c;
  if (const float* f = std::get_if<float>(v)) return Color(*f);
  if (const int* i = std::get_if<int>(v)) return Color(static_cast<float>(*i));
  wrong_type(name, "a colour (float3) or a number");
}

Vec2f ParameterList::get_float2(const std::string& name, Vec2f fallback) const {
  const ParameterValue* v = find(name);
  if (!v) return fallback;
  if (const Vec2f* p = std::get_if<Vec2f>(v)) return *p;
  wrong_type(name, "a float2");
}

std::shared_ptr<const Texture> ParameterList::get_texture(const std::string& name) const {
  const ParameterValue* v = find(name);
  if (!v) return nullptr;
  if (const auto* t = std::get_if<std::shared_ptr<const Texture>>(v)) return *t;
  if (std::holds_alternative<std::string>(*v) || std::holds_alternative<Vec2f>(*v))
    wrong_type(name, "a texture, a colour or a number");
  used_.erase(name);  // get_color marks it used again
  return std::make_shared<ConstantTexture>(get_color(name, Color()));
}

std::vector<std::string> ParameterList::unused() const {
  std::vector<std::string> names;
  for (const auto& [name, value] : values_)
    if (!used_.count(name)) names.push_back(name);
  return names;
}

// Materials ----------------------------------------------------------------------------------

float Material::opacity_at(Vec2f uv) const {
  if (!opacity_map) return opacity;
  return std::clamp(opacity * average(opacity_map->eval(uv)), 0.0f, 1.0f);
}

// [ch12-bump]
Vec3f Material::bumped_normal(Vec3f n, Vec3f dpdu, Vec3f dpdv, Vec2f uv) const {
  if (!bump) return n;
  // The height's slopes by central differences, half a texel to each side of uv (a
  // thousandth of the unit square for a texture that is not an image).
  float du = 1e-3f, dv = 1e-3f;
  if (const auto* image = dynamic_cast<const ImageTexture*>(bump.get()))
    du = 0.5f / image->width(), dv = 0.5f / image->height();
  auto height = [&](float u, float v) { return bump_scale * average(bump->eval({u, v})); };
  const float h_u = (height(uv.x + du, uv.y) - height(uv.x - du, uv.y)) / (2.0f * du);
  const float h_v = (height(uv.x, uv.y + dv) - height(uv.x, uv.y - dv)) / (2.0f * dv);
  // The surface displaced by h along n has tangents dpdu + h_u n and dpdv + h_v n (the
  // change of n itself is neglected: the heights are small); their cross product is the
  // displaced surface's normal, turned to n's side.
  const Vec3f m = cross(dpdu + h_u * n, dpdv + h_v * n);
  const float len = length(m);
  if (!(len > 0.0f) || !std::isfinite(len)) return n;
  return dot(m, n) < 0.0f ? -m / len : m / len;
}
// [ch12-bump]

namespace {

// The narrowest flake lobe (glitterSpread 0): a GGX width below this is sampled and
// evaluated with large rounding errors in single precision.
constexpr float kMinFlakeAlpha = 0.01f;

std::string lower(std::string_view s) {
  std::string r(s);
  std::transform(r.begin(), r.end(), r.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return r;
}

// Validation of values that would make a BSDF produce NaN.
float positive(float v, const char* what) {
  if (!(v > 0.0f) || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " must be a positive number");
  return v;
}
float non_negative(float v, const char* what) {
  if (!(v >= 0.0f) || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " must be >= 0");
  return v;
}
Color non_negative(Color c, const char* what) {
  if (!(c.r >= 0 && c.g >= 0 && c.b >= 0) || !is_finite(c))
    throw std::invalid_argument(std::string(what) + " must be >= 0");
  return c;
}
Color positive(Color c, const char* what) {
  if (!(c.r > 0 && c.g > 0 && c.b > 0) || !is_finite(c))
    throw std::invalid_argument(std::string(what) + " must be > 0");
  return c;
}

// The diffuse colour: a texture when one is given, the constant otherwise.
void diffuse(Material& m, const ParameterList& p, const std::string& name, Color fallback) {
  std::shared_ptr<const Texture> t = p.get_texture(name);
  if (!t) t = std::make_shared<ConstantTexture>(fallback);
  if (const auto* c = dynamic_cast<const ConstantTexture*>(t.get())) {
    non_negative(c->color(), name.c_str());
    if (auto* l = std::get_if<Lambertian>(&m.prototype)) l->reflectance = c->color();
    if (auto* q = std::get_if<Plastic>(&m.prototype)) q->pigment = c->color();
    if (auto* v = std::get_if<Velvet>(&m.prototype)) v->reflectance = c->color();
    if (auto* q = std::get_if<MetallicPaint>(&m.prototype)) q->shade = c->color();
  } else {
    m.albedo = std::move(t);
  }
}

Material make_plastic(const ParameterList& p, const std::string& color_name, Color color, float eta,
                      float roughness) {
  Material m;
  m.name = "Plastic";
  m.prototype = Plastic{Color(), positive(eta, "eta"),
                        GgxDistribution{roughness_to_alpha(non_negative(roughness, "roughness"))}};
  diffuse(m, p, color_name, color);
  return m;
}

}  // namespace

Material make_material(std::string_view name_in, const ParameterList& p,
                       const WarningHandler& warn_in) {
  const WarningHandler warn = warn_in ? warn_in : [](const std::string&) {};
  const std::string name = lower(name_in);
  Material m;
  if (name == "matte") {
    m.prototype = Lambertian{};
    diffuse(m, p, "reflectance", Color(0.5f));
  } else if (name == "mattetextured") {
    m.prototype = Lambertian{};
    diffuse(m, p, "Kd", Color(0.5f));
    const Vec2f s0 = p.get_float2("s0", {0, 0}), ds = p.get_float2("ds", {1, 1});
    if (m.albedo && !(s0 == Vec2f{0, 0} && ds == Vec2f{1, 1}))
      m.albedo = std::make_shared<MappedTexture>(m.albedo, s0, ds);
  } else if (name == "velvet") {
    m.name = "Velvet";
    Velvet v;
    v.back_scattering = non_negative(p.get_float("backScattering", v.back_scattering), "backScattering");
    v.horizon = non_negative(p.get_color("horizonScatteringColor", v.horizon), "horizonScatteringColor");
    v.horizon_falloff =
        non_negative(p.get_float("horizonScatteringFallOff", v.horizon_falloff), "horizonScatteringFallOff");
    m.prototype = v;
    diffuse(m, p, "reflectance", Velvet{}.reflectance);
  } else if (name == "mirror") {
    m.name = "Mirror";
    const Color r = p.has("reflectivity") ? p.get_color("reflectivity", Color(1))
                                          : p.get_color("reflectance", Color(1));
    m.prototype = Mirror{non_negative(r, "reflectance")};
  } else if (name == "metal") {
    m.name = "Metal";
    // Default: aluminium, roughly, at the red, green and blue wavelengths.
    const Color eta = positive(p.get_color("eta", Color(1.5f, 0.96f, 0.62f)), "eta");
    const Color k = non_negative(p.get_color("k", Color(7.8f, 6.7f, 5.5f)), "k");
    const float alpha =
        roughness_to_alpha(non_negative(p.get_float("roughness", 0.01f), "roughness"));
    // Embree 1.1's reflectance colours the metal: a factor on its Fresnel term.
    const Color r = non_negative(p.get_color("reflectance", Color(1)), "reflectance");
    if (alpha == 0.0f)
      m.prototype = SmoothConductor{eta, k, r};
    else
      m.prototype = RoughConductor{eta, k, GgxDistribution{alpha}, r};
  } else if (name == "dielectric" || name == "glass") {
    m.name = "Dielectric";
    const float inside = positive(p.get_float("etaInside", 1.4f), "etaInside");
    const float outside = positive(p.get_float("etaOutside", 1.0f), "etaOutside");
    m.prototype = SmoothDielectric{
        inside / outside, non_negative(p.get_color("transmission", Color(1)), "transmission")};
  } else if (name == "thindielectric" || name == "thinglass") {
    m.name = "ThinDielectric";
    m.prototype =
        ThinDielectric{positive(p.get_float("eta", 1.4f), "eta"),
                       non_negative(p.get_color("transmission", Color(1)), "transmission"),
                       non_negative(p.get_float("thickness", 0.1f), "thickness")};
  } else if (name == "plastic") {
    m = make_plastic(p, "pigmentColor", Color(0.5f), p.get_float("eta", 1.4f),
                     p.get_float("roughness", 0.01f));
  } else if (name == "metallicpaint") {
    m.name = "MetallicPaint";
    MetallicPaint paint;
    paint.eta = positive(p.get_float("eta", paint.eta), "eta");
    paint.glitter = non_negative(p.get_color("glitterColor", Color()), "glitterColor");
    if (paint.glitter.r > 1 || paint.glitter.g > 1 || paint.glitter.b > 1)
      throw std::invalid_argument("glitterColor must be at most 1 (the flakes' share of the light)");
    // glitterSpread reads like a roughness (the reciprocal of a power-cosine exponent). A
    // spread of 0, flakes lying flat, is taken as the narrowest lobe that is still sampled
    // stably.
    const float spread = non_negative(p.get_float("glitterSpread", 1.0f), "glitterSpread");
    paint.flakes = GgxDistribution{std::max(roughness_to_alpha(spread), kMinFlakeAlpha)};
    m.prototype = paint;
    diffuse(m, p, "shadeColor", Color(0.5f));
  } else if (name == "obj") {
    // The MTL model: a diffuse colour, optionally a specular highlight.
    const Color ks = non_negative(p.get_color("Ks", Color()), "Ks");
    const float ns = p.get_float("Ns", 10.0f);
    const float ni = p.get_float("Ni", 1.5f);
    const std::string kd_name = p.has("map_Kd") ? "map_Kd" : "Kd";
    if (is_black(ks)) {
      m.prototype = Lambertian{};
      diffuse(m, p, kd_name, Color(1.0f));
    } else {
      warn(
          "OBJ: the specular colour Ks is approximated by a dielectric coat (Plastic) of index Ni "
          "and roughness 1/Ns");
      m = make_plastic(p, kd_name, Color(1.0f), ni > 1.0f ? ni : 1.5f,
                       ns > 0.0f ? 1.0f / ns : 0.0f);
    }
    if (p.has("map_Kd")) p.get_color("Kd", Color());  // superseded by the map, not unused
    // d, the dissolve: the share of the surface that is there (Tr = 1 - d is read as d).
    m.opacity = std::clamp(non_negative(p.get_float("d", 1.0f), "d"), 0.0f, 1.0f);
    m.opacity_map = p.get_texture("map_d");
    // The bump map: heights in scene units per unit of texture value, scaled by -bm.
    m.bump = p.get_texture("map_Bump");
    m.bump_scale = p.get_float("bump_scale", 1.0f);
    if (!std::isfinite(m.bump_scale)) throw std::invalid_argument("bump_scale must be finite");
    if (!is_black(p.get_color("Tf", Color()))) warn("OBJ: transmission filter Tf is not modelled");
    // Ka, the ambient colour, has no meaning in a path tracer, whose ambient light is the
    // light that bounces; Embree 1.1 ignored it too (its lamps give Ka 20), so it is read
    // without a warning. Emission is Ke.
    p.get_color("Ka", Color());
    p.get_float("illum", 0.0f);
    m.emission = non_negative(p.get_color("Ke", Color()), "Ke");
  } else {
    warn("unknown material '" + std::string(name_in) + "': rendered as a grey Matte");
    m.prototype = Lambertian{Color(0.5f)};
  }
  if (p.has("emission")) m.emission = non_negative(p.get_color("emission", Color()), "emission");
  for (const std::string& unused : p.unused())
    warn("material '" + std::string(name_in) + "': parameter '" + unused + "' is not used");
  return m;
}

}  // namespace rtk
