#include "scene/obj_scene.h"

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "io/read_file.h"
#include "scene/mtl_file.h"
#include "scene/parse_number.h"
#include "scene/text_lines.h"

namespace rtk {

namespace {

using scene_io::fail;
using scene_io::parse_float;
using scene_io::TextLine;
using scene_io::Where;

// A corner's index: 1 is the first element read, -1 the last one read so far.
uint32_t resolve_index(std::string_view token, size_t count, const Where& where, const char* kind) {
  const long long index = scene_io::parse_int(token, where, std::string(kind) + " index", -(1ll << 40), 1ll << 40);
  const long long n = static_cast<long long>(count);
  if (index > n || index < -n)
    fail(where, std::string(kind) + " index " + std::to_string(index) + " is out of range (" +
                    std::to_string(count) + " read so far)");
  if (index == 0) fail(where, std::string(kind) + " index 0 is invalid (OBJ indices count from 1)");
  return static_cast<uint32_t>(index > 0 ? index - 1 : static_cast<long long>(count) + index);
}

constexpr uint32_t kAbsent = 0xFFFFFFFFu;

struct Corner {
  uint32_t v, t, n;
  bool operator==(const Corner&) const = default;
};
struct CornerHash {
  size_t operator()(const Corner& c) const {
    return (size_t(c.v) * 0x9E3779B97F4A7C15ull) ^ (size_t(c.t) * 0xC2B2AE3D27D4EB4Full) ^ c.n;
  }
};

}  // namespace

void load_obj_scene(const std::filesystem::path& path, RenderScene& scene, const WarningHandler& warn,
                    const TextureConventions& conventions) {
  const std::string file = path.string();
  const std::string text = read_file(path);
  std::deque<std::string> storage;
  const std::vector<TextLine> lines = scene_io::split_lines(text, file, storage);

  std::vector<Vec3f> positions, normals;
  std::vector<Vec2f> texcoords;
  std::map<std::string, uint32_t> materials;
  std::set<std::string> warned;
  std::unordered_map<Corner, uint32_t, CornerHash> vertex_of;
  uint32_t default_material = kAbsent;
  uint32_t material = kAbsent;
  bool has_normals = false, has_uvs = false;
  const size_t first_vertex = scene.mesh.vertices.size();
  const size_t first_triangle = scene.mesh.triangles.size();
  std::vector<Corner> corners;  // the scene vertex's attributes, per new vertex
  std::vector<uint32_t> face;

  auto number = [](const TextLine& l, size_t i, const Where& w) { return parse_float(l.tokens[i], w, l.tokens[0]); };
  for (const TextLine& l : lines) {
    const Where where{file, l.line};
    const std::string_view key = l.tokens[0];
    const size_t args = l.tokens.size() - 1;
    if (key == "v") {
      if (args != 3 && args != 4 && args != 6)
        fail(where, "'v' takes 3 coordinates (4 with a weight, 6 with a colour), found " + std::to_string(args));
      for (size_t i = 4; i <= args; ++i) number(l, i, where);
      positions.push_back({number(l, 1, where), number(l, 2, where), number(l, 3, where)});
    } else if (key == "vt") {
      if (args < 1 || args > 3) fail(where, "'vt' takes 1 to 3 coordinates, found " + std::to_string(args));
      texcoords.push_back({number(l, 1, where), args >= 2 ? number(l, 2, where) : 0.0f});
      if (args == 3) number(l, 3, where);
    } else if (key == "vn") {
      if (args != 3) fail(where, "'vn' takes 3 coordinates, found " + std::to_string(args));
      normals.push_back({number(l, 1, where), number(l, 2, where), number(l, 3, where)});
    } else if (key == "f") {
      if (args < 3) fail(where, "a face needs at least 3 corners, found " + std::to_string(args));
      face.clear();
      for (size_t i = 1; i <= args; ++i) {
        const std::string_view c = l.tokens[i];
        const size_t s1 = c.find('/');
        Corner corner{resolve_index(c.substr(0, s1), positions.size(), where, "vertex"), kAbsent, kAbsent};
        if (s1 != std::string_view::npos) {
          const std::string_view rest = c.substr(s1 + 1);
          const size_t s2 = rest.find('/');
          const std::string_view t = rest.substr(0, s2);
          if (!t.empty()) corner.t = resolve_index(t, texcoords.size(), where, "texture");
          if (s2 != std::string_view::npos) corner.n = resolve_index(rest.substr(s2 + 1), normals.size(), where, "normal");
          else if (t.empty())
            fail(where,
                 "bad face corner '" + scene_io::shown(c) + "' (expected i, i/t, i//n or i/t/n)");
        }
        has_uvs |= corner.t != kAbsent;
        has_normals |= corner.n != kAbsent;
        auto [it, added] = vertex_of.try_emplace(corner, static_cast<uint32_t>(first_vertex + corners.size()));
        if (added) corners.push_back(corner);
        face.push_back(it->second);
      }
      if (material == kAbsent) {
        if (default_material == kAbsent) {
          Material grey = make_material("Matte", ParameterList{});
          grey.name = "default";
          default_material = scene.add_material(std::move(grey));
        }
        material = default_material;
      }
      // The same fan as lib/io's strict loader: (c0, c1, c2), (c0, c2, c3), ...
      for (size_t i = 1; i + 1 < face.size(); ++i) {
        scene.mesh.triangles.push_back({face[0], face[i], face[i + 1]});
        scene.triangle_material.push_back(material);
        scene.triangle_light.push_back(kNoLight);
      }
    } else if (key == "usemtl") {
      if (args != 1) fail(where, "usemtl takes one name");
      const auto it = materials.find(std::string(l.tokens[1]));
      if (it != materials.end()) {
        material = it->second;
      } else {
        if (warn)
          warn(file + ":" + std::to_string(l.line) + ": material '" + scene_io::shown(l.tokens[1]) +
               "' is not in any mtllib read so far; using a grey Matte");
        material = kAbsent;
      }
    } else if (key == "mtllib") {
      if (args < 1) fail(where, "mtllib takes file names");
      for (size_t i = 1; i <= args; ++i) {
        try {
          for (const auto& [name, index] : load_mtl(path.parent_path() / std::string(l.tokens[i]), scene, warn, conventions))
            materials[name] = index;
        } catch (const FileError& e) {
          if (e.line() != 0) throw;
          fail(where, e.what());  // a library that cannot be read: say which line named it
        }
      }
    } else if (key == "o" || key == "g" || key == "s" || key == "l" || key == "p") {
      // Names, groups and smoothing groups do not change what is rendered.
    } else if (warned.insert(std::string(key)).second && warn) {
      warn(file + ":" + std::to_string(l.line) + ": OBJ statement '" + scene_io::shown(key) +
           "' is ignored");
    }
  }

  // The new vertices, with the scene's attribute arrays kept as long as its vertices.
  const size_t old_count = scene.mesh.vertices.size();
  const bool keep_normals = has_normals || !scene.normals.empty();
  const bool keep_uvs = has_uvs || !scene.uvs.empty();
  if (keep_normals) scene.normals.resize(old_count, Vec3f(0.0f));
  if (keep_uvs) scene.uvs.resize(old_count, Vec2f{});
  for (const Corner& c : corners) {
    scene.mesh.vertices.push_back(positions[c.v]);
    if (keep_normals) scene.normals.push_back(c.n == kAbsent ? Vec3f(0.0f) : normals[c.n]);
    if (keep_uvs) scene.uvs.push_back(c.t == kAbsent ? Vec2f{} : texcoords[c.t]);
  }
  if (!scene.vertices_t1.empty())  // an earlier file moves: this one stands still
    for (const Corner& c : corners) scene.vertices_t1.push_back(positions[c.v]);

  // Emitting triangles become lights; TriangleLight shines toward
  // cross(v2 - v0, v1 - v0), so the corners are passed as (c0, c2, c1) to make that the
  // OBJ front face's normal.
  for (size_t t = first_triangle; t < scene.mesh.triangles.size(); ++t) {
    const Material& m = scene.materials[scene.triangle_material[t]];
    if (!m.is_emissive()) continue;
    const auto& tri = scene.mesh.triangles[t];
    const Vec3f p0 = scene.mesh.vertices[tri[0]], p1 = scene.mesh.vertices[tri[1]],
                p2 = scene.mesh.vertices[tri[2]];
    const Vec3f n = cross(p1 - p0, p2 - p0);
    if (!(dot(n, n) > 0.0f)) continue;  // a zero-area emitter cannot be sampled, nor hit
    scene.lights.push_back(std::make_shared<TriangleLight>(p0, p2, p1, m.emission));
    scene.triangle_light[t] = static_cast<int32_t>(scene.lights.size() - 1);
  }
}

}  // namespace rtk
