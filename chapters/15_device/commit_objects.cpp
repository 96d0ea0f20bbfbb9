// What commit() builds for each kind of object, and the parameter reader it builds from.
// Chapter 15's reference lists the same types and parameters; keep the two in step.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "13_lights/distant_light.h"
#include "13_lights/environment_light.h"
#include "13_lights/point_light.h"
#include "15_device/device_objects.h"
#include "15_device/sphere_mesh.h"

namespace rtk::device_detail {

const Object& object_of(const Handle& handle) {
  if (!handle.object_) throw std::invalid_argument("rtk device: null handle");
  return *handle.object_;
}

// ---------------------------------------------------------------------------------------------
// Types
// ---------------------------------------------------------------------------------------------

namespace {

const std::vector<std::string>& types_of(ObjectKind kind) {
  static const std::vector<std::string> camera{"pinhole", "thinlens"}, texture{"image", "constant"},
      light{"point", "directional", "distant", "ambient", "triangle", "quad", "environment"},
      shape{"trianglemesh", "sphere"}, scene{"default", "imported"}, renderer{"pathtracer", "debug"},
      framebuffer{"rgb"}, none{};
  switch (kind) {
    case ObjectKind::camera: return camera;
    case ObjectKind::texture: return texture;
    case ObjectKind::light: return light;
    case ObjectKind::shape: return shape;
    case ObjectKind::scene: return scene;
    case ObjectKind::renderer: return renderer;
    case ObjectKind::framebuffer: return framebuffer;
    case ObjectKind::material: return none;
  }
  return none;
}

const char* value_type_name(const DeviceValue& v) {
  static const char* names[] = {"int", "float", "vec3", "string", "float array", "int array", "handle", "handle list"};
  return names[v.index()];
}

}  // namespace

bool known_type(ObjectKind kind, std::string_view type) {
  // A material's type is chapter 12's model name; an unknown one becomes a grey Matte with a
  // warning at commit, as in the scene files.
  if (kind == ObjectKind::material) return !type.empty();
  const auto& t = types_of(kind);
  return std::find(t.begin(), t.end(), type) != t.end();
}

std::string known_types(ObjectKind kind) {
  if (kind == ObjectKind::material) return "any of chapter 12's material names";
  std::string s;
  for (const std::string& t : types_of(kind)) s += (s.empty() ? "" : ", ") + t;
  return s;
}

// ---------------------------------------------------------------------------------------------
// ParamReader
// ---------------------------------------------------------------------------------------------

void ParamReader::fail(std::string_view name, const std::string& message) const {
  throw std::invalid_argument("rtk device: " + object_.describe() + ": parameter '" + std::string(name) + "': " + message);
}

void ParamReader::fail(const std::string& message) const {
  throw std::invalid_argument("rtk device: " + object_.describe() + ": " + message);
}

const DeviceValue* ParamReader::find(std::string_view name) const {
  auto it = params_.find(name);
  if (it == params_.end()) return nullptr;
  used_.insert(std::string(name));
  return &it->second;
}

float ParamReader::get_float(std::string_view name, float fallback) const {
  const DeviceValue* v = find(name);
  if (!v) return fallback;
  float f = 0;
  if (const float* p = std::get_if<float>(v)) f = *p;
  else if (const int* i = std::get_if<int>(v)) f = static_cast<float>(*i);
  else fail(name, std::string("expected a float, got a ") + value_type_name(*v));
  if (!std::isfinite(f)) fail(name, "not a finite number");
  return f;
}

float ParamReader::require_float(std::string_view name) const {
  if (!has(name)) fail(name, "required");
  return get_float(name, 0);
}

int ParamReader::get_int(std::string_view name, int fallback) const {
  const DeviceValue* v = find(name);
  if (!v) return fallback;
  if (const int* i = std::get_if<int>(v)) return *i;
  fail(name, std::string("expected an int, got a ") + value_type_name(*v));
}

Vec3f ParamReader::get_vec3(std::string_view name, Vec3f fallback) const {
  const DeviceValue* v = find(name);
  if (!v) return fallback;
  Vec3f r;
  if (const Vec3f* p = std::get_if<Vec3f>(v)) r = *p;
  else if (std::holds_alternative<float>(*v) || std::holds_alternative<int>(*v)) {
    const float f = get_float(name, 0);
    r = {f, f, f};
  } else fail(name, std::string("expected a vec3, got a ") + value_type_name(*v));
  if (!std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z)) fail(name, "not finite");
  return r;
}

Vec3f ParamReader::require_vec3(std::string_view name) const {
  if (!has(name)) fail(name, "required");
  return get_vec3(name, {});
}

std::string ParamReader::get_string(std::string_view name, std::string fallback) const {
  const DeviceValue* v = find(name);
  if (!v) return fallback;
  if (const std::string* s = std::get_if<std::string>(v)) return *s;
  fail(name, std::string("expected a string, got a ") + value_type_name(*v));
}

std::vector<float> ParamReader::get_floats(std::string_view name, size_t group) const {
  const DeviceValue* v = find(name);
  if (!v) return {};
  const auto* a = std::get_if<std::vector<float>>(v);
  if (!a) fail(name, std::string("expected a float array, got a ") + value_type_name(*v));
  if (a->size() % group != 0)
    fail(name, "length " + std::to_string(a->size()) + " is not a multiple of " + std::to_string(group));
  for (size_t i = 0; i < a->size(); ++i)
    if (!std::isfinite((*a)[i])) fail(name, "element " + std::to_string(i) + " is not finite");
  return *a;
}

std::vector<int> ParamReader::get_ints(std::string_view name, size_t group) const {
  const DeviceValue* v = find(name);
  if (!v) return {};
  const auto* a = std::get_if<std::vector<int>>(v);
  if (!a) fail(name, std::string("expected an int array, got a ") + value_type_name(*v));
  if (a->size() % group != 0)
    fail(name, "length " + std::to_string(a->size()) + " is not a multiple of " + std::to_string(group));
  return *a;
}

std::shared_ptr<const Version> ParamReader::version_of(std::string_view name, const Handle& h, ObjectKind kind) const {
  const Object& o = object_of(h);
  if (o.kind != kind)
    fail(name, std::string("expected a ") + kind_name(kind) + ", got " + o.describe());
  std::lock_guard lock(o.mutex);
  if (!o.current) fail(name, o.describe() + " was never committed");
  return o.current;
}

std::shared_ptr<const Version> ParamReader::get_version(std::string_view name, ObjectKind kind) const {
  const DeviceValue* v = find(name);
  if (!v) return nullptr;
  const Handle* h = std::get_if<Handle>(v);
  if (!h) fail(name, std::string("expected a handle, got a ") + value_type_name(*v));
  return version_of(name, *h, kind);
}

std::vector<std::shared_ptr<const Version>> ParamReader::get_versions(std::string_view name, ObjectKind kind) const {
  const DeviceValue* v = find(name);
  if (!v) return {};
  std::vector<std::shared_ptr<const Version>> out;
  if (const Handle* h = std::get_if<Handle>(v)) out.push_back(version_of(name, *h, kind));
  else if (const auto* list = std::get_if<std::vector<Handle>>(v))
    for (const Handle& e : *list) out.push_back(version_of(name, e, kind));
  else fail(name, std::string("expected a list of handles, got a ") + value_type_name(*v));
  return out;
}

ParameterList ParamReader::remaining_as_material_parameters() const {
  ParameterList list;
  for (const auto& [name, value] : params_) {
    if (used_.count(name)) continue;
    used_.insert(name);
    if (const int* i = std::get_if<int>(&value)) list.set(name, *i);
    else if (const float* f = std::get_if<float>(&value)) list.set(name, *f);
    else if (const Vec3f* c = std::get_if<Vec3f>(&value)) list.set(name, Color(c->x, c->y, c->z));
    else if (const std::string* s = std::get_if<std::string>(&value)) list.set(name, *s);
    else if (const auto* a = std::get_if<std::vector<float>>(&value); a && a->size() == 2)
      list.set(name, Vec2f{(*a)[0], (*a)[1]});
    else if (std::holds_alternative<Handle>(value))
      list.set(name, std::static_pointer_cast<const TextureVersion>(version_of(name, std::get<Handle>(value), ObjectKind::texture))->texture);
    else fail(name, std::string("a material parameter cannot be a ") + value_type_name(value));
  }
  return list;
}

void ParamReader::finish() const {
  for (const auto& [name, value] : params_)
    if (!used_.count(name)) fail(name, std::string("unknown parameter for a ") + kind_name(object_.kind) + " of type '" + object_.type + "'");
}

// ---------------------------------------------------------------------------------------------
// One builder per kind
// ---------------------------------------------------------------------------------------------

namespace {

std::shared_ptr<const Version> build_camera(const Object& o, const ParamReader& p) {
  auto v = std::make_shared<CameraVersion>(o.counters);
  CameraParams& c = v->params;
  c.position = p.get_vec3("position", c.position);
  c.look_at = p.get_vec3("lookAt", c.look_at);
  c.up = p.get_vec3("up", c.up);
  c.fov_degrees = p.get_float("fov", c.fov_degrees);
  const int handed = p.get_int("rightHanded", 0);
  if (handed != 0 && handed != 1) p.fail("rightHanded", "must be 0 (left-handed, Embree 1.1) or 1");
  c.right_handed = handed == 1;
  const int vignetting = p.get_int("vignetting", 0);
  if (vignetting != 0 && vignetting != 1) p.fail("vignetting", "must be 0 (none) or 1 (cos^4 falloff)");
  c.vignetting = vignetting == 1;
  if (o.type == "thinlens") {
    c.lens_radius = p.get_float("radius", c.lens_radius);
    c.focal_distance = p.get_float("focalDistance", c.focal_distance);
  }
  p.finish();
  try {
    Camera check(c);  // the same checks the renderer makes, at commit rather than at render
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  }
  return v;
}

std::shared_ptr<const Version> build_texture(const Object& o, const ParamReader& p) {
  auto v = std::make_shared<TextureVersion>(o.counters);
  if (o.type == "constant") {
    const Vec3f c = p.get_vec3("color", {1, 1, 1});
    v->texture = std::make_shared<ConstantTexture>(Color(c.x, c.y, c.z));
  } else {
    if (!p.has("filename")) p.fail("filename", "required");
    const std::string file = p.get_string("filename", "");
    const std::string enc = p.get_string("encoding", "srgb");
    if (enc != "srgb" && enc != "linear") p.fail("encoding", "expected \"srgb\" or \"linear\", got \"" + enc + "\"");
    p.finish();
    try {
      v->texture = load_image_texture(file, enc == "srgb" ? ColorEncoding::srgb : ColorEncoding::linear);
    } catch (const std::exception& e) {
      p.fail("filename", e.what());
    }
  }
  p.finish();
  return v;
}

std::shared_ptr<const Version> build_material(const Object& o, const ParamReader& p, const WarningHandler& warn) {
  auto v = std::make_shared<MaterialVersion>(o.counters);
  const ParameterList list = p.remaining_as_material_parameters();
  const std::string what = o.describe();
  try {
    v->material = make_material(o.type, list, [&](const std::string& m) {
      if (warn) warn("rtk device: " + what + ": " + m);
    });
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  }
  return v;
}

Color color_of(Vec3f v) { return Color(v.x, v.y, v.z); }

std::shared_ptr<const Version> build_light(const Object& o, const ParamReader& p) {
  auto v = std::make_shared<LightVersion>(o.counters);
  const std::string& t = o.type;
  try {
    if (t == "point") {
      v->light = std::make_shared<PointLight>(p.require_vec3("position"), color_of(p.require_vec3("I")));
    } else if (t == "directional") {
      v->light = std::make_shared<DirectionalLight>(p.require_vec3("direction"), color_of(p.require_vec3("E")));
    } else if (t == "distant") {
      v->light = std::make_shared<DistantLight>(p.require_vec3("direction"), color_of(p.require_vec3("L")),
                                                p.require_float("halfAngle"));
    } else if (t == "ambient") {
      v->light = std::make_shared<AmbientLight>(color_of(p.require_vec3("L")));
    } else if (t == "triangle") {
      v->radiance = color_of(p.require_vec3("L"));
      v->triangles.push_back(std::make_shared<TriangleLight>(p.require_vec3("v0"), p.require_vec3("v1"),
                                                             p.require_vec3("v2"), v->radiance));
    } else if (t == "quad") {
      v->radiance = color_of(p.require_vec3("L"));
      v->triangles = make_quad_light(p.require_vec3("P"), p.require_vec3("U"), p.require_vec3("V"), v->radiance);
    } else {  // environment
      if (!p.has("filename")) p.fail("filename", "required");
      const Color scale = color_of(p.get_vec3("L", {1, 1, 1}));
      v->light = std::make_shared<EnvironmentLight>(load_environment_image(p.get_string("filename", "")), scale);
    }
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    if (m.rfind("rtk device:", 0) == 0) throw;
    p.fail(m);
  } catch (const std::runtime_error& e) {
    p.fail(e.what());
  }
  p.finish();
  return v;
}

std::shared_ptr<const Version> build_shape(const Object& o, const ParamReader& p) {
  auto v = std::make_shared<ShapeVersion>(o.counters);
  v->material = std::static_pointer_cast<const MaterialVersion>(p.get_version("material", ObjectKind::material));
  auto vec3s = [](const std::vector<float>& f) {
    std::vector<Vec3f> out(f.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) out[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
    return out;
  };
  if (o.type == "sphere") {
    const Vec3f centre = p.get_vec3("center", {0, 0, 0});
    const float radius = p.get_float("radius", 1.0f);
    try {
      SphereMesh m = tessellate_sphere(centre, radius, p.get_int("numTheta", 32), p.get_int("numPhi", 32));
      v->vertices = std::move(m.vertices);
      v->normals = std::move(m.normals);
      v->triangles = std::move(m.triangles);
    } catch (const std::invalid_argument& e) {
      p.fail(e.what());
    }
    if (p.has("motion")) {
      const Vec3f d = p.get_vec3("motion", {});
      for (const Vec3f& x : v->vertices) v->vertices_t1.push_back(x + d);
    }
  } else {
    if (!p.has("positions")) p.fail("positions", "required");
    if (!p.has("indices")) p.fail("indices", "required");
    v->vertices = vec3s(p.get_floats("positions", 3));
    const std::vector<int> idx = p.get_ints("indices", 3);
    for (size_t i = 0; i < idx.size(); ++i)
      if (idx[i] < 0 || static_cast<size_t>(idx[i]) >= v->vertices.size())
        p.fail("indices", "index " + std::to_string(idx[i]) + " at position " + std::to_string(i) +
                              " is out of range (" + std::to_string(v->vertices.size()) + " vertices)");
    for (size_t i = 0; i < idx.size(); i += 3)
      v->triangles.push_back({uint32_t(idx[i]), uint32_t(idx[i + 1]), uint32_t(idx[i + 2])});
    v->normals = vec3s(p.get_floats("normals", 3));
    v->vertices_t1 = vec3s(p.get_floats("positions1", 3));
    const std::vector<float> uv = p.get_floats("texcoords", 2);
    for (size_t i = 0; i < uv.size(); i += 2) v->uvs.push_back({uv[i], uv[i + 1]});
    auto per_vertex = [&](const char* name, size_t n) {
      if (n != 0 && n != v->vertices.size())
        p.fail(name, std::to_string(n) + " entries for " + std::to_string(v->vertices.size()) + " vertices");
    };
    per_vertex("normals", v->normals.size());
    per_vertex("positions1", v->vertices_t1.size());
    per_vertex("texcoords", v->uvs.size());
  }
  p.finish();
  return v;
}

// [ch15-scene-commit]
std::shared_ptr<const Version> build_scene(const Object& o, const ParamReader& p, const KernelFactory& kernels) {
  auto v = std::make_shared<SceneVersion>(o.counters);
  const bool imported = o.type == "imported";
  if (imported && (p.has("shapes") || p.has("lights")))
    p.fail(p.has("shapes") ? "shapes" : "lights", "an imported scene has its content already");
  const auto shapes = imported ? std::vector<std::shared_ptr<const Version>>{} : p.get_versions("shapes", ObjectKind::shape);
  const auto lights = imported ? std::vector<std::shared_ptr<const Version>>{} : p.get_versions("lights", ObjectKind::light);
  AccelConfig config;
  config.accel = p.get_string("accel", "");
  config.tri = p.get_string("tri", "");
  const std::string isa = p.get_string("isa", "");
  config.threads = p.get_int("threads", 1);
  if (config.threads < 0) p.fail("threads", "must be 0 (every core) or more");
  p.finish();
  if (!isa.empty()) {
    config.isa = parse_isa(isa);
    if (!config.isa) p.fail("isa", "unknown ISA '" + isa + "' (scalar, sse4, avx2, avx512)");
  }
  // Merge the shapes into one mesh, as chapter 14's RenderScene wants: vertex numbers are
  // offset, materials shared between shapes are stored once. An imported scene is merged.
  RenderScene& sc = v->scene;
  if (imported) sc = *o.imported;
  const bool any_normals = std::any_of(shapes.begin(), shapes.end(), [](auto& s) { return !static_cast<const ShapeVersion&>(*s).normals.empty(); });
  const bool any_uvs = std::any_of(shapes.begin(), shapes.end(), [](auto& s) { return !static_cast<const ShapeVersion&>(*s).uvs.empty(); });
  const bool any_motion = std::any_of(shapes.begin(), shapes.end(), [](auto& s) { return !static_cast<const ShapeVersion&>(*s).vertices_t1.empty(); });
  std::map<const MaterialVersion*, uint32_t> material_index;
  for (const auto& base : shapes) {
    const auto& s = static_cast<const ShapeVersion&>(*base);
    uint32_t material;
    if (auto it = material_index.find(s.material.get()); it != material_index.end()) material = it->second;
    else material = material_index[s.material.get()] = sc.add_material(s.material ? s.material->material : Material{});
    const auto first = static_cast<uint32_t>(sc.mesh.vertices.size());
    sc.mesh.vertices.insert(sc.mesh.vertices.end(), s.vertices.begin(), s.vertices.end());
    if (any_normals) {
      if (s.normals.empty()) sc.normals.resize(sc.normals.size() + s.vertices.size(), Vec3f{0, 0, 0});
      else sc.normals.insert(sc.normals.end(), s.normals.begin(), s.normals.end());
    }
    if (any_uvs) {
      if (s.uvs.empty()) sc.uvs.resize(sc.uvs.size() + s.vertices.size(), Vec2f{0, 0});
      else sc.uvs.insert(sc.uvs.end(), s.uvs.begin(), s.uvs.end());
    }
    if (any_motion) {
      const auto& t1 = s.vertices_t1.empty() ? s.vertices : s.vertices_t1;
      sc.vertices_t1.insert(sc.vertices_t1.end(), t1.begin(), t1.end());
    }
    for (const auto& t : s.triangles) {
      sc.mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
      sc.triangle_material.push_back(material);
      sc.triangle_light.push_back(kNoLight);
    }
  }
  // Lights: area lights become emitting triangles of the mesh (rays must be able to hit
  // them), the others are added as they are.
  for (const auto& base : lights) {
    const auto& l = static_cast<const LightVersion&>(*base);
    if (l.light) {
      sc.add_light(l.light);
      continue;
    }
    sc.add_area_light(l.triangles, l.radiance);
  }
  if (sc.mesh.triangles.empty()) p.fail("shapes", "the scene has no triangles (give it at least one shape)");
  try {
    sc.validate();
    RenderKernels built = kernels ? kernels(sc, config) : make_rtk_kernels(sc, config);
    v->kernels = std::move(built.kernels);
    v->kernels_summary = std::move(built.summary);
  } catch (const std::invalid_argument& e) {
    p.fail(e.what());
  } catch (const std::runtime_error& e) {  // another system's kernels may fail to build
    p.fail(e.what());
  }
  v->parts.insert(v->parts.end(), shapes.begin(), shapes.end());
  v->parts.insert(v->parts.end(), lights.begin(), lights.end());
  return v;
}
// [ch15-scene-commit]

std::shared_ptr<const Version> build_renderer(const Object& o, const ParamReader& p) {
  auto v = std::make_shared<RendererVersion>(o.counters);
  RenderOptions& r = v->options;
  r.spp = p.get_int("spp", r.spp);
  r.seed = static_cast<uint32_t>(p.get_int("seed", 0));
  r.threads = p.get_int("threads", r.threads);
  r.tile_size = p.get_int("tileSize", r.tile_size);
  if (o.type == "debug") {
    r.eye_light = true;
  } else {
    r.max_depth = p.get_int("maxDepth", r.max_depth);
    r.rr_depth = p.get_int("rrDepth", r.rr_depth);
    r.min_contribution = p.get_float("minContribution", r.min_contribution);
  }
  try {
    if (p.has("sampler")) r.sampler = parse_sampler_type(p.get_string("sampler", ""));
  } catch (const std::invalid_argument& e) {
    p.fail("sampler", e.what());
  }
  try {
    if (p.has("filter")) r.filter = parse_filter_type(p.get_string("filter", ""));
  } catch (const std::invalid_argument& e) {
    p.fail("filter", e.what());
  }
  r.filter_radius = p.get_float("filterRadius", 0);
  r.progress = p.get_int("progress", 0) != 0;
  p.finish();
  if (r.spp < 1) p.fail("spp", "must be at least 1");
  if (r.max_depth < 0) p.fail("maxDepth", "must not be negative");
  if (r.rr_depth < 0) p.fail("rrDepth", "must not be negative");
  if (!(r.min_contribution >= 0.0f && std::isfinite(r.min_contribution)))
    p.fail("minContribution", "must be a finite number, 0 or more");
  if (r.threads < 0) p.fail("threads", "must be 0 (every core) or more");
  if (r.tile_size < 1) p.fail("tileSize", "must be at least 1");
  if (r.filter_radius < 0) p.fail("filterRadius", "must not be negative");
  return v;
}

std::shared_ptr<const Version> build_framebuffer(const Object& o, const ParamReader& p) {
  const int w = p.get_int("width", 512), h = p.get_int("height", 512);
  p.finish();
  constexpr int kMax = 1 << 15;
  if (w < 1 || w > kMax) p.fail("width", "must be in [1, 32768] (got " + std::to_string(w) + ")");
  if (h < 1 || h > kMax) p.fail("height", "must be in [1, 32768] (got " + std::to_string(h) + ")");
  return std::make_shared<FramebufferVersion>(o.counters, w, h);
}

}  // namespace

std::shared_ptr<const Version> build_version(const Object& o, const ParamMap& params, const CommitContext& context) {
  const WarningHandler& warn = context.warn;
  const ParamReader p(o, params);
  switch (o.kind) {
    case ObjectKind::camera: return build_camera(o, p);
    case ObjectKind::material: return build_material(o, p, warn);
    case ObjectKind::texture: return build_texture(o, p);
    case ObjectKind::light: return build_light(o, p);
    case ObjectKind::shape: return build_shape(o, p);
    case ObjectKind::scene: return build_scene(o, p, context.kernels);
    case ObjectKind::renderer: return build_renderer(o, p);
    case ObjectKind::framebuffer: return build_framebuffer(o, p);
  }
  p.fail("unknown object kind");
}

}  // namespace rtk::device_detail
