/// \file
/// Building a layout BVH from a mesh: chapter 4's SAH builder, told what a leaf of the layout
/// costs, then make_layout_bvh.
#pragma once

#include "04_sah/sah_options.h"
#include "06_layouts/layout_bvh.h"

namespace rtk {

// [ch06-sah-options]
/// SAH options that fill a layout's blocks. Chapter 4's builder prices a leaf by its
/// triangles, but a block of M triangles is tested in about the time of one: left alone it
/// makes leaves of one or two triangles, which blocks of four hold mostly as padding (on a
/// sphere of 16,256 triangles, 199 bytes per triangle for triangle4). So leaves are priced in
/// blocks of M (chapter 4's leaf_block), a block at the price of a node step, and a leaf may
/// hold two blocks.
SahBuildOptions sah_options_for(TriangleLayout layout);
// [ch06-sah-options]

/// Builds the tree with sah_options_for(layout) (and `threads`, 0 for all), then the
/// structure. Throws like make_layout_bvh.
template <int N>
LayoutBVH<N> build_layout_bvh(const TriangleMesh& mesh, TriangleLayout layout, int threads = 0);

extern template LayoutBVH<2> build_layout_bvh<2>(const TriangleMesh&, TriangleLayout, int);
extern template LayoutBVH<4> build_layout_bvh<4>(const TriangleMesh&, TriangleLayout, int);
extern template LayoutBVH<8> build_layout_bvh<8>(const TriangleMesh&, TriangleLayout, int);

}  // namespace rtk
