/// \file
/// The names of the ray/triangle intersectors, for code outside the kernels (tests, the
/// configuration strings of chapter 6, benchmarks).
#pragma once

#include <optional>
#include <string_view>

namespace rtk {

/// The three ray/triangle tests of chapter 7.
enum class IntersectorKind {
  moeller,     ///< Möller-Trumbore: fastest, leaks between long thin triangles
  pluecker,    ///< stable Plücker: shared edges decided consistently
  watertight,  ///< Woop, Benthin and Wald 2013: edges and vertices decided exactly
};

/// All intersectors, fastest first.
inline constexpr IntersectorKind kAllIntersectors[] = {
    IntersectorKind::moeller, IntersectorKind::pluecker, IntersectorKind::watertight};

/// The name used in `-tri` strings: "moeller", "pluecker", "watertight".
constexpr std::string_view intersector_name(IntersectorKind kind) {
  switch (kind) {
    case IntersectorKind::moeller: return "moeller";
    case IntersectorKind::pluecker: return "pluecker";
    case IntersectorKind::watertight: return "watertight";
  }
  return "?";
}

/// Parses an intersector name; std::nullopt for anything else.
constexpr std::optional<IntersectorKind> parse_intersector(std::string_view name) {
  for (const IntersectorKind kind : kAllIntersectors)
    if (intersector_name(kind) == name) return kind;
  return std::nullopt;
}

}  // namespace rtk
