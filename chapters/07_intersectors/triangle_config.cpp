#include "07_intersectors/triangle_config.h"

#include <optional>
#include <stdexcept>

namespace rtk {

bool layout_supports(TriangleLayout layout, IntersectorKind intersector) {
  return !is_precomputed(layout) || intersector == IntersectorKind::moeller;
}

std::string TriangleConfig::name() const {
  return std::string(layout_name(layout)) + "." + std::string(intersector_name(intersector));
}

std::vector<TriangleConfig> supported_triangle_configs() {
  std::vector<TriangleConfig> configs;
  for (const TriangleLayout layout : kAllLayouts)
    for (const IntersectorKind kind : kAllIntersectors)
      if (layout_supports(layout, kind)) configs.push_back({layout, kind});
  return configs;
}

namespace {

std::string supported_list() {
  std::string list;
  for (const TriangleConfig& c : supported_triangle_configs()) list += (list.empty() ? "" : ", ") + c.name();
  return list + " (or a layout with .fast or .accurate)";
}

[[noreturn]] void refuse(std::string_view text, std::string_view why) {
  throw std::invalid_argument("-tri: '" + std::string(text) + "' " + std::string(why) +
                              "; supported: " + supported_list());
}

}  // namespace

TriangleConfig parse_triangle_config(std::string_view text) {
  const size_t dot = text.find('.');
  const std::string_view layout_text = text.substr(0, dot);
  const std::string_view kind_text = dot == std::string_view::npos ? "fast" : text.substr(dot + 1);
  TriangleConfig config;
  const std::optional<TriangleLayout> layout = parse_layout(layout_text);
  if (!layout) refuse(text, "names no triangle layout");
  config.layout = *layout;
  if (kind_text == "fast") {
    config.intersector = IntersectorKind::moeller;
  } else if (kind_text == "accurate") {
    config.intersector = layout_supports(config.layout, IntersectorKind::watertight)
                             ? IntersectorKind::watertight
                             : IntersectorKind::moeller;
  } else if (const auto kind = parse_intersector(kind_text)) {
    config.intersector = *kind;
    if (!layout_supports(config.layout, *kind))
      refuse(text, "is not supported: " + std::string(layout_text) +
                       " stores precomputed edges, which only Möller-Trumbore reads");
  } else {
    refuse(text, "names no intersector");
  }
  return config;
}

}  // namespace rtk
