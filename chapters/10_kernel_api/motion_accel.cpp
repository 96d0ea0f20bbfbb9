#include "10_kernel_api/motion_accel.h"

#include <stdexcept>
#include <string>

#include "01_base/timer.h"
#include "01_base/isa_dispatch.h"
#include "07_intersectors/triangle_config.h"
#include "08_motion/bvh4mb.h"
#include "10_kernel_api/backends.h"

namespace rtk {

namespace {

// "bvh4mb.objectsplit" -> {"bvh4mb", "objectsplit"}.
std::pair<std::string, std::string> split_spec(const std::string& spec) {
  const size_t dot = spec.find('.');
  if (dot == std::string::npos) return {spec, ""};
  return {spec.substr(0, dot), spec.substr(dot + 1)};
}

}  // namespace

void check_motion_meshes(const TriangleMesh& t0, const TriangleMesh& t1, std::string_view name0,
                         std::string_view name1) {
  check_motion_pair(t0, t1, name0, name1);
}

Accel::Accel(const TriangleMesh& t0, const TriangleMesh& t1, const AccelConfig& config) {
  // Step 1: the motion, checked (same vertices and faces, indices in range).
  if (t0.vertices.size() >= kInvalidPrim || t0.triangles.size() >= kInvalidPrim)
    throw std::invalid_argument("the scene has more than 2^32 - 2 triangles or vertices");
  MotionMesh mesh = make_motion_mesh(t0, t1, MotionStorage::sparse);
  // [ch10-motion-storage]
  // Model no more than the scene needs: sparse storage costs 16 bytes per vertex plus 12 per
  // moving one, dense storage 24 per vertex, so dense is smaller (and a little faster) once two
  // vertices in three move.
  if (3 * mesh.moving > 2 * t0.vertices.size()) mesh = make_motion_mesh(t0, t1, MotionStorage::dense);
  // [ch10-motion-storage]
  const char* storage = mesh.storage == MotionStorage::dense ? "dense motion" : "sparse motion";

  // Step 2: which structure. A static scene builds no motion structure unless asked to.
  const auto [base, split] = split_spec(config.accel);
  const bool motion = base == kMotionAccel || (base.empty() && mesh.moves());
  if (!motion) {
    if (mesh.moves())
      throw std::invalid_argument("-accel: '" + config.accel + "' cannot trace motion blur (" +
                                  std::to_string(mesh.moving) + " of " + std::to_string(t0.vertices.size()) +
                                  " vertices move); use -accel bvh4mb, or leave -accel out");
    *this = Accel(t0, config);
    return;
  }
  if (!split.empty() && split != "objectsplit")
    throw std::invalid_argument("-accel: bvh4mb is built with object splits only (bvh4mb.objectsplit), not '" +
                                config.accel + "'");
  TriangleConfig tri{TriangleLayout::triangle4i, IntersectorKind::moeller};
  if (!config.tri.empty()) {
    tri = parse_triangle_config(config.tri);
    if (tri.layout != TriangleLayout::triangle4i)
      throw std::invalid_argument("-tri: bvh4mb has triangle4i leaves only (triangle4i.moeller, "
                                  "triangle4i.pluecker, triangle4i.watertight), not '" + config.tri + "'");
  }
  // The ISA and thread checks of the static configuration, with its defaults for the rest.
  AccelConfig checked = config;
  checked.accel.clear();
  checked.tri.clear();
  const AccelInfo resolved = resolve_config(checked);

  // Step 3: build.
  info_.accel = std::string(kMotionAccel) + ".objectsplit";
  info_.tri = tri.name();
  info_.choice = (config.tri.empty() ? "default: " + info_.tri + ", the only leaves " + info_.accel + " has"
                                     : "asked for " + config.tri) +
                 "; " + storage + " (" + std::to_string(mesh.moving) + " of " +
                 std::to_string(mesh.base.vertices.size()) + " vertices move)";
  info_.isa = resolved.isa;
  info_.threads = resolved.threads;
  info_.triangles = mesh.size();
  SahBuildOptions options = motion_sah_options();
  options.threads = resolved.threads;
  Timer timer;
  BVH4MB bvh = build_bvhmb<4>(std::move(mesh), tri.intersector, &options);
  const TraceKernels kernels = RTK_PICK_ISA(resolved.isa, motion_kernels<4>)(bvh.mesh.storage, bvh.intersector);
  api::BuiltStructure built = api::bind(std::move(bvh), kernels, [](const BVH4MB& b) { return &b; });
  info_.build_seconds = timer.seconds();
  info_.bytes = built.bytes;
  structure_ = std::move(built.owner);
  traced_ = built.traced;
  kernels_ = given_ = built.kernels;
  choose_order(merge(t0.bounds(), t1.bounds()), config.order);
}

}  // namespace rtk
