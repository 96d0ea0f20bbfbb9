#include "06_layouts/layout_build.h"

#include "04_sah/build_sah.h"

namespace rtk {

SahBuildOptions sah_options_for(TriangleLayout layout) {
  const int width = layout == TriangleLayout::triangle8 ? 8
                    : (layout == TriangleLayout::triangle4 || layout == TriangleLayout::triangle4i ||
                       layout == TriangleLayout::triangle4v)
                        ? 4
                        : 1;
  return block_priced_options(width);
}

template <int N>
LayoutBVH<N> build_layout_bvh(const TriangleMesh& mesh, TriangleLayout layout, int threads) {
  SahBuildOptions options = sah_options_for(layout);
  options.threads = threads;
  return make_layout_bvh<N>(build_binned_sah<N>(mesh, options), mesh, layout,
                            threads);
}

template LayoutBVH<2> build_layout_bvh<2>(const TriangleMesh&, TriangleLayout, int);
template LayoutBVH<4> build_layout_bvh<4>(const TriangleMesh&, TriangleLayout, int);
template LayoutBVH<8> build_layout_bvh<8>(const TriangleMesh&, TriangleLayout, int);

}  // namespace rtk
