/// \file
/// The leaf policy of every supported `-tri` configuration: chapter 6's layouts with this
/// chapter's tests, named once for every kernel made per configuration. Per-ISA template:
/// include from kernel sources only.
#pragma once

#ifndef RTK_ISA
#error "leaf_intersectors.h belongs to kernel sources compiled once per ISA"
#endif

#include "02_bvh2/leaf_intersector.h"
#include "06_layouts/layout_loads.h"
#include "07_intersectors/pluecker.h"
#include "07_intersectors/triangle_config.h"
#include "07_intersectors/watertight.h"

namespace rtk::RTK_ISA {

// [ch07-leaf-intersectors]
/// Calls make(std::type_identity<Leaf>{}) with the leaf policy of `config` and returns what
/// it returns: Möller-Trumbore in any layout (chapter 6's with_moeller_leaf), the stable
/// Plücker test and the watertight test in the vertex and indexed layouts (chapter 6's
/// with_vertex_leaf), whose blocks keep the vertices those tests start from. An unsupported pair (layout_supports) gives {}.
template <class Make>
auto with_leaf_intersector(TriangleConfig config, Make&& make)
    -> decltype(with_moeller_leaf(config.layout, make)) {
  switch (config.intersector) {
    case IntersectorKind::moeller: return with_moeller_leaf(config.layout, make);
    case IntersectorKind::pluecker: return with_vertex_leaf<PlueckerStable>(config.layout, make);
    case IntersectorKind::watertight: return with_vertex_leaf<Watertight>(config.layout, make);
  }
  return {};
}
// [ch07-leaf-intersectors]

}  // namespace rtk::RTK_ISA
