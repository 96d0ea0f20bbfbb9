/// \file
/// The tiled renderer: the frame is cut into tiles that oneTBB tasks render with the path
/// tracer, adding HDR samples to lib/image's Framebuffer. Each pixel sample draws its random
/// numbers from a sampler seeded by (pixel, sample index, seed), so an image does not depend
/// on the thread count or on the order in which tiles finish.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

#include "11_sampling/camera.h"
#include "11_sampling/filter.h"
#include "11_sampling/sampler.h"
#include "14_pathtracer/ray_kernels.h"
#include "14_pathtracer/scene.h"
#include "image/framebuffer.h"

namespace rtk {

// [ch14-render-options]
/// How to render a frame. The defaults are the guide's where it has one (512 x 512, 1 sample
/// per pixel).
struct RenderOptions {
  int width = 512;           ///< image width in pixels
  int height = 512;          ///< image height in pixels
  int spp = 1;               ///< samples per pixel of render() (render_pass takes its own count)
  /// The most scattering events on a path (the guide's depth): 0 shows only what emits, 1
  /// adds direct lighting, 2 one bounce of indirect light, and so on.
  int max_depth = 10;
  int rr_depth = 3;          ///< Russian roulette starts after this many scattering events
  /// Embree 1.1's minContribution: a path whose throughput (its largest component) falls below
  /// this after a bounce ends there. 0, the default, never ends a path early; above 0 the
  /// image loses the light of the ended paths (a bias Embree 1.1 traded for speed).
  float min_contribution = 0.0f;
  uint32_t seed = 0;         ///< selects another, equally good image
  int threads = 0;           ///< worker threads; 0 for every core
  int tile_size = 16;        ///< tile side in pixels
  SamplerType sampler = SamplerType::sobol;  ///< chapter 11's sample generator
  FilterType filter = FilterType::box;       ///< chapter 11's pixel filter
  float filter_radius = 0;   ///< the filter's radius; 0 for the type's default
  bool progress = false;     ///< a progress bar on stderr (only when it is a terminal, after 1 s)
  /// The guide's `-renderer debug`: instead of path tracing, each pixel shows |cos| between the
  /// camera ray and the surface it hits (an "eye light"), which needs no light in the scene.
  bool eye_light = false;
  /// A request to stop, read before each tile (an interrupted `rtk render` sets it from its
  /// signal handler): once it reads true, the tiles not yet begun are skipped and the frame
  /// keeps what was rendered. Null: the frame always finishes.
  const std::atomic<bool>* stop = nullptr;
};
// [ch14-render-options]

/// What a render did and how long it took.
struct RenderStats {
  double seconds = 0;         ///< wall-clock time of the rendering (not the build)
  double kernel_seconds = 0;  ///< time inside RayKernels calls, summed over all threads
  double thread_seconds = 0;  ///< time inside tile tasks, summed over all threads
  uint64_t samples = 0;       ///< camera paths traced (pixels x samples per pixel)
  uint64_t rays = 0;          ///< rays traced: camera, bounce and shadow rays
  uint64_t shadow_rays = 0;   ///< of which occlusion (shadow) rays
  uint64_t invalid_samples = 0;  ///< samples that were not finite, dropped by the framebuffer
  uint64_t tiles = 0;            ///< tiles of the frame (of every pass, for a sum of passes)
  uint64_t tiles_done = 0;       ///< of which rendered: fewer when RenderOptions::stop was set

  /// Whether the render was stopped before every tile was rendered.
  bool stopped() const { return tiles_done < tiles; }

  /// Camera paths per second.
  double samples_per_second() const { return seconds > 0 ? samples / seconds : 0; }
  /// Rays per second (all kinds).
  double rays_per_second() const { return seconds > 0 ? rays / seconds : 0; }
  /// The share of the tile tasks' time spent in ray queries, in [0, 1].
  double kernel_share() const { return thread_seconds > 0 ? kernel_seconds / thread_seconds : 0; }
  /// Adds another pass's figures.
  RenderStats& operator+=(const RenderStats& other);
};

class PathTracer;

// [ch14-renderer]
/// Renders a scene with a path tracer (next-event estimation, multiple importance sampling,
/// Russian roulette) over a set of ray kernels. The scene and kernels must outlive the
/// renderer; rendering is const, so one renderer may serve a viewer frame after frame.
class Renderer {
 public:
  /// Prepares the lights and camera for `options` (the camera's aspect becomes width /
  /// height). Throws std::invalid_argument naming the option for a size below 1 or above
  /// 2^15, spp below 1, a negative max_depth or rr_depth, a tile size below 1, threads below 0, or for an
  /// invalid scene (RenderScene::validate) or camera.
  Renderer(const RenderScene& scene, const RayKernels& kernels, const RenderOptions& options);
  ~Renderer();

  /// One progressive pass: adds samples first_sample .. first_sample + count - 1 of every
  /// pixel to `framebuffer` (which must be width x height). Calling it with consecutive ranges
  /// gives exactly the image one call with the whole range gives.
  RenderStats render_pass(Framebuffer& framebuffer, uint32_t first_sample, uint32_t count) const;

  /// Renders samples 0 .. options.spp - 1 of every pixel (render_pass(fb, 0, spp)), with the
  /// progress bar if options.progress is set. Clear the framebuffer first for a fresh image.
  RenderStats render(Framebuffer& framebuffer) const;

  /// The options (validated).
  const RenderOptions& options() const { return options_; }

 private:
  RenderOptions options_;
  std::unique_ptr<const PathTracer> tracer_;
};
// [ch14-renderer]

}  // namespace rtk
