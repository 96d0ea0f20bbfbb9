#include "14_pathtracer/accel_kernels.h"

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

}  // namespace

AccelKernels::AccelKernels(const RenderScene& scene, const AccelConfig& config)
    : accel_(build(scene, config)) {}

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
