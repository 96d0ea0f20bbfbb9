/// \file
/// The integrator: a unidirectional path tracer with next-event estimation and multiple
/// importance sampling, run over one tile at a time in batches of rays (a small wavefront),
/// so that the ray kernels see spans of rays and their time can be measured per call.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "11_sampling/camera.h"
#include "11_sampling/distribution.h"
#include "11_sampling/filter.h"
#include "14_pathtracer/ray_kernels.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/scene.h"
#include "image/framebuffer.h"

namespace rtk {

/// A rectangle of pixels [x0, x1) x [y0, y1).
struct Tile {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

/// The power heuristic with exponent 2 (Veach and Guibas, "Optimally Combining Sampling
/// Techniques for Monte Carlo Rendering", SIGGRAPH 1995): the weight of a sample drawn with
/// density pdf_a when density pdf_b could also have produced it.
inline float power_heuristic(float pdf_a, float pdf_b) {
  const float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  if (!(a > 0.0f)) return 0.0f;
  // a / (a + b) loses nothing when b overflows to infinity: the weight is then 0.
  return a / (a + b);
}

/// What the path loop asks of a material at every hit, found once per material: whether its
/// BSDF is delta-only or transmissive, and which of the sampler's numbers its sampling reads.
struct MaterialTraits {
  bool delta_only = false, transmissive = false, reads_lobe = true, reads_direction = true;
};

/// The path tracer of chapter 14 over one scene. Immutable after construction, so tiles may
/// be rendered on many threads at once; each call keeps its own path state.
class PathTracer {
 public:
  /// Prepares the camera (aspect from the options), the light-selection distribution (in
  /// proportion to each light's power) and the per-triangle light table. Throws
  /// std::invalid_argument for an invalid scene or camera.
  PathTracer(const RenderScene& scene, const RayKernels& kernels, const RenderOptions& options);

  /// Adds samples first_sample .. first_sample + count - 1 of every pixel of `tile` to the
  /// framebuffer and the tile's figures to `stats` (kernel_seconds, samples, rays).
  void render_tile(const Tile& tile, uint32_t first_sample, uint32_t count, Framebuffer& fb,
                   RenderStats& stats) const;

 private:
  struct Path;
  struct Batch;
  void shade(Path& path, const Ray& ray, const Hit& hit, Batch& batch, uint32_t index) const;
  Color escaped(const Path& path, Vec3f dir) const;
  bool passes_through(Path& path, const Hit& hit, Vec3f p, Vec3f ng) const;
  float transmittance(Ray shadow, RenderStats& stats) const;

  const RenderScene& scene_;
  Tracer kernels_;  ///< the scene's structure and kernels (RayKernels::tracer)
  RenderOptions options_;
  Camera camera_;
  PixelFilter filter_;
  std::unique_ptr<Distribution1D> light_choice_;  // null when the scene has no light
  std::vector<const TriangleLight*> triangle_lights_;  // per light: itself if a triangle light
  std::vector<uint8_t> light_is_delta_;                // per light: whether it is a delta light
  std::vector<uint32_t> infinite_lights_;              // the lights that rays escaping can see
  std::vector<MaterialTraits> material_traits_;  // per material, found once
  std::vector<Vec3f> face_normals_;  // per triangle: the unit geometric normal (static scenes)
  bool uses_lens_ = false;           // whether camera rays need a lens sample (a thin lens)
  bool transparency_ = false;  // whether shadow rays may pass through surfaces
};

}  // namespace rtk
