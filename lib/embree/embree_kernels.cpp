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

void EmbreeKernels::intersect(std::span<const Ray> rays, std::span<Hit> hits) const { scene_.intersect(rays, hits); }

void EmbreeKernels::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  scene_.occluded(rays, occluded);
}

std::string EmbreeKernels::name() const {
  return "embree " + EmbreeScene::version() + " (rtcIntersect1, medium-quality build)";
}

}  // namespace rtk
