#include "06_layouts/layout_bvh.h"

#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"

namespace rtk {

template <int N>
LayoutBVH<N> make_layout_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh, TriangleLayout layout) {
  LayoutBVH<N> out;
  out.layout = layout;
  // The indexed layouts' blocks point at the copy's vertices, which never move after this.
  auto shared_copy = [&] {
    out.shared = std::make_unique<const TriangleMesh>(mesh);
    return out.shared.get();
  };
  switch (layout) {
    case TriangleLayout::triangle1: out.bvh = make_layout_tree<N, Triangle1Layout>(tree, mesh); break;
    case TriangleLayout::triangle4: out.bvh = make_layout_tree<N, Triangle4Layout>(tree, mesh); break;
    case TriangleLayout::triangle8: out.bvh = make_layout_tree<N, Triangle8Layout>(tree, mesh); break;
    case TriangleLayout::triangle1v: out.bvh = make_layout_tree<N, Triangle1vLayout>(tree, mesh); break;
    case TriangleLayout::triangle4v: out.bvh = make_layout_tree<N, Triangle4vLayout>(tree, mesh); break;
    case TriangleLayout::triangle1i: out.bvh = make_layout_tree<N, Triangle1iLayout>(tree, *shared_copy()); break;
    case TriangleLayout::triangle4i: out.bvh = make_layout_tree<N, Triangle4iLayout>(tree, *shared_copy()); break;
  }
  return out;
}

template LayoutBVH<2> make_layout_bvh<2>(const BuildTree<2>&, const TriangleMesh&, TriangleLayout);
template LayoutBVH<4> make_layout_bvh<4>(const BuildTree<4>&, const TriangleMesh&, TriangleLayout);
template LayoutBVH<8> make_layout_bvh<8>(const BuildTree<8>&, const TriangleMesh&, TriangleLayout);

}  // namespace rtk
