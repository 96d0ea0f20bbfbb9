#include "06_layouts/triangle_config.h"

#include <stdexcept>

#include "06_layouts/triangle_i.h"
#include "06_layouts/triangle_m.h"
#include "06_layouts/triangle_v.h"
#include "02_bvh2/triangle1.h"

namespace rtk {

std::string_view layout_name(TriangleLayout layout) {
  switch (layout) {
    case TriangleLayout::triangle1: return "triangle1";
    case TriangleLayout::triangle4: return "triangle4";
    case TriangleLayout::triangle8: return "triangle8";
    case TriangleLayout::triangle1i: return "triangle1i";
    case TriangleLayout::triangle4i: return "triangle4i";
    case TriangleLayout::triangle1v: return "triangle1v";
    case TriangleLayout::triangle4v: return "triangle4v";
  }
  return "?";
}

bool layout_supports(TriangleLayout layout, IntersectorKind intersector) {
  const bool precomputed = layout == TriangleLayout::triangle1 || layout == TriangleLayout::triangle4 ||
                           layout == TriangleLayout::triangle8;
  return !precomputed || intersector == IntersectorKind::moeller;
}

size_t leaf_bytes_per_triangle(TriangleLayout layout) {
  switch (layout) {
    case TriangleLayout::triangle1: return sizeof(Triangle1);
    case TriangleLayout::triangle4: return sizeof(TriangleM<4>) / 4;
    case TriangleLayout::triangle8: return sizeof(TriangleM<8>) / 8;
    case TriangleLayout::triangle1i: return sizeof(Triangle1i);
    case TriangleLayout::triangle4i: return sizeof(TriangleMi<4>) / 4;
    case TriangleLayout::triangle1v: return sizeof(Triangle1v);
    case TriangleLayout::triangle4v: return sizeof(TriangleMv<4>) / 4;
  }
  return 0;
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
  bool known_layout = false;
  for (const TriangleLayout layout : kAllLayouts)
    if (layout_name(layout) == layout_text) config.layout = layout, known_layout = true;
  if (!known_layout) refuse(text, "names no triangle layout");
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

// [ch06-estimate]
double estimated_bytes_per_triangle(TriangleLayout layout) {
  // Measured with BVH4 and sah_options_for(layout) on the closed procedural meshes (spheres
  // of 16,128 and 130,560 triangles, terrains of 20,000 and 131,072; the largest value,
  // rounded up): leaf blocks with their padding, the nodes, and for the indexed layouts the
  // shared vertices (12 bytes each, about half a vertex per triangle). A triangle soup, with
  // three vertices of its own per triangle, costs the indexed layouts some 35 bytes more.
  switch (layout) {
    case TriangleLayout::triangle1: return 85;
    case TriangleLayout::triangle4: return 85;
    case TriangleLayout::triangle8: return 85;
    case TriangleLayout::triangle1i: return 75;
    case TriangleLayout::triangle4i: return 48;
    case TriangleLayout::triangle1v: return 85;
    case TriangleLayout::triangle4v: return 70;
  }
  return 0;
}

TriangleLayout choose_default_layout(size_t triangle_count, Isa isa, size_t memory_budget_bytes) {
  // The guide's recommendation: blocks of four for SSE, of eight for AVX. The scalar variant
  // measured fastest with blocks of eight too: its eight-lane loops are vectorized by the
  // compiler with the SSE2 that every x86-64 has.
  const TriangleLayout fastest = isa == Isa::sse4 ? TriangleLayout::triangle4 : TriangleLayout::triangle8;
  // Model no more than the scene needs: a scene that would not fit gets the leanest layout.
  const double needed = estimated_bytes_per_triangle(fastest) * double(triangle_count);
  return needed <= double(memory_budget_bytes) ? fastest : TriangleLayout::triangle4i;
}
// [ch06-estimate]

}  // namespace rtk
