/// \file
/// The motion-blur side of the public API (chapter 8). A scene in linear motion over the
/// shutter [0, 1] is given as two meshes with the same triangles: `t0` with the vertices at
/// time 0, `t1` with them at time 1; each ray's `time` says when it looks. Build it with
/// `Accel(t0, t1, config)` (declared in accel.h, defined in motion_accel.cpp):
/// - no `-accel`: `bvh4mb.objectsplit` with `triangle4i` leaves, or, when no vertex moves, the
///   static default (a static scene builds no motion structure);
/// - `-accel bvh4mb`: the motion structure, even for a static scene;
/// - a static `-accel` (bvh2, bvh4, bvh8) is refused when anything moves;
/// - `-tri`: `triangle4i` with `.moeller`, `.pluecker`, `.watertight`, `.fast` or `.accurate`.
/// Rays whose time is NaN or outside [0, 1] miss the motion structure (chapter 8 explains why);
/// a static structure ignores the time. `Accel(mesh, config)` refuses `-accel bvh4mb`.
#pragma once

#include <string_view>

#include "10_kernel_api/accel.h"

namespace rtk {

/// The `-accel` base name of the motion-blur structure.
inline constexpr std::string_view kMotionAccel = "bvh4mb";

/// Throws std::invalid_argument unless `t1` can be `t0` at time 1 (the same numbers of vertices
/// and triangles, the same faces); the message names both meshes by `name0` and `name1`
/// (e.g. their file names). Accel(t0, t1, config) makes the same check with the names "t0" and
/// "t1"; a command line calls this first to name its files.
void check_motion_meshes(const TriangleMesh& t0, const TriangleMesh& t1, std::string_view name0,
                         std::string_view name1);

}  // namespace rtk
