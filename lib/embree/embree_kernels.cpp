#include "embree/embree_kernels.h"

#include <stdexcept>

namespace rtk {

namespace {

const TriangleMesh& static_mesh(const RenderScene& scene) {
  if (scene.has_motion())
    throw std::invalid_argument("-kernels embree: the scene moves, and RTK drives Embree only for static "
                                "scenes; render it with -kernels rtk");
  return scene.mesh;
}

}  // namespace

EmbreeKernels::EmbreeKernels(const RenderScene& scene, int threads) : scene_(static_mesh(scene), threads) {}

Tracer EmbreeKernels::tracer() const {
  // The same form as RTK's kernels: plain functions of (structure, rays, results).
  const TraceKernels kernels{
      [](const void* s, std::span<const Ray> rays, std::span<Hit> hits) {
        static_cast<const EmbreeScene*>(s)->intersect(rays, hits);
      },
      [](const void* s, std::span<const Ray> rays, std::span<uint8_t> occluded) {
        static_cast<const EmbreeScene*>(s)->occluded(rays, occluded);
      }};
  return {&scene_, kernels};
}

std::string EmbreeKernels::name() const {
  return "embree " + EmbreeScene::version() + " (rtcIntersect1, medium-quality build)";
}

}  // namespace rtk
