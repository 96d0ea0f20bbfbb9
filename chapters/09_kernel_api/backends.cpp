#include "09_kernel_api/backends.h"

#include <utility>

#include "02_bvh2/bvh2.h"
#include "03_bvh4/bvh4.h"
#include "04_sah/build_sah.h"
#include "05_spatial/build_spatial.h"
#include "06_layouts/layout_build.h"
#include "06_layouts/layout_bvh.h"

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

// triangle1.moeller: the node layout of width N with chapter 2's triangle1 leaves, traced by
// chapters 2 and 3's kernels, from a tree built with the SAH builders' default options.
template <int N, bool Spatial>
std::unique_ptr<AccelBackend> build_triangle1(const TriangleMesh& mesh, Isa isa, int threads) {
  const BuildTree<N> tree = build_tree<N, Spatial>(mesh, SahBuildOptions{}, threads);
  if constexpr (N == 2) {
    return std::make_unique<BvhBackend<BVH2>>(make_bvh2<Triangle1Layout>(tree, mesh), isa);
  } else {
    return std::make_unique<BvhBackend<BVHN<N>>>(make_bvh<N, Triangle1Layout>(tree, mesh), isa);
  }
}

// Every other layout and intersector: chapter 6's layout BVH, from a tree built with the SAH
// options that fill the layout's blocks (sah_options_for).
template <int N, bool Spatial, TriangleLayout L, IntersectorKind K>
std::unique_ptr<AccelBackend> build_layout(const TriangleMesh& mesh, Isa isa, int threads) {
  const BuildTree<N> tree = build_tree<N, Spatial>(mesh, sah_options_for(L), threads);
  return std::make_unique<BvhBackend<LayoutBVH<N>>>(make_layout_bvh<N>(tree, mesh, TriangleConfig{L, K}), isa);
}

// The configurations chapter 6 implements beyond triangle1.moeller, in its order (layouts as
// the guide lists them, fastest intersector first). test_api.cpp checks that this list and
// supported_triangle_configs() agree.
constexpr TriangleConfig kLayoutConfigs[] = {
    {TriangleLayout::triangle4, IntersectorKind::moeller},
    {TriangleLayout::triangle8, IntersectorKind::moeller},
    {TriangleLayout::triangle1i, IntersectorKind::moeller},
    {TriangleLayout::triangle1i, IntersectorKind::pluecker},
    {TriangleLayout::triangle1i, IntersectorKind::watertight},
    {TriangleLayout::triangle4i, IntersectorKind::moeller},
    {TriangleLayout::triangle4i, IntersectorKind::pluecker},
    {TriangleLayout::triangle4i, IntersectorKind::watertight},
    {TriangleLayout::triangle1v, IntersectorKind::moeller},
    {TriangleLayout::triangle1v, IntersectorKind::pluecker},
    {TriangleLayout::triangle1v, IntersectorKind::watertight},
    {TriangleLayout::triangle4v, IntersectorKind::moeller},
    {TriangleLayout::triangle4v, IntersectorKind::pluecker},
    {TriangleLayout::triangle4v, IntersectorKind::watertight},
};

constexpr std::string_view split_name(bool spatial) { return spatial ? "spatialsplit" : "objectsplit"; }

// The rows of one base and split strategy: triangle1.moeller, then every layout configuration.
template <int N, bool Spatial, size_t... I>
void add_rows(std::vector<BackendEntry>& table, std::string_view base, std::index_sequence<I...>) {
  table.push_back({base, split_name(Spatial), "triangle1", "moeller", &build_triangle1<N, Spatial>});
  if constexpr (N != 2)
    (table.push_back({base, split_name(Spatial), layout_name(kLayoutConfigs[I].layout),
                      intersector_name(kLayoutConfigs[I].intersector),
                      &build_layout<N, Spatial, kLayoutConfigs[I].layout, kLayoutConfigs[I].intersector>}),
     ...);
}

std::vector<BackendEntry> make_table() {
  constexpr auto all = std::make_index_sequence<std::size(kLayoutConfigs)>();
  std::vector<BackendEntry> table;
  // BVH2 has chapter 2's triangle1 leaves only; BVH4 and BVH8 have every layout of chapter 6.
  add_rows<2, false>(table, "bvh2", all);
  add_rows<2, true>(table, "bvh2", all);
  add_rows<4, false>(table, "bvh4", all);
  add_rows<4, true>(table, "bvh4", all);
  add_rows<8, false>(table, "bvh8", all);
  add_rows<8, true>(table, "bvh8", all);
  return table;
}

}  // namespace

const std::vector<BackendEntry>& backend_table() {
  static const std::vector<BackendEntry> table = make_table();
  return table;
}

}  // namespace rtk::api
