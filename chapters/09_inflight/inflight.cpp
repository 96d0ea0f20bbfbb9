#include "09_inflight/inflight.h"

namespace rtk {

std::string InflightConfig::name() const {
  std::string out = "r";
  out += std::to_string(rays);
  if (!prefetch) out += "-noprefetch";
  return out;
}

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
