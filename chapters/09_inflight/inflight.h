/// \file
/// Rays in flight: the batch kernels that trace several rays of a batch interleaved on one
/// thread (inflight_traverser.h), for chapter 6's layout BVHs and chapter 7's intersectors, and
/// the configurations compiled for the ablation.
#pragma once

#include <span>
#include <string>

#include "01_base/isa_dispatch.h"
#include "02_bvh2/trace_kernels.h"
#include "06_layouts/layout_bvh.h"
#include "07_intersectors/triangle_config.h"

namespace rtk {

// [ch09-config]
/// How a batch is traced: `rays` rays in flight at once on one thread (1 is one ray after the
/// other, as chapter 3 traces them), and whether each ray asks the cache for the nodes it will
/// visit next (chapter 3's prefetch of the hit children, and of each node popped from the
/// stack). Both are compile-time parameters of the kernel.
struct InflightConfig {
  int rays = 4;
  bool prefetch = true;

  constexpr bool operator==(const InflightConfig&) const = default;
  /// "r4" or "r4-noprefetch".
  std::string name() const;
};
// [ch09-config]

/// The configurations of the ablation: 1, 2, 4 and 8 rays in flight, with and without
/// prefetching. They are compiled for the precomputed Möller-Trumbore leaves of four and eight
/// triangles (triangle4, triangle8); the other layouts and intersectors have kDefaultInflight.
inline constexpr InflightConfig kInflightConfigs[] = {{1, true}, {2, true}, {4, true}, {8, true},
                                                      {1, false}, {2, false}, {4, false}, {8, false}};
inline constexpr size_t kInflightConfigCount = sizeof(kInflightConfigs) / sizeof(kInflightConfigs[0]);

/// The configuration every layout and intersector is compiled with (chapter 9 measures it).
inline constexpr InflightConfig kDefaultInflight{4, true};

/// Whether the kernels of `tri` with `config` are compiled.
bool inflight_compiled(TriangleConfig tri, InflightConfig config);

// [ch09-kernels]
/// The in-flight kernels of each ISA for a layout BVH of width N = 8 whose leaves are in
/// `tri.layout`, tested with `tri.intersector`: `structure` is the LayoutBVH's `bvh`. Rays
/// get the same answers, bit for bit, as from chapter 7's intersector_kernels. Throws
/// std::invalid_argument for an unsupported layout and intersector, or a configuration that
/// is not compiled for them (inflight_compiled).
RTK_DECLARE_FOR_EACH_ISA(template <int N> TraceKernels inflight_kernels(TriangleConfig tri, InflightConfig config))

/// Closest hits through a layout BVH8 with `config` and the kernels of `isa`.
inline void intersect_inflight(Isa isa, const LayoutBVH<8>& bvh, IntersectorKind kind, InflightConfig config,
                               std::span<const Ray> rays, std::span<Hit> hits) {
  RTK_PICK_ISA(isa, inflight_kernels<8>)({bvh.layout, kind}, config).intersect(&bvh.bvh, rays, hits);
}
/// Occlusion through a layout BVH8 with `config` and the kernels of `isa`.
inline void occluded_inflight(Isa isa, const LayoutBVH<8>& bvh, IntersectorKind kind, InflightConfig config,
                              std::span<const Ray> rays, std::span<uint8_t> occluded) {
  RTK_PICK_ISA(isa, inflight_kernels<8>)({bvh.layout, kind}, config).occluded(&bvh.bvh, rays, occluded);
}
// [ch09-kernels]

}  // namespace rtk
