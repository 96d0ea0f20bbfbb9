#include "09_inflight/inflight.h"

namespace rtk {

bool inflight_compiled(TriangleConfig tri, InflightConfig config) {
  if (!layout_supports(tri.layout, tri.intersector)) return false;
  if (config == kDefaultInflight) return true;
  const bool ablation_leaf = tri.intersector == IntersectorKind::moeller &&
                             (tri.layout == TriangleLayout::triangle4 || tri.layout == TriangleLayout::triangle8);
  if (!ablation_leaf) return false;
  for (const InflightConfig& c : kInflightConfigs)
    if (c == config) return true;
  return false;
}

}  // namespace rtk
