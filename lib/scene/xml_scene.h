/// \file
/// The Embree scene graph in XML (FORMATS.md section 2), read into chapter 14's RenderScene.
///
/// Read: `<scene>`, `<Group>`, `<Transform>` (its first child an `<AffineSpace>`: a body of 12
/// numbers, a 3x4 row-major matrix whose last column is the translation, or one of the
/// attributes translate, scale, rotate_x, rotate_y, rotate_z, rotate + axis), `<TriangleMesh>`
/// (positions, optional motions (p(t) = p + t m), normals, texcoords, triangles, material),
/// `<Sphere>` (position, radius, numTheta, numPhi, optional motion, material; tessellated as
/// chapter 15's tessellate_sphere), lights (`<PointLight>`, `<SpotLight>` approximated by a
/// point light, `<DirectionalLight>`, `<DistantLight>`, `<AmbientLight>`, `<TriangleLight>`,
/// `<QuadLight>`, `<HDRILight>`), materials (`<material>` with `<code>` and `<parameters>`,
/// made by chapter 12's make_material, which warns about what it approximates), reuse
/// (`<assign type="material|scene" id>`, `<material id/>`, `<ref id/>`), inclusion (`<obj
/// src>`, `<xml src>`, `<extern src>`, `<material file>`), and binary arrays (`ofs`, `size`)
/// from the side file (`scene.bin`, then `scene.xml.bin`). The 2.x cameras are ignored with a
/// warning (the script's -vp and friends place the camera), other unknown elements are skipped
/// with a warning.
///
/// Every number (element text and attributes alike) is read strictly, finite, and every vertex
/// is checked finite after its transforms. Limits (scene/scene_limits.h): elements and `<ref>`s
/// nested at most kMaxXmlDepth deep, XML files included at most kMaxXmlIncludeDepth deep, at
/// most kMaxGeneratedTriangles triangles made by references and spheres; a binary array must
/// lie inside its side file, which is checked before anything is allocated.
#pragma once

#include <filesystem>
#include <string_view>

#include "12_materials/material.h"
#include "14_pathtracer/scene.h"

namespace rtk {

/// Appends the geometry, materials and lights of an XML scene to `scene`. Throws FileError
/// "FILE:LINE: message" for malformed XML, a malformed or missing value, an index out of
/// range, a binary array outside its side file, or a file that cannot be read; warnings go to
/// `warn`.
/// Textures and HDRILight images are read by `conventions` (chapters 12 and 13).
void load_xml_scene(const std::filesystem::path& path, RenderScene& scene, const WarningHandler& warn = {},
                    const TextureConventions& conventions = {});

/// load_xml_scene on the text of the file named `path` (the files it names are relative to
/// its folder), for the fuzzer.
void read_xml_scene_text(std::string_view text, const std::filesystem::path& path,
                         RenderScene& scene, const WarningHandler& warn = {},
                         const TextureConventions& conventions = {});

}  // namespace rtk
