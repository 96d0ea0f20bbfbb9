#include "14_pathtracer/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "01_base/timer.h"
#include "14_pathtracer/ray_offset.h"

namespace rtk {

namespace {

CameraParams with_aspect(CameraParams params, const RenderOptions& options) {
  params.aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
  return params;
}

float scene_radius(const TriangleMesh& mesh) {
  const Box3f box = mesh.bounds();
  if (mesh.vertices.empty()) return 1.0f;
  const float r = 0.5f * length(box.upper - box.lower);
  return r > 0.0f ? r : 1.0f;
}

// A shadow ray stops this fraction short of the sampled light point, so that it does not find
// the light's own triangle there.
constexpr float kShadowShortening = 1.0f - 1e-4f;

// A ray passes through at most this many transparent surfaces; at the next it stops as if the
// surface were opaque (a bound on the work, not a limit any real scene meets).
constexpr uint16_t kMaxPassThrough = 256;

}  // namespace

// The state of one camera path between two batches of rays.
struct PathTracer::Path {
  Sampler sampler{SamplerType::sobol, 0};
  int x = 0, y = 0;
  Vec2f film;  // the camera sample's film position, for the backplate
  float filter_weight = 1.0f;
  Color throughput{1.0f};
  Color radiance;
  Color pending;          // next-event contribution waiting for its shadow ray
  int depth = 0;          // scattering events so far
  float prev_pdf = 0.0f;  // the density of the BSDF sample that made the current ray
  bool prev_delta = true; // whether it came from a delta lobe (or the camera): no MIS then
  uint16_t passes = 0;    // transparent surfaces passed through (in prev_delta's padding)
  Vec3f prev_p, prev_n;   // the previous vertex and its light-query normal (for pdf_li)
  Ray ray;
};

// The rays of one round, for all live paths of a tile.
struct PathTracer::Batch {
  std::vector<Ray> shadow_rays;
  std::vector<uint32_t> shadow_path;
  std::vector<uint32_t> next;  // paths that continue
};

PathTracer::PathTracer(const RenderScene& scene, const RayKernels& kernels,
                       const RenderOptions& options)
    : scene_(scene),
      kernels_(kernels.tracer()),
      options_(options),
      camera_(with_aspect(scene.camera, options)),
      filter_(options.filter, options.filter_radius) {
  scene.validate();
  // Lights are chosen in proportion to their power: a dim fill light gets few samples.
  const float radius = scene_radius(scene.mesh);
  std::vector<float> power;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = *scene.lights[i];
    const float p = luminance(light.power(radius));
    power.push_back(std::isfinite(p) && p > 0.0f ? p : 0.0f);
    triangle_lights_.push_back(dynamic_cast<const TriangleLight*>(&light));
    light_is_delta_.push_back(light.is_delta());
    if (light.is_infinite()) infinite_lights_.push_back(static_cast<uint32_t>(i));
  }
  if (!power.empty()) light_choice_ = std::make_unique<Distribution1D>(power);
  // What every hit would otherwise ask again: a material's kind, and, in a scene that does not
  // move, each triangle's unit normal (by the formula a hit would use, so bit for bit the same).
  for (const Material& m : scene.materials)
    material_traits_.push_back({is_delta_only(m.prototype), is_transmissive(m.prototype),
                                reads_lobe_choice(m.prototype), reads_direction_sample(m.prototype)});
  if (!scene.has_motion()) {
    face_normals_.reserve(scene.mesh.triangles.size());
    for (const auto& tri : scene.mesh.triangles) {
      const Vec3f v0 = scene.mesh.vertices[tri[0]], v1 = scene.mesh.vertices[tri[1]],
                  v2 = scene.mesh.vertices[tri[2]];
      face_normals_.push_back(normalize(cross(v1 - v0, v2 - v0)));
    }
  }
  uses_lens_ = camera_.params().lens_radius > 0.0f;
  transparency_ = scene.has_transparency();
}

// [ch14-transmittance]
// A shadow ray that the any-hit query found blocked, in a scene with transparent surfaces:
// followed from surface to surface, each transparent one letting the share 1 - opacity of the
// light through, until it reaches the light (the share left) or an opaque surface (none).
float PathTracer::transmittance(Ray ray, RenderStats& stats) const {
  float through = 1.0f;
  for (uint16_t pass = 0; pass < kMaxPassThrough; ++pass) {
    Hit hit;
    kernels_.intersect({&ray, 1}, {&hit, 1});
    ++stats.rays;
    if (!hit.found()) return through;
    const Material& m = scene_.materials[scene_.triangle_material[hit.prim]];
    if (!m.transparent()) return 0.0f;
    through *= 1.0f - m.opacity_at(scene_.texcoords(hit.prim, hit.u, hit.v));
    if (!(through > 0.0f)) return 0.0f;
    // On beyond the surface, for the rest of the segment.
    const auto c = scene_.corners(hit.prim, ray.time);
    const Vec3f ng = cross(c[1] - c[0], c[2] - c[0]);
    const Vec3f p = c[0] * (1.0f - hit.u - hit.v) + c[1] * hit.u + c[2] * hit.v;
    ray.org = offset_ray_origin(p, dot(ray.dir, ng) > 0.0f ? ng : -ng);
    ray.tfar -= hit.t;
    if (!(ray.tfar > 0.0f)) return through;
  }
  return 0.0f;
}
// [ch14-transmittance]

// [ch14-pass-through]
// A transparent surface is there with probability opacity: otherwise the ray goes on through
// it unchanged, neither scattered nor counted as a bounce (opacity 0 or 1 takes no random
// number, so that a cut-out renders as the geometry without the cut-out part).
bool PathTracer::passes_through(Path& path, const Hit& hit, Vec3f p, Vec3f ng) const {
  const Material& material = scene_.materials[scene_.triangle_material[hit.prim]];
  if (!material.transparent() || path.passes >= kMaxPassThrough) return false;
  const float opacity = material.opacity_at(scene_.texcoords(hit.prim, hit.u, hit.v));
  if (opacity >= 1.0f || (opacity > 0.0f && path.sampler.get_1d() < opacity)) return false;
  ++path.passes;
  path.ray.org = offset_ray_origin(p, dot(path.ray.dir, ng) > 0.0f ? ng : -ng);
  path.ray.tfar = std::numeric_limits<float>::infinity();
  return true;
}
// [ch14-pass-through]

// [ch14-escaped]
// A ray that leaves the scene sees the lights at infinity. Unless the ray came from the
// camera or a delta lobe, light sampling could have found the same direction, and the power
// heuristic weighs the two strategies.
Color PathTracer::escaped(const Path& path, Vec3f dir) const {
  Color sum;
  for (uint32_t i : infinite_lights_) {
    const Light& light = *scene_.lights[i];
    const Color le = light.le(dir);
    if (is_black(le)) continue;
    float weight = 1.0f;
    if (!path.prev_delta) {
      const float light_pdf = light_choice_->pmf(static_cast<int>(i)) *
                              light.pdf_li(LightQuery{path.prev_p, path.prev_n}, dir);
      weight = power_heuristic(path.prev_pdf, light_pdf);
    }
    sum += le * weight;
  }
  return sum;
}
// [ch14-escaped]

void PathTracer::shade(Path& path, const Ray& ray, const Hit& hit, Batch& batch,
                       uint32_t index) const {
  // Every ray of the path is born with a unit direction (the camera's, or a BSDF sample's
  // turned into world space), so it is not normalised again here.
  const Vec3f dir = ray.dir;
  if (!hit.found()) {
    // [ch14-backplate]
    // A camera ray that meets nothing sees the backplate, where there is one, at its film
    // position (film y grows downward, texture v upward).
    if (path.depth == 0 && scene_.backplate) {
      path.radiance += path.throughput * scene_.backplate->eval({path.film.x, 1.0f - path.film.y});
      return;
    }
    // [ch14-backplate]
    if (!infinite_lights_.empty()) path.radiance += path.throughput * escaped(path, dir);
    return;
  }
  // The hit point: from the barycentrics (more accurate than org + t dir), at the ray's time.
  // A scene that does not move has its triangles' normals ready.
  const auto& tri = scene_.mesh.triangles[hit.prim];
  Vec3f v[3];
  for (int k = 0; k < 3; ++k) v[k] = scene_.mesh.vertices[tri[k]];
  Vec3f ng;
  if (scene_.has_motion()) {
    for (int k = 0; k < 3; ++k) v[k] = v[k] + (scene_.vertices_t1[tri[k]] - v[k]) * ray.time;
    ng = normalize(cross(v[1] - v[0], v[2] - v[0]));
  } else {
    ng = face_normals_[hit.prim];
  }
  const float b0 = 1.0f - hit.u - hit.v;
  const Vec3f p = v[0] * b0 + v[1] * hit.u + v[2] * hit.v;
  const Vec3f wo = -dir;
  if (options_.eye_light) {
    // [ch14-debug]
    // The guide's debug renderer: |cos| between the ray and the surface. A back face (a hit
    // from the side the normal points away from) is tinted red, so that a ray which leaked
    // into a closed, outward-facing mesh and hit its far wall from inside shows up.
    const float c = dot(ng, wo);
    path.radiance = c >= 0.0f ? Color(c) : Color(-c, -0.15f * c, -0.15f * c);
    // [ch14-debug]
    return;
  }

  // [ch14-emission]
  // Emission found by the path: counted in full when no light sample could have found it
  // (the camera ray, a delta bounce), otherwise weighted against next-event estimation.
  if (const int32_t li = scene_.triangle_light[hit.prim]; li != kNoLight) {
    const TriangleLight& light = *triangle_lights_[li];
    const Color le = light.emitted(wo);
    if (!is_black(le)) {
      float weight = 1.0f;
      if (!path.prev_delta)
        weight = power_heuristic(path.prev_pdf, light_choice_->pmf(li) * light.pdf_hit(path.prev_p, p));
      path.radiance += path.throughput * le * weight;
    }
  }
  // [ch14-emission]
  // A surface that is only partly there may let the ray through (scenes with transparency).
  if (transparency_ && passes_through(path, hit, p, ng)) [[unlikely]] {
    batch.next.push_back(index);
    return;
  }
  if (path.depth >= options_.max_depth) return;

  // The shading frame: the interpolated normal where the scene has one, on the geometric
  // normal's side, tilted by the bump map if the material has one; the texture coordinates,
  // or the barycentrics without them.
  Vec3f ns = ng;
  if (!scene_.normals.empty()) {
    const Vec3f n = scene_.normals[tri[0]] * b0 + scene_.normals[tri[1]] * hit.u +
                    scene_.normals[tri[2]] * hit.v;
    const float len = length(n);
    if (len > 0.0f && std::isfinite(len)) ns = n / len;
    if (dot(ns, ng) < 0.0f) ns = -ns;
  }
  Vec2f uv{hit.u, hit.v};
  if (!scene_.uvs.empty())
    uv = scene_.uvs[tri[0]] * b0 + scene_.uvs[tri[1]] * hit.u + scene_.uvs[tri[2]] * hit.v;
  const uint32_t material_index = scene_.triangle_material[hit.prim];
  const MaterialTraits traits = material_traits_[material_index];
  const Material& material = scene_.materials[material_index];
  if (material.bump) [[unlikely]] {
    Vec3f dpdu, dpdv;
    scene_.texture_tangents(hit.prim, {v[0], v[1], v[2]}, dpdu, dpdv);
    ns = material.bumped_normal(ns, dpdu, dpdv, uv);
    if (dot(ns, ng) < 0.0f) ns = -ns;
  }
  const Bsdf bsdf = material.make_bsdf(Frame(ns), uv);
  const Vec3f ng_wo = dot(ng, wo) >= 0.0f ? ng : -ng;  // the geometric normal on wo's side
  const LightQuery query{p, traits.transmissive ? Vec3f(0.0f) : ng_wo};
  Sampler& sampler = path.sampler;

  // [ch14-nee]
  // Next-event estimation: one light chosen by power, one point or direction on it, one
  // shadow ray. Its weight against BSDF sampling is the power heuristic; delta lights take
  // no part in MIS since BSDF sampling cannot find them.
  // Each bounce takes five dimensions of the sampler, always in this order (light choice,
  // point on the light, lobe choice, direction, roulette), so that dimension d means the same
  // thing in every path, as Sobol stratification needs. A number the bounce will not use (the
  // choice among one light, a point light's point, a Lambertian surface's lobe) is skipped:
  // counted, not computed.
  const bool nee = light_choice_ && !traits.delta_only;
  float pmf = 1.0f;
  int light_index = 0;
  if (nee && light_choice_->size() > 1)
    light_index = light_choice_->sample_discrete(sampler.get_1d(), &pmf);
  else
    sampler.skip_1d();  // no choice to make: the light is light 0, with probability 1
  Vec2f u_light{};
  if (nee && !light_is_delta_[light_index])
    u_light = sampler.get_2d();
  else
    sampler.skip_2d();  // a delta light is reached by one direction only
  if (nee) {
    const std::optional<LightSample> ls = scene_.lights[light_index]->sample_li(query, u_light);
    const bool same_side = traits.transmissive || dot(ls ? ls->wi : wo, ng_wo) > 0.0f;
    if (ls && ls->pdf > 0.0f && pmf > 0.0f && !is_black(ls->L) && same_side) {
      const Color f = bsdf.eval(wo, ls->wi) * std::fabs(dot(ls->wi, ns));
      if (!is_black(f)) {
        const float light_pdf = pmf * ls->pdf;
        const float weight = ls->delta ? 1.0f : power_heuristic(light_pdf, bsdf.pdf(wo, ls->wi));
        path.pending = path.throughput * f * ls->L * (weight / light_pdf);
        // Written where the batch keeps it: a ray assembled on the stack and then copied was
        // stored in pieces and read back whole, which the processor cannot forward.
        Ray& shadow = batch.shadow_rays.emplace_back();
        shadow.org = offset_ray_origin(p, dot(ls->wi, ng) > 0.0f ? ng : -ng);
        shadow.dir = ls->wi;
        shadow.time = ray.time;
        shadow.tfar = std::isfinite(ls->distance) ? ls->distance * kShadowShortening
                                                  : std::numeric_limits<float>::infinity();
        batch.shadow_path.push_back(index);
      }
    }
  }
  // [ch14-nee]

  // [ch14-bounce]
  // BSDF sampling continues the path. A direction on the other side of the geometric
  // surface than a shading normal suggested would leak light through an opaque surface.
  float u_lobe = 0.0f;
  Vec2f u_bsdf{};
  if (traits.reads_lobe)
    u_lobe = sampler.get_1d();
  else
    sampler.skip_1d();
  if (traits.reads_direction)
    u_bsdf = sampler.get_2d();
  else
    sampler.skip_2d();
  const std::optional<BsdfSample> bs = bsdf.sample(wo, u_lobe, u_bsdf);
  if (!bs || is_black(bs->weight) || !is_finite(bs->weight)) return;
  if (!traits.transmissive && dot(bs->wi, ng_wo) <= 0.0f) return;
  path.throughput *= bs->weight;
  // Embree 1.1's minContribution: a path that can add little any more ends (biased).
  if (max_component(path.throughput) < options_.min_contribution) return;
  path.prev_pdf = bs->pdf;
  path.prev_delta = bs->delta;
  path.prev_p = p;
  path.prev_n = query.n;
  ++path.depth;

  // Russian roulette: after rr_depth bounces a path survives with a probability that follows
  // its throughput, and a survivor's weight grows to keep the estimate unbiased. Its number
  // is the bounce's last.
  if (path.depth >= options_.rr_depth) {
    const float survive = std::min(0.95f, max_component(path.throughput));
    if (!(sampler.get_1d() < survive)) return;
    path.throughput *= 1.0f / survive;
  } else {
    sampler.skip_1d();
  }
  path.ray = Ray{};
  path.ray.org = offset_ray_origin(p, dot(bs->wi, ng) > 0.0f ? ng : -ng);
  path.ray.dir = bs->wi;
  path.ray.time = ray.time;
  batch.next.push_back(index);
  // [ch14-bounce]
}

// [ch14-tile]
void PathTracer::render_tile(const Tile& tile, uint32_t first_sample, uint32_t count,
                             Framebuffer& fb, RenderStats& stats) const {
  const int w = tile.x1 - tile.x0, h = tile.y1 - tile.y0;
  if (w <= 0 || h <= 0) return;
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  std::vector<Path> paths(n);
  std::vector<uint32_t> live;
  std::vector<Ray> rays;
  std::vector<Hit> hits;
  std::vector<uint8_t> blocked;
  Batch batch;
  const Sampler prototype(options_.sampler, options_.seed);
  for (uint32_t s = first_sample; s < first_sample + count; ++s) {
    // Camera rays: film position from the pixel filter, lens position, shutter time.
    live.clear();
    for (size_t i = 0; i < n; ++i) {
      Path& path = paths[i];
      path = Path{};
      path.sampler = prototype;
      path.x = tile.x0 + static_cast<int>(i % w);
      path.y = tile.y0 + static_cast<int>(i / w);
      path.sampler.start_pixel_sample(path.x, path.y, s);
      const FilterSample fs = filter_.sample(path.sampler.get_pixel_2d());
      const Vec2f film{(path.x + 0.5f + fs.offset.x) / options_.width,
                       (path.y + 0.5f + fs.offset.y) / options_.height};
      // A pinhole camera needs no lens position, a scene that stands still no time: their
      // dimensions are skipped (see shade).
      Vec2f lens{};
      if (uses_lens_)
        lens = path.sampler.get_2d();
      else
        path.sampler.skip_2d();
      float time = 0.0f;
      if (scene_.has_motion())
        time = path.sampler.get_1d();
      else
        path.sampler.skip_1d();
      path.filter_weight = fs.weight;
      path.film = film;
      path.ray = camera_.generate_ray(film, lens, time);
      live.push_back(static_cast<uint32_t>(i));
    }
    // Rounds: one batch of closest-hit rays, shading, one batch of shadow rays.
    while (!live.empty()) {
      rays.resize(live.size());
      hits.resize(live.size());
      for (size_t k = 0; k < live.size(); ++k) rays[k] = paths[live[k]].ray;
      Timer timer;
      kernels_.intersect(rays, hits);
      stats.kernel_seconds += timer.seconds();
      stats.rays += rays.size();
      batch.shadow_rays.clear();
      batch.shadow_path.clear();
      batch.next.clear();
      for (size_t k = 0; k < live.size(); ++k) shade(paths[live[k]], rays[k], hits[k], batch, live[k]);
      if (!batch.shadow_rays.empty()) {
        blocked.resize(batch.shadow_rays.size());
        timer.reset();
        kernels_.occluded(batch.shadow_rays, blocked);
        stats.kernel_seconds += timer.seconds();
        stats.rays += blocked.size();
        stats.shadow_rays += blocked.size();
        // In a scene with transparency, what a blocked shadow ray still lets through.
        if (transparency_) [[unlikely]]
          for (size_t k = 0; k < blocked.size(); ++k)
            if (blocked[k]) {
              Path& path = paths[batch.shadow_path[k]];
              path.radiance += path.pending * transmittance(batch.shadow_rays[k], stats);
            }
        for (size_t k = 0; k < blocked.size(); ++k) {
          Path& path = paths[batch.shadow_path[k]];
          if (!blocked[k]) path.radiance += path.pending;
          path.pending = Color{};
        }
      }
      live.swap(batch.next);
    }
    // Natural vignetting (chapter 11) scales what each camera path brought back.
    if (camera_.params().vignetting) [[unlikely]]
      for (Path& path : paths) path.radiance *= camera_.vignetting(path.film);
    for (const Path& path : paths) fb.add_sample(path.x, path.y, path.radiance, path.filter_weight);
    stats.samples += n;
  }
}
// [ch14-tile]

}  // namespace rtk
