#include "10_kernel_api/backends.h"

#include <tbb/task_arena.h>

#include <utility>

#include "01_base/isa_dispatch.h"
#include "04_sah/build_sah.h"
#include "05_spatial/build_spatial.h"
#include "06_layouts/layout_build.h"
#include "07_intersectors/layout_intersectors.h"
#include "09_inflight/packets.h"

namespace rtk::api {

namespace {

// The tree: chapter 4's binned SAH builder (object splits) or chapter 5's (object and spatial
// splits under the default 30 % duplication budget), with `sah`, on the threads of the
// caller's task arena (the tree is the same for any count).
template <int N, bool Spatial>
BuildTree<N> build_tree(const TriangleMesh& mesh, SahBuildOptions sah) {
  sah.threads = 0;
  if constexpr (Spatial) {
    SpatialBuildOptions options;
    options.sah = sah;
    return build_spatial_sah<N>(mesh, options);
  } else {
    return build_binned_sah<N>(mesh, sah);
  }
}

// [ch10-build-rows]
// BVH2, BVH4 and BVH8: chapter 6's layout BVH (chapter 2's binary node for BVH2, chapter 3's
// wide node for the others), from a tree built with the SAH options that fill the layout's
// blocks, traced by the kernels chapter 7 resolves for the width, layout and intersector, and
// in packets by chapter 9's kernels where it has them (BVH4 and BVH8).
template <int N, bool Spatial>
BuiltStructure build_layout(const TriangleMesh& mesh, Isa isa, int threads, TriangleConfig tri) {
  // One task arena for the tree and the layout (0 threads inside: the caller's arena), not one
  // each: on a small mesh, making an arena and waking its threads costs a measurable part of
  // the build.
  tbb::task_arena arena(threads);
  LayoutBVH<N> bvh = arena.execute([&] {
    const BuildTree<N> tree = build_tree<N, Spatial>(mesh, sah_options_for(tri.layout));
    return make_layout_bvh<N>(tree, mesh, tri.layout, 0);
  });
  BuiltStructure built = bind(std::move(bvh),
                              RTK_PICK_ISA(isa, intersector_kernels<N>)(tri),
                              [](const LayoutBVH<N>& bvh) { return &bvh.bvh; });
  if constexpr (N == 4 || N == 8) built.packets = RTK_PICK_ISA(isa, packet_kernels<N>)(tri);
  return built;
}
// [ch10-build-rows]

constexpr std::string_view split_name(bool spatial) { return spatial ? "spatialsplit" : "objectsplit"; }

std::vector<BackendEntry> make_table() {
  std::vector<BackendEntry> table;
  // Every width has every configuration of chapter 7, in its order (layouts as the guide lists
  // them, fastest intersector first), with both split strategies.
  auto add_width = [&table](std::string_view base, BuildFunction object, BuildFunction spatial) {
    for (const bool is_spatial : {false, true})
      for (const TriangleConfig& tri : supported_triangle_configs())
        table.push_back({base, split_name(is_spatial), tri, is_spatial ? spatial : object});
  };
  add_width("bvh2", &build_layout<2, false>, &build_layout<2, true>);
  add_width("bvh4", &build_layout<4, false>, &build_layout<4, true>);
  add_width("bvh8", &build_layout<8, false>, &build_layout<8, true>);
  return table;
}

}  // namespace

const std::vector<BackendEntry>& backend_table() {
  static const std::vector<BackendEntry> table = make_table();
  return table;
}

}  // namespace rtk::api
