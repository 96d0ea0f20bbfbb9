/// \file
/// OBJ and MTL files for rendering: geometry with texture coordinates, normals and materials.
///
/// lib/io's strict loader (io/obj_loader.h) reads triangles for ray replay and skips
/// everything else; the renderer also needs `vt`, `vn`, `usemtl` and `mtllib`. This reader
/// keeps the strict loader's rules for what it shares with it (the same fan triangulation and
/// triangle order, so primIDs agree; the same index rules; errors as FILE:LINE) and adds:
/// - `vt u [v [w]]` and `vn x y z`; a corner `i/t/n` takes its attributes from them. A vertex
///   is one (position, texture, normal) triple, so a position used with two normals becomes
///   two vertices of the render mesh;
/// - `usemtl NAME` selects a material of the libraries read so far (an unknown name is warned
///   about and gets the default grey Matte); `mtllib FILE...` reads MTL files, relative to the
///   OBJ file's folder;
/// - MTL: `newmtl`, `Kd Ks Ka Ke Tf` (three numbers, or one for a grey), `Ns Ni d Tr illum`,
///   `map_Kd FILE` (a texture, sRGB-decoded); they become chapter 12's "OBJ" material through
///   make_material, whose warnings say what is approximated. A material with a non-zero `Ke`
///   emits: each of its triangles becomes a TriangleLight shining on the side its corners
///   turn counter-clockwise toward (the OBJ front face). Other keys (map_Ks, bump, ...) are
///   warned about once per file and ignored.
/// - `o`, `g`, `s`, `l`, `p` are ignored; another statement is warned about once per file.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "12_materials/material.h"
#include "14_pathtracer/scene.h"

namespace rtk {

/// Appends the triangles, vertices, materials and emitting triangles of an OBJ file (and of
/// the MTL files it names) to `scene`. Throws FileError (file and line) for a malformed line
/// or a file that cannot be read; warnings go to `warn`.
/// Texture files (map_Kd) are read by `conventions` (chapter 12).
void load_obj_scene(const std::filesystem::path& path, RenderScene& scene,
                    const WarningHandler& warn = {}, const TextureConventions& conventions = {});

}  // namespace rtk
