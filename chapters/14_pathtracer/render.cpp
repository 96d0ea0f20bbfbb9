#include "14_pathtracer/render.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "01_base/timer.h"
#include "14_pathtracer/path_tracer.h"

namespace rtk {

namespace {

constexpr int kMaxSide = 1 << 15;

RenderOptions checked(const RenderOptions& o) {
  auto fail = [](const std::string& m) { throw std::invalid_argument(m); };
  if (o.width < 1 || o.height < 1 || o.width > kMaxSide || o.height > kMaxSide)
    fail("-size: " + std::to_string(o.width) + " x " + std::to_string(o.height) +
         " is not from 1 to 32768 on each side");
  if (o.spp < 1) fail("-spp: " + std::to_string(o.spp) + " is below 1");
  if (o.max_depth < 0) fail("-depth: " + std::to_string(o.max_depth) + " is negative");
  if (o.rr_depth < 0) fail("rr_depth: " + std::to_string(o.rr_depth) + " is negative");
  if (o.tile_size < 1) fail("tile size " + std::to_string(o.tile_size) + " is below 1");
  if (o.threads < 0) fail("-threads: " + std::to_string(o.threads) + " is negative");
  return o;
}

// The progress bar: redrawn from whichever thread finishes a tile, at most ten times a
// second, and only once the render has run for a second (a short render prints nothing).
class Progress {
 public:
  Progress(bool enabled, size_t total) : enabled_(enabled && isatty(STDERR_FILENO)), total_(total) {}
  void tile_done() {
    if (!enabled_) return;
    const size_t done = ++done_;
    const double now = timer_.seconds();
    if (now < 1.0) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || (now - last_ < 0.1 && done != total_)) return;
    last_ = now;
    const int width = 40, filled = static_cast<int>(width * done / total_);
    std::fprintf(stderr, "\r[%s%s] %3d%%  %.1f s", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), static_cast<int>(100 * done / total_), now);
    std::fflush(stderr);
    drawn_ = true;
  }
  ~Progress() {
    if (drawn_) std::fputc('\n', stderr);
  }

 private:
  bool enabled_;
  size_t total_;
  std::atomic<size_t> done_{0};
  std::mutex mutex_;
  Timer timer_;
  double last_ = 0;
  bool drawn_ = false;
};

}  // namespace

RenderStats& RenderStats::operator+=(const RenderStats& o) {
  seconds += o.seconds;
  kernel_seconds += o.kernel_seconds;
  thread_seconds += o.thread_seconds;
  samples += o.samples;
  rays += o.rays;
  shadow_rays += o.shadow_rays;
  invalid_samples += o.invalid_samples;
  tiles += o.tiles;
  tiles_done += o.tiles_done;
  return *this;
}

Renderer::Renderer(const RenderScene& scene, const RayKernels& kernels, const RenderOptions& options)
    : options_(checked(options)),
      tracer_(std::make_unique<PathTracer>(scene, kernels, options_)) {}

Renderer::~Renderer() = default;

namespace {

// [ch14-tiles]
// The frame in tiles, row by row. Tiles are the unit of parallel work: each is rendered by
// one task from start to end, its pixels' samples come from samplers seeded by the pixel
// and the sample index, and its pixels are its own in the framebuffer. So neither the
// thread count nor the order in which tasks run can change a single bit of the image.
std::vector<Tile> make_tiles(int width, int height, int size) {
  std::vector<Tile> tiles;
  for (int y = 0; y < height; y += size)
    for (int x = 0; x < width; x += size)
      tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
  return tiles;
}

RenderStats render_tiles(const PathTracer& tracer, const RenderOptions& options, Framebuffer& fb,
                         uint32_t first, uint32_t count, bool progress) {
  if (fb.width() != options.width || fb.height() != options.height)
    throw std::invalid_argument("render: the framebuffer is " + std::to_string(fb.width()) + " x " +
                                std::to_string(fb.height()) + ", the options ask for " +
                                std::to_string(options.width) + " x " + std::to_string(options.height));
  const std::vector<Tile> tiles = make_tiles(options.width, options.height, options.tile_size);
  Progress bar(progress, tiles.size());
  RenderStats total;
  std::mutex mutex;
  const long long invalid_before = fb.invalid_samples();
  Timer wall;
  auto body = [&](const tbb::blocked_range<size_t>& range) {
    for (size_t t = range.begin(); t != range.end(); ++t) {
      // [ch14-stop]
      // A stop request is honoured between tiles: a tile once begun is finished, so every
      // pixel holds all its samples or none, and the image written is what was rendered.
      if (options.stop && options.stop->load(std::memory_order_relaxed)) continue;
      // [ch14-stop]
      RenderStats stats;
      stats.tiles_done = 1;
      Timer timer;
      tracer.render_tile(tiles[t], first, count, fb, stats);
      stats.thread_seconds = timer.seconds();
      {
        std::lock_guard lock(mutex);
        total += stats;
      }
      bar.tile_done();
    }
  };
  const int threads = options.threads > 0 ? options.threads : tbb::this_task_arena::max_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] { tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), body); });
  total.seconds = wall.seconds();
  total.tiles = tiles.size();
  total.invalid_samples = static_cast<uint64_t>(fb.invalid_samples() - invalid_before);
  return total;
}
// [ch14-tiles]

}  // namespace

RenderStats Renderer::render_pass(Framebuffer& framebuffer, uint32_t first_sample, uint32_t count) const {
  return render_tiles(*tracer_, options_, framebuffer, first_sample, count, false);
}

RenderStats Renderer::render(Framebuffer& framebuffer) const {
  return render_tiles(*tracer_, options_, framebuffer, 0, static_cast<uint32_t>(options_.spp),
                      options_.progress);
}

}  // namespace rtk
