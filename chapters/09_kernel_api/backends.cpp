#include "09_kernel_api/backends.h"

#include <utility>

#include "01_base/isa_dispatch.h"
#include "02_bvh2/bvh2.h"
#include "04_sah/build_sah.h"
#include "05_spatial/build_spatial.h"
#include "06_layouts/layout_build.h"
#include "07_intersectors/layout_intersectors.h"

namespace rtk::api {

namespace {

// The tree: chapter 4's binned SAH builder (object splits) or chapter 5's (object and spatial
// splits under the default 30 % duplication budget), with `sah` and `threads` threads (the
// tree is the same for any count).
template <int N, bool Spatial>
BuildTree<N> build_tree(const TriangleMesh& mesh, SahBuildOptions sah, int threads) {
  sah.threads = threads;
  if constexpr (Spatial) {
    SpatialBuildOptions options;
    options.sah = sah;
    return build_spatial_sah<N>(mesh, options);
  } else {
    return build_binned_sah<N>(make_prim_refs(mesh), sah);
  }
}

// [ch09-build-rows]
// BVH2: chapter 2's binary node with triangle1 leaves and chapter 2's kernels.
template <bool Spatial>
BuiltStructure build_bvh2(const TriangleMesh& mesh, Isa isa, int threads, TriangleConfig) {
  const BuildTree<2> tree = build_tree<2, Spatial>(mesh, SahBuildOptions{}, threads);
  return bind(make_bvh2<Triangle1Layout>(tree, mesh), RTK_PICK_ISA(isa, bvh2_kernels)(),
              [](const BVH2& bvh) { return &bvh; });
}

// BVH4 and BVH8: chapter 6's layout BVH, from a tree built with the SAH options that fill the
// layout's blocks, traced by the kernels chapter 7 resolves for the layout and intersector.
template <int N, bool Spatial>
BuiltStructure build_layout(const TriangleMesh& mesh, Isa isa, int threads, TriangleConfig tri) {
  const BuildTree<N> tree = build_tree<N, Spatial>(mesh, sah_options_for(tri.layout), threads);
  return bind(make_layout_bvh<N>(tree, mesh, tri.layout), RTK_PICK_ISA(isa, intersector_kernels<N>)(tri),
              [](const LayoutBVH<N>& bvh) { return &bvh.bvh; });
}
// [ch09-build-rows]

constexpr std::string_view split_name(bool spatial) { return spatial ? "spatialsplit" : "objectsplit"; }

std::vector<BackendEntry> make_table() {
  std::vector<BackendEntry> table;
  const TriangleConfig triangle1{TriangleLayout::triangle1, IntersectorKind::moeller};
  // BVH2 has chapter 2's triangle1 leaves only; BVH4 and BVH8 have every configuration of
  // chapter 7, in its order (layouts as the guide lists them, fastest intersector first).
  table.push_back({"bvh2", split_name(false), triangle1, &build_bvh2<false>});
  table.push_back({"bvh2", split_name(true), triangle1, &build_bvh2<true>});
  for (const bool spatial : {false, true})
    for (const TriangleConfig& tri : supported_triangle_configs()) {
      table.push_back({"bvh4", split_name(spatial), tri, spatial ? &build_layout<4, true> : &build_layout<4, false>});
    }
  for (const bool spatial : {false, true})
    for (const TriangleConfig& tri : supported_triangle_configs())
      table.push_back({"bvh8", split_name(spatial), tri, spatial ? &build_layout<8, true> : &build_layout<8, false>});
  return table;
}

}  // namespace

const std::vector<BackendEntry>& backend_table() {
  static const std::vector<BackendEntry> table = make_table();
  return table;
}

}  // namespace rtk::api
