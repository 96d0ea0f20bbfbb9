/// \file
/// The table behind the public API: one entry per configuration the chapters implement, each
/// with the function that builds it for an ISA. Adding a kernel to the API is adding a row.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "api/accel.h"

namespace rtk::api {

/// Builds one configuration's structure for an ISA with at most `threads` threads.
using BuildFunction = std::unique_ptr<AccelBackend> (*)(const TriangleMesh& mesh, Isa isa, int threads);

/// One configuration: `accel` = base + "." + split, `tri` = layout + "." + intersector.
struct BackendEntry {
  std::string_view base;         ///< "bvh2", "bvh4", "bvh8"
  std::string_view split;        ///< "objectsplit" or "spatialsplit"
  std::string_view layout;       ///< "triangle1", "triangle4", ...
  std::string_view intersector;  ///< "moeller" or "pluecker"
  BuildFunction build;
};

/// Every configuration RTK has, in order of preference within a base and layout.
const std::vector<BackendEntry>& backend_table();

}  // namespace rtk::api
