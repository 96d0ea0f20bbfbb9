/// \file
/// The table behind the public API: one row per configuration the chapters implement, each with
/// the function that builds it for an ISA and binds it to its kernels. Adding a structure to the
/// API is adding rows.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "07_intersectors/triangle_config.h"
#include "10_kernel_api/accel.h"

namespace rtk::api {

// [ch10-built]
/// A built structure and the kernels resolved for it: the owner of the structure (of whatever
/// type), the part the kernels read, the two kernels, the memory it holds, and the packet
/// kernels (chapter 9) where the configuration has them.
struct BuiltStructure {
  std::shared_ptr<const void> owner;
  const void* traced = nullptr;
  TraceKernels kernels;
  size_t bytes = 0;
  TraceKernels packets;  ///< null where the configuration has none
};

/// Moves a built structure into shared ownership and binds it to `kernels`. `traced` picks the
/// part the kernels read (the structure itself, or its node tree for chapter 6's LayoutBVH).
template <class Structure, class Traced>
BuiltStructure bind(Structure structure, TraceKernels kernels, Traced traced) {
  auto owner = std::make_shared<const Structure>(std::move(structure));
  return {owner, traced(*owner), kernels, owner->bytes(), {}};
}
// [ch10-built]

/// Builds one configuration's structure for an ISA with at most `threads` threads.
using BuildFunction = BuiltStructure (*)(const TriangleMesh& mesh, Isa isa, int threads, TriangleConfig tri);

/// One configuration: `accel` = base + "." + split, `tri` = the layout and its intersector.
struct BackendEntry {
  std::string_view base;   ///< "bvh2", "bvh4", "bvh8"
  std::string_view split;  ///< "objectsplit" or "spatialsplit"
  TriangleConfig tri;      ///< e.g. triangle4.moeller
  BuildFunction build;
};

/// Every configuration RTK has, in order of preference within a base and layout.
const std::vector<BackendEntry>& backend_table();

}  // namespace rtk::api
