#include "scene/mtl_file.h"

#include <deque>
#include <set>
#include <stdexcept>
#include <vector>

#include "io/file_error.h"
#include "io/read_file.h"
#include "scene/parse_number.h"
#include "scene/text_lines.h"

namespace rtk {

namespace {

using scene_io::fail;
using scene_io::TextLine;
using scene_io::Where;

// [ch14-mtl-ranges]
// The range of each number an MTL file may give, checked on the line that gives it: a
// reflectance above 1 (Kd 1e38) would make energy, an index of refraction of 1e30 nonsense.
struct Range {
  float min, max;
};
const std::map<std::string_view, Range, std::less<>> kColorRanges = {
    {"Kd", {0, 1}}, {"Ks", {0, 1}}, {"Tf", {0, 1}}, {"Ka", {0, 1e10f}}, {"Ke", {0, 1e10f}}};
const std::map<std::string_view, Range, std::less<>> kScalarRanges = {
    {"Ns", {0, 1e6f}}, {"Ni", {0, 10}}, {"d", {0, 1}}, {"Tr", {0, 1}}};
// [ch14-mtl-ranges]

}  // namespace

std::map<std::string, uint32_t> read_mtl_text(std::string_view text,
                                              const std::filesystem::path& path, RenderScene& scene,
                                              const WarningHandler& warn,
                                              const TextureConventions& conventions) {
  const std::string file = path.string();
  std::deque<std::string> storage;
  const std::vector<TextLine> lines = scene_io::split_lines(text, file, storage);
  std::map<std::string, uint32_t> names;
  std::set<std::string> warned;
  std::string current;
  Where opened;  // the newmtl line of the material being read
  ParameterList params;
  bool open = false;
  auto finish = [&] {
    if (!open) return;
    const std::string prefix =
        file + ":" + std::to_string(opened.line) + ": material '" + current + "': ";
    Material m;
    try {
      m = make_material("OBJ", params, [&](const std::string& w) {
        if (warn) warn(prefix + w);
      });
    } catch (const std::invalid_argument& e) {
      fail(opened, "material '" + scene_io::shown(current) + "': " + e.what());
    }
    m.name = current;
    names[current] = scene.add_material(std::move(m));
    params = ParameterList{};
  };
  for (const TextLine& l : lines) {
    const Where where{file, l.line};
    const std::string_view key = l.tokens[0];
    const size_t args = l.tokens.size() - 1;
    auto number = [&](size_t i, Range r) {
      return scene_io::parse_float(l.tokens[i], where, key, r.min, r.max);
    };
    if (key == "newmtl") {
      if (args != 1) fail(where, "newmtl takes one name");
      finish();
      current = std::string(l.tokens[1]);
      opened = where;
      open = true;
      continue;
    }
    if (!open) fail(where, std::string(key.substr(0, 40)).append(" comes before the first newmtl"));
    if (const auto c = kColorRanges.find(key); c != kColorRanges.end()) {
      if (args == 1) {
        params.set(std::string(key), Color(number(1, c->second)));
      } else if (args == 3) {
        params.set(std::string(key),
                   Color(number(1, c->second), number(2, c->second), number(3, c->second)));
      } else {
        fail(where, std::string(key) + " takes 3 numbers (r g b) or 1 (a grey)");
      }
    } else if (const auto r = kScalarRanges.find(key); r != kScalarRanges.end()) {
      if (args != 1) fail(where, std::string(key) + " takes one number");
      const float value = number(1, r->second);
      // Tr is the transparency some exporters write instead of the dissolve d.
      params.set(key == "Tr" ? "d" : std::string(key), key == "Tr" ? 1.0f - value : value);
    } else if (key == "illum") {
      if (args != 1) fail(where, "illum takes one whole number");
      params.set("illum", static_cast<float>(scene_io::parse_int(l.tokens[1], where, key, 0, 10)));
    } else if (key == "map_Kd" || key == "map_d" || key == "map_Bump" || key == "map_bump" ||
               key == "bump") {
      // [ch14-mtl-maps]
      // A texture statement: options, then the file name, the last token. The colour map is
      // read by the scene's conventions; the opacity and height maps hold data, not colours:
      // always linear and interpolated (a height's slope needs the interpolation), with the
      // scene's origin.
      const bool colour = key == "map_Kd";
      const std::string name = colour ? "map_Kd" : key == "map_d" ? "map_d" : "map_Bump";
      if (args < 1) fail(where, name + " takes a file name");
      size_t i = 1;
      for (; i + 1 < l.tokens.size(); ++i) {
        if (name == "map_Bump" && l.tokens[i] == "-bm" && i + 2 < l.tokens.size()) {
          params.set("bump_scale", scene_io::parse_float(l.tokens[i + 1], where, "-bm", -1e6f, 1e6f));
          ++i;
        } else if (warn) {
          warn(file + ":" + std::to_string(l.line) + ": " + name + " option '" +
               scene_io::shown(l.tokens[i]) + "' is ignored");
          break;
        }
      }
      // [ch14-mtl-maps]
      const std::filesystem::path image = path.parent_path() / std::string(l.tokens.back());
      TextureConventions data = conventions;
      data.encoding = ColorEncoding::linear;
      data.lookup = TextureLookup::bilinear;
      try {
        params.set(name, std::shared_ptr<const Texture>(
                             load_image_texture(image.string(), colour ? conventions : data)));
      } catch (const std::exception& e) {
        fail(where, name + ": " + e.what());
      }
    } else if (warned.insert(std::string(key)).second && warn) {
      warn(file + ":" + std::to_string(l.line) + ": MTL key '" + scene_io::shown(key) +
           "' is not modelled and is ignored");
    }
  }
  finish();
  return names;
}

std::map<std::string, uint32_t> load_mtl(const std::filesystem::path& path, RenderScene& scene,
                                         const WarningHandler& warn,
                                         const TextureConventions& conventions) {
  return read_mtl_text(read_file(path, kMaxTextFileBytes), path, scene, warn, conventions);
}

}  // namespace rtk
