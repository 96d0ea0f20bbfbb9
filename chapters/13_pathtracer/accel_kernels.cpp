#include "13_pathtracer/accel_kernels.h"

#include <algorithm>
#include <cstdio>

namespace rtk {

namespace {

Accel build(const RenderScene& scene, const AccelConfig& config) {
  if (!scene.has_motion()) return Accel(scene.mesh, config);
  TriangleMesh t1;
  t1.vertices = scene.vertices_t1;
  t1.triangles = scene.mesh.triangles;
  return Accel(scene.mesh, t1, config);
}

// The renderer's batches are one tile's rays; rtk::Accel would spread a batch above its task
// size over its own threads, inside a tile task that already runs on one of them. Calls are
// cut to this size so that every batch is traced on the calling thread.
constexpr size_t kMaxBatch = 1024;

}  // namespace

AccelKernels::AccelKernels(const RenderScene& scene, const AccelConfig& config)
    : accel_(build(scene, config)) {}

void AccelKernels::intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
  for (size_t i = 0; i < rays.size(); i += kMaxBatch) {
    const size_t n = std::min(kMaxBatch, rays.size() - i);
    accel_.intersect(rays.subspan(i, n), hits.subspan(i, n));
  }
}

void AccelKernels::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  for (size_t i = 0; i < rays.size(); i += kMaxBatch) {
    const size_t n = std::min(kMaxBatch, rays.size() - i);
    accel_.occluded(rays.subspan(i, n), occluded.subspan(i, n));
  }
}

std::string AccelKernels::name() const {
  const AccelInfo& i = accel_.info();
  return "rtk " + i.accel + " " + i.tri + " " + std::string(isa_name(i.isa));
}

RenderKernels make_rtk_kernels(const RenderScene& scene, const AccelConfig& config) {
  auto kernels = std::make_unique<AccelKernels>(scene, config);
  const AccelInfo& info = kernels->info();
  char figures[64];
  std::snprintf(figures, sizeof figures, "build %.3f s, %.1f MB", info.build_seconds, info.bytes / 1e6);
  std::string summary = "accel " + info.accel + ", tri " + info.tri + ", isa " + std::string(isa_name(info.isa)) +
                        " (" + info.choice + "); " + figures;
  return {std::move(kernels), std::move(summary)};
}

}  // namespace rtk
