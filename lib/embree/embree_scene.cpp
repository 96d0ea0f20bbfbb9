#include "embree/embree_scene.h"

#include <cstring>
#include <limits>
#include <stdexcept>

#include "01_base/timer.h"

namespace rtk {

bool EmbreeScene::monitor(void* user, ssize_t bytes, bool /*post*/) {
  static_cast<EmbreeScene*>(user)->allocated_ += int64_t(bytes);
  return true;  // never refuse an allocation: we measure, we do not limit
}

EmbreeScene::EmbreeScene(const TriangleMesh& mesh, int threads, const std::string& isa, bool robust)
    : threads_(threads) {
  const std::string config = "threads=" + std::to_string(threads) + (isa.empty() ? "" : ",max_isa=" + isa);
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("Embree: cannot create a device (" + config + ")");
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeScene::monitor, this);

  // The buffers: Embree's own (rtcSetNewGeometryBuffer pads them for its SIMD loads), filled
  // from the mesh.
  const int64_t before_buffers = allocated_;
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  if (robust) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangles.size()));
  if (!mesh.vertices.empty()) std::memcpy(vertices, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vec3f));
  if (!mesh.triangles.empty()) std::memcpy(indices, mesh.triangles.data(), mesh.triangles.size() * 12);
  rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_MEDIUM);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  const int64_t before_build = allocated_;

  Timer timer;
  rtcCommitScene(scene_);
  build_seconds_ = timer.seconds();
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("Embree: the scene did not build");
  buffer_bytes_ = size_t(before_build - before_buffers);
  bvh_bytes_ = size_t(allocated_ - before_build);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeScene::intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    hits[i] = Hit{};
    if (!is_valid(r)) continue;
    RTCRayHit rh;
    rh.ray.org_x = r.org.x;
    rh.ray.org_y = r.org.y;
    rh.ray.org_z = r.org.z;
    rh.ray.tnear = r.tnear;
    rh.ray.dir_x = r.dir.x;
    rh.ray.dir_y = r.dir.y;
    rh.ray.dir_z = r.dir.z;
    rh.ray.time = r.time;
    rh.ray.tfar = r.tfar;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) hits[i] = {rh.ray.tfar, rh.hit.u, rh.hit.v, rh.hit.primID};
  }
}

void EmbreeScene::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Ray& r = rays[i];
    occluded[i] = 0;
    if (!is_valid(r)) continue;
    RTCRay ray;
    ray.org_x = r.org.x;
    ray.org_y = r.org.y;
    ray.org_z = r.org.z;
    ray.tnear = r.tnear;
    ray.dir_x = r.dir.x;
    ray.dir_y = r.dir.y;
    ray.dir_z = r.dir.z;
    ray.time = r.time;
    ray.tfar = r.tfar;
    ray.mask = ~0u;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(scene_, &context, &ray);
    // Embree marks an occluded ray by setting tfar to -inf.
    occluded[i] = ray.tfar == -std::numeric_limits<float>::infinity() ? 1 : 0;
  }
}

std::string EmbreeScene::version() {
  RTCDevice device = rtcNewDevice("threads=1");
  std::string v = "3";
  if (device) {
    const ssize_t major = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MAJOR);
    const ssize_t minor = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_MINOR);
    const ssize_t patch = rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION_PATCH);
    v = std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
    rtcReleaseDevice(device);
  }
  return v;
}

}  // namespace rtk
