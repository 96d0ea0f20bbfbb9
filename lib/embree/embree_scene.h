/// \file
/// The yardstick: Embree 3 (Debian's libembree-dev) behind the same three calls as RTK's API,
/// so that the benchmark, `rtk-embree-trace` and the renderer (`rtk render -kernels embree`) can
/// trace the same rays through both.
///
/// Embree is configured as a renderer would for a static scene: one triangle geometry,
/// RTC_BUILD_QUALITY_MEDIUM (its default, an SAH build), no robust or compact flags, and a
/// device with a fixed number of build threads. Its memory is measured with a device memory
/// monitor callback, which sees every allocation Embree makes: the bytes held after the build
/// minus those held before it, with and without the vertex and index buffers.
///
/// Embree treats invalid rays (NaN, infinite or zero directions, tnear > tfar) as the caller's
/// error; this wrapper gives them a miss without calling Embree, as shared/ray-replay.md
/// requires of every tracer.
#pragma once

#include <atomic>
#include <cstdint>
#include <span>
#include <string>

#include <embree3/rtcore.h>

#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"

namespace rtk {

/// An Embree device and scene holding one triangle mesh.
class EmbreeScene {
 public:
  /// Builds the scene with `threads` build threads (Embree's "threads=N" device option) and,
  /// if `isa` is not empty, with Embree's kernels for at most that instruction set (its
  /// "max_isa" option: "sse4.2", "avx", "avx2", ...; Embree then uses the node width and
  /// leaves it chooses for that ISA). Throws std::runtime_error with Embree's message when the
  /// device cannot be made. `robust` sets RTC_SCENE_FLAG_ROBUST, Embree's mode that "avoids
  /// optimizations that reduce arithmetic accuracy" (its watertight traversal and test).
  EmbreeScene(const TriangleMesh& mesh, int threads, const std::string& isa = "", bool robust = false);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Closest hits with rtcIntersect1, one ray at a time.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const;
  /// Occlusion with rtcOccluded1, one ray at a time (1 = blocked).
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const;

  double build_seconds() const { return build_seconds_; }   ///< rtcCommitScene's wall time
  size_t bvh_bytes() const { return bvh_bytes_; }            ///< allocated by the build
  size_t buffer_bytes() const { return buffer_bytes_; }      ///< the vertex and index buffers
  size_t total_bytes() const { return bvh_bytes_ + buffer_bytes_; }  ///< all the scene holds
  int threads() const { return threads_; }                   ///< build threads

  /// Embree's version, e.g. "3.13.5".
  static std::string version();

 private:
  static bool monitor(void* user, ssize_t bytes, bool post);
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::atomic<int64_t> allocated_{0};
  double build_seconds_ = 0;
  size_t bvh_bytes_ = 0;
  size_t buffer_bytes_ = 0;
  int threads_ = 1;
};

}  // namespace rtk
