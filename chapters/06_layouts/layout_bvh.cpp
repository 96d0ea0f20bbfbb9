#include "06_layouts/layout_bvh.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"

namespace rtk {

namespace {

// [ch06-parallel-loop]
/// make_bvh2's and make_bvh's loop over the nodes as a TBB parallel loop: every node and its
/// leaves have their place before the loop starts (LeafPlacement), so the threads write
/// disjoint bytes and the structure is the one the serial loop makes.
struct ParallelLoop {
  template <class F>
  void operator()(size_t n, F&& f) const {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 64),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i) f(i);
                      });
  }
};
// [ch06-parallel-loop]

}  // namespace

template <int N>
LayoutBVH<N> make_layout_bvh(const BuildTree<N>& tree, const TriangleMesh& mesh,
                             TriangleLayout layout, int threads) {
  if (threads > 0) {
    tbb::task_arena arena(threads);
    return arena.execute([&] { return make_layout_bvh<N>(tree, mesh, layout, 0); });
  }
  LayoutBVH<N> out;
  out.layout = layout;
  // The indexed layouts' blocks point at the copy's vertices, which never move after this.
  auto shared_copy = [&] {
    out.shared = std::make_unique<const TriangleMesh>(mesh);
    return out.shared.get();
  };
  // The structure with leaves in layout L over mesh `m`, its nodes made by the parallel loop.
  auto make = [&]<class L>(L, const TriangleMesh& m) {
    out.bvh = make_layout_tree<N, L>(tree, m, ParallelLoop{});
  };
  switch (layout) {
    case TriangleLayout::triangle1: make(Triangle1Layout{}, mesh); break;
    case TriangleLayout::triangle4: make(Triangle4Layout{}, mesh); break;
    case TriangleLayout::triangle8: make(Triangle8Layout{}, mesh); break;
    case TriangleLayout::triangle1v: make(Triangle1vLayout{}, mesh); break;
    case TriangleLayout::triangle4v: make(Triangle4vLayout{}, mesh); break;
    case TriangleLayout::triangle1i: make(Triangle1iLayout{}, *shared_copy()); break;
    case TriangleLayout::triangle4i: make(Triangle4iLayout{}, *shared_copy()); break;
  }
  return out;
}

template LayoutBVH<2> make_layout_bvh<2>(const BuildTree<2>&, const TriangleMesh&, TriangleLayout,
                                         int);
template LayoutBVH<4> make_layout_bvh<4>(const BuildTree<4>&, const TriangleMesh&, TriangleLayout,
                                         int);
template LayoutBVH<8> make_layout_bvh<8>(const BuildTree<8>&, const TriangleMesh&, TriangleLayout,
                                         int);

}  // namespace rtk
