/// \file
/// RTK's public API: build an acceleration structure over an indexed triangle set, then ask
/// it for closest hits and for occlusion. This is the layer `rtk trace`, the renderer and the
/// Embree comparison use; it links the chapters' per-ISA kernels and chooses among them.
///
/// The choice is made with the configuration strings of the Embree 1.1 guide, in our names:
/// - `accel`: `bvh2`, `bvh4` or `bvh8`, optionally followed by the split strategy,
///   `.objectsplit` (the default) or `.spatialsplit`;
/// - `tri`: the leaf triangle layout (`triangle1`, `triangle4`, `triangle8`, `triangle1i`,
///   `triangle4i`, `triangle1v`, `triangle4v`: chapter 6) optionally followed by the intersector
///   (chapter 7), `.moeller`, `.pluecker`, `.watertight`, or `.fast` / `.accurate` (the fastest
///   or most accurate intersector that layout has). Every width takes every layout.
/// Only combinations that the chapters implement are accepted; any other is refused with a
/// message that lists the supported ones (supported_accels(), supported_tris()). Empty strings
/// mean the defaults, which follow the guide's advice adapted to the ISA: the node width the
/// ISA's registers fit (BVH4 for scalar and SSE4, BVH8 for AVX2 and AVX-512), object splits
/// (chapter 5 measures when spatial splits pay), and chapter 6's default layout with
/// Möller-Trumbore: the ISA's fastest blocks unless the scene would not fit the memory budget,
/// then the leanest (AccelInfo::choice says which rule chose). A batch of incoherent rays is
/// traced in an order of RTK's choosing (chapter 9), its answers in the caller's order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "01_base/cpu_features.h"
#include "01_base/ray.h"
#include "01_base/triangle_mesh.h"
#include "02_bvh2/trace_kernels.h"
#include "09_inflight/ray_order.h"

namespace rtk {

/// What to build: configuration strings, ISA and thread count.
struct AccelConfig {
  std::string accel;       ///< e.g. "bvh4.objectsplit"; empty for the default
  std::string tri;         ///< e.g. "triangle4.moeller"; empty for the default
  std::optional<Isa> isa;  ///< the kernels' variant; nothing for the best the CPU runs
  int threads = 1;         ///< threads for building and tracing (1: the calling thread only)
  /// Bytes the structure may take when `tri` is empty: a scene whose fastest layout would need
  /// more gets the leanest one (chapter 6). 0: half of the machine's physical memory.
  size_t memory_budget = 0;
  /// Whether intersect() and occluded() sort a batch before tracing it (chapter 9): when the
  /// batch is large and incoherent (the default), always, or never. The answers are the same.
  RayOrderPolicy::Mode order = RayOrderPolicy::Mode::automatic;
  /// Whether a batch traced in the order given goes in packets wherever P consecutive rays share
  /// an octant (chapter 9; P is 4, 8 or 16 with the ISA), for the configurations that have
  /// packet kernels. The answers are the same.
  bool packets = true;
};

/// What was built, with the configuration resolved to full names.
struct AccelInfo {
  std::string accel;         ///< e.g. "bvh4.objectsplit"
  std::string tri;           ///< e.g. "triangle4.moeller"
  std::string choice;        ///< why that layout: "asked for ...", or which default rule chose it
  Isa isa = Isa::scalar;     ///< the variant that runs
  int threads = 1;           ///< threads used for building and tracing
  size_t triangles = 0;      ///< triangles in the scene (zero-area ones included)
  size_t bytes = 0;          ///< memory the structure holds: nodes, leaves and any vertex data
  double build_seconds = 0;  ///< wall-clock time of the build
};

// [ch10-tracer]
/// A built structure bound to the two kernels its configuration resolved to: what a batch of
/// rays needs to reach its traversal loop through one indirect call. It is a view: the Accel
/// (or whatever else built the structure) must outlive it. A renderer holds one and calls it
/// from many threads at once, each call on the calling thread.
struct Tracer {
  const void* structure = nullptr;  ///< what the kernels read, of the type they were made for
  TraceKernels kernels;             ///< the resolved kernels

  /// The closest hit of every ray: hits[i] for rays[i]; a miss for invalid rays.
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const {
    kernels.intersect(structure, rays, hits);
  }
  /// Whether each ray is blocked in [tnear, tfar]: occluded[i] = 1 or 0.
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
    kernels.occluded(structure, rays, occluded);
  }
};
// [ch10-tracer]

/// An acceleration structure over a triangle mesh, ready to trace. It keeps what it needs
/// (the mesh may be destroyed after construction); tracing is const and may be called from
/// several threads at once.
class Accel {
 public:
  /// Builds the structure. Throws std::invalid_argument, naming the option (-accel, -tri,
  /// -isa, -threads) and listing what is supported, when the configuration is not one RTK has,
  /// and naming the triangle when a vertex index lies past the mesh's vertices.
  Accel(const TriangleMesh& mesh, const AccelConfig& config = {});
  /// Builds a structure for a scene in linear motion: `t0` holds the vertices at shutter time 0,
  /// `t1` the same triangles with the vertices at time 1, and each ray's time picks the moment.
  /// Chooses bvh4mb (chapter 8) unless nothing moves; see 10_kernel_api/motion_accel.h for the rules.
  Accel(const TriangleMesh& t0, const TriangleMesh& t1, const AccelConfig& config = {});
  ~Accel();
  Accel(Accel&&) noexcept;
  Accel& operator=(Accel&&) noexcept;

  /// Finds the closest hit of every ray: hits[i] for rays[i] (the spans have the same length).
  /// Invalid rays (rtk::is_valid) get a miss. Uses `threads` threads when there are enough rays,
  /// and traces a large incoherent batch sorted (AccelConfig::order).
  void intersect(std::span<const Ray> rays, std::span<Hit> hits) const;

  /// Whether each ray is blocked anywhere in [tnear, tfar]: occluded[i] = 1 or 0.
  void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const;

  /// The configuration that was built, its size and its build time.
  const AccelInfo& info() const { return info_; }

  /// The structure with its kernels, for a caller that makes its own batches and threads (the
  /// renderer): every call traces on the calling thread, in the order given (in packets where
  /// the rays allow). Valid while this Accel lives.
  Tracer tracer() const { return {traced_, given_}; }

 private:
  /// Sort keys over the scene's box `scene` (both positions for motion), and when a batch is
  /// sorted: as `mode` says.
  void choose_order(const Box3f& scene, RayOrderPolicy::Mode mode);

  AccelInfo info_;
  std::shared_ptr<const void> structure_;  ///< the built structure, whatever its type
  const void* traced_ = nullptr;           ///< what the kernels read: the structure or a part of it
  TraceKernels kernels_;                   ///< resolved once, when the structure was built
  TraceKernels given_;                     ///< for a batch in the order given: packets, or kernels_
  RayOrderKey order_key_{Box3f{}};         ///< sort keys over the scene's box
  RayOrderPolicy order_policy_;            ///< when a batch is sorted
};

/// The accepted `-accel` strings, full names (e.g. "bvh4.objectsplit").
std::vector<std::string> supported_accels();

/// The accepted `-tri` strings for an accel string, full names (e.g. "triangle4.moeller").
std::vector<std::string> supported_tris(const std::string& accel = "");

/// Resolves configuration strings to full names without building anything, so that a command
/// line can refuse a bad one before it loads a large scene. Throws like Accel's constructor.
AccelInfo resolve_config(const AccelConfig& config);

}  // namespace rtk
