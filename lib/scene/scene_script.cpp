#include "scene/scene_script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "13_lights/area_light.h"
#include "13_lights/distant_light.h"
#include "13_lights/environment_light.h"
#include "13_lights/point_light.h"
#include "image/image_io.h"
#include "io/read_file.h"
#include "scene/obj_scene.h"
#include "scene/parse_number.h"
#include "scene/scene_limits.h"
#include "scene/xml_scene.h"

namespace rtk {

namespace {

using scene_io::fail;
using scene_io::Where;

// Scripts may include scripts; deeper than this is taken for a script that includes itself.
constexpr int kMaxInclude = kMaxScriptIncludeDepth;
// The longest token of a script: a file name (PATH_MAX) is the longest thing it may hold.
constexpr size_t kMaxTokenBytes = 4096;

struct Token {
  std::string text;
  Where where;
};

// [ch14-script-tokens]
// A script is a command line in a file: tokens separated by any ASCII white space (space, tab,
// CR, LF, vertical tab, form feed), '#' to the end of the line a comment, a UTF-8 byte-order
// mark at the start ignored. Every other control byte (NUL, ESC, ...) is binary data and an
// error at its line; so is a token longer than any option or file name can be.
bool is_script_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

std::vector<Token> tokenize(std::string_view text, const std::string& file) {
  std::vector<Token> tokens;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  size_t line = 1;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (is_script_space(c)) {
      line += c == '\n';
      ++i;
    } else if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else {
      const size_t start = i;
      for (; i < text.size() && !is_script_space(text[i]) && text[i] != '#'; ++i) {
        const unsigned char u = static_cast<unsigned char>(text[i]);
        if (u < 0x20 || u == 0x7f) {
          char hex[8];
          std::snprintf(hex, sizeof hex, "0x%02X", u);
          fail({file, line}, std::string("control byte ") + hex + " in the script (binary data?)");
        }
      }
      const std::string_view token = text.substr(start, i - start);
      if (token.size() > kMaxTokenBytes)
        fail({file, line},
             "a token of " + std::to_string(token.size()) + " bytes ('" + scene_io::shown(token) +
                 "'): no option or file name is longer than " + std::to_string(kMaxTokenBytes));
      tokens.push_back({std::string(token), {file, line}});
    }
  }
  return tokens;
}
// [ch14-script-tokens]

// Reads one token list (a script or the command line) into the script state.
class ScriptReader {
 public:
  ScriptReader(SceneScript& script, const WarningHandler& warn, int depth)
      : s_(script), warn_(warn), depth_(depth) {}

  void run(const std::vector<Token>& tokens, const std::filesystem::path& dir) {
    tokens_ = &tokens;
    dir_ = dir;
    pos_ = 0;
    while (pos_ < tokens.size()) option();
  }

 private:
  const Token& take(const Token& option, const char* what) {
    if (pos_ >= tokens_->size())
      fail(option.where, option.text + ": missing " + what + " (end of input)");
    return (*tokens_)[pos_++];
  }
  float number(const Token& option) {
    const Token& t = take(option, "a number");
    return scene_io::parse_float(t.text, t.where, option.text);
  }
  Vec3f vec3(const Token& option) {
    const float x = number(option), y = number(option);
    return {x, y, number(option)};
  }
  Color color(const Token& option) {
    const Vec3f c = vec3(option);
    return {c.x, c.y, c.z};
  }
  long long integer(const Token& option, long long min, long long max) {
    const Token& t = take(option, "an integer");
    return scene_io::parse_int(t.text, t.where, option.text, min, max);
  }
  std::filesystem::path file(const Token& option) {
    return dir_ / take(option, "a file name").text;
  }
  void warn(const Where& w, const std::string& message) const {
    if (!warn_) return;
    warn_(w.line ? w.file + ":" + std::to_string(w.line) + ": " + message : w.file + ": " + message);
  }
  // Runs `body`, turning the std::invalid_argument of a constructor (a light with a negative
  // radiance, a bad configuration string) into an error at the option's place.
  // A file the option names that cannot be read or is not a valid image is reported at the
  // option's place too, with the file's own message.
  // The message names the option; the place is that of `value` where the fault is in the
  // value the option was given (an unknown sampler's name).
  template <class Body>
  void at(const Token& option, Body&& body, const Token* value = nullptr) {
    try {
      body();
    } catch (const std::exception& e) {
      fail((value ? *value : option).where, option.text + ": " + e.what());
    }
  }
  void include(const Token& option) {
    const std::filesystem::path path = file(option);
    if (depth_ + 1 >= kMaxInclude)
      fail(option.where, "-c: scripts nested more than " + std::to_string(kMaxInclude) +
                             " deep (does '" + path.string() + "' include itself?)");
    std::string text;
    try {
      text = read_file(path, kMaxTextFileBytes);
    } catch (const FileError& e) {
      fail(option.where, std::string("-c: ") + e.what());
    }
    s_.files.push_back(path);
    const std::vector<Token> tokens = tokenize(text, path.string());
    ScriptReader(s_, warn_, depth_ + 1).run(tokens, path.parent_path());
  }

  void geometry(const Token& option) {
    const std::filesystem::path path = file(option);
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".obj" && ext != ".xml")
      fail(option.where, "-i " + scene_io::shown(path.string()) +
                             ": unknown scene format (expected .obj or .xml)");
    if (!std::filesystem::is_regular_file(path))
      fail(option.where, "-i: cannot open '" + path.string() + "'");
    keep_scene_for_outputs();
    last_first_vertex_ = s_.scene.mesh.vertices.size();
    last_first_triangle_ = s_.scene.mesh.triangles.size();
    try {
      if (ext == ".xml")
        load_xml_scene(path, s_.scene, warn_, s_.conventions);
      else
        load_obj_scene(path, s_.scene, warn_, s_.conventions);
    } catch (const FileError& e) {
      // An error at a line of the scene file is reported there; one about the whole file
      // (its size, its type) at the -i that named it.
      if (e.line() != 0) throw;
      fail(option.where, "-i: " + std::string(e.what()));
    }
    s_.files.push_back(path);
    has_last_ = true;
  }

  // -motion FILE: the same faces as the previous -i, with the vertices at shutter time 1.
  void motion(const Token& option) {
    const std::filesystem::path path = file(option);
    if (!has_last_) fail(option.where, "-motion must follow the -i of the geometry it moves");
    if (!std::filesystem::is_regular_file(path))
      fail(option.where, "-motion: cannot open '" + path.string() + "'");
    RenderScene t1;
    try {
      load_obj_scene(path, t1, {});
    } catch (const FileError& e) {
      if (e.line() != 0) throw;
      fail(option.where, "-motion: " + std::string(e.what()));
    }
    keep_scene_for_outputs();
    RenderScene& sc = s_.scene;
    const size_t nv = sc.mesh.vertices.size() - last_first_vertex_;
    const size_t nt = sc.mesh.triangles.size() - last_first_triangle_;
    bool same = t1.mesh.vertices.size() == nv && t1.mesh.triangles.size() == nt;
    for (size_t t = 0; same && t < nt; ++t)
      for (int k = 0; k < 3; ++k)
        same &= t1.mesh.triangles[t][k] + last_first_vertex_ == sc.mesh.triangles[last_first_triangle_ + t][k];
    if (!same)
      fail(option.where, "-motion " + path.string() + ": its faces and vertices do not match those of the previous -i");
    if (sc.vertices_t1.empty()) sc.vertices_t1 = sc.mesh.vertices;
    std::copy(t1.mesh.vertices.begin(), t1.mesh.vertices.end(), sc.vertices_t1.begin() + last_first_vertex_);
    s_.files.push_back(path);
    has_last_ = false;
  }

  // -renderer NAME [{ key = value ... }]
  void renderer(const Token& option) {
    const Token& name = take(option, "a renderer name");
    if (name.text == "pathtracer" || name.text == "pt") {
      s_.options.eye_light = false;
    } else if (name.text == "debug") {
      s_.options.eye_light = true;
    } else {
      fail(name.where, "-renderer: unknown renderer '" + scene_io::shown(name.text) +
                           "' (pathtracer, pt or debug)");
    }
    if (pos_ >= tokens_->size() || (*tokens_)[pos_].text != "{") return;
    const Token& open = (*tokens_)[pos_++];
    while (true) {
      if (pos_ >= tokens_->size()) fail(open.where, "-renderer: '{' without its '}'");
      const Token& key = (*tokens_)[pos_++];
      if (key.text == "}") break;
      if (key.text == "{") fail(key.where, "-renderer: '{' inside a parameter block");
      const Token& eq = take(key, "'=' after the parameter name");
      if (eq.text != "=")
        fail(eq.where, "-renderer: expected '=' after '" + scene_io::shown(key.text) +
                           "', found '" + scene_io::shown(eq.text) + "'");
      if (key.text == "depth" || key.text == "maxDepth") {
        s_.options.max_depth = static_cast<int>(integer(key, 0, 1 << 16));
      } else if (key.text == "spp") {
        s_.options.spp = static_cast<int>(integer(key, 1, 1 << 20));
      } else if (key.text == "rrDepth") {
        // RTK's own: the bounces before Russian roulette starts (chapter 14).
        s_.options.rr_depth = static_cast<int>(integer(key, 0, 1 << 16));
      } else if (key.text == "minContribution") {
        const float m = number(key);
        if (!(m >= 0.0f)) fail(key.where, "-renderer: minContribution must be 0 or more");
        s_.options.min_contribution = m;
      } else {
        // A parameter we do not model (Embree 1.1 has a few more): its value is the
        // tokens up to the next "key =" or the closing brace.
        warn(key.where, "-renderer: parameter '" + scene_io::shown(key.text) +
                            "' is not modelled and is ignored");
        while (pos_ < tokens_->size() && (*tokens_)[pos_].text != "}" &&
               !(pos_ + 1 < tokens_->size() && (*tokens_)[pos_ + 1].text == "="))
          ++pos_;
      }
    }
  }

  void option() {
    const Token& o = (*tokens_)[pos_++];
    std::string_view name = o.text;
    if (name.starts_with("--")) name.remove_prefix(1);
    // Each -o renders the state set up before it (ScriptOutput); what follows the last one
    // changes no image. An included script is counted by its own options.
    if (name != "-o" && name != "-c") {
      ++s_.options_read;
      if (!s_.output_states.empty() && s_.after_last_output.empty())
        s_.after_last_output = where_text(o.where) + ": " + o.text;
    }
    // Everything that adds to the scene keeps it first for the outputs named before.
    if (name.ends_with("light") || name == "-trisphere") keep_scene_for_outputs();
    RenderScene& sc = s_.scene;
    CameraParams& cam = sc.camera;
    if (name == "-c") include(o);
    else if (name == "-i") geometry(o);
    else if (name == "-motion") motion(o);
    // The camera's values are checked one by one here; whether they make a camera together
    // (-vi apart from -vp, -vu not along the view) is checked when the camera is made, and
    // that error names the places recorded in given_at.
    else if (name == "-vp")
      given(o), cam.position = vec3(o);
    else if (name == "-vi")
      given(o), cam.look_at = vec3(o);
    else if (name == "-vd") {
      given(o, "-vi");
      const Vec3f d = vec3(o);
      if (!(length(d) > 0.0f)) fail(o.where, "-vd: the view direction is zero");
      cam.look_at = cam.position + d;
    } else if (name == "-vu") {
      given(o);
      cam.up = vec3(o);
      if (!(length(cam.up) > 0.0f)) fail(o.where, "-vu: the up vector is zero");
    } else if (name == "-fov" || name == "-angle") {
      given(o, "-fov");
      cam.fov_degrees = number(o);
      if (!(cam.fov_degrees > 0.0f && cam.fov_degrees < 180.0f))
        fail(o.where,
             o.text + ": " + std::to_string(cam.fov_degrees) + " degrees is not between 0 and 180");
    } else if (name == "-radius") {
      given(o);
      cam.lens_radius = number(o);
      if (cam.lens_radius < 0.0f)
        fail(o.where, "-radius: the lens radius must be 0 (a pinhole) or more");
    } else if (name == "-focaldistance") {
      given(o);
      cam.focal_distance = number(o);
      if (cam.focal_distance < 0.0f)
        fail(o.where, "-focaldistance: must be 0 (the look-at distance) or more");
    } else if (name == "-size") {
      s_.options.width = static_cast<int>(integer(o, 1, 1 << 15));
      s_.options.height = static_cast<int>(integer(o, 1, 1 << 15));
      if (uint64_t(s_.options.width) * uint64_t(s_.options.height) > kMaxRenderPixels)
        fail(o.where, "-size: " + std::to_string(s_.options.width) + " x " +
                          std::to_string(s_.options.height) + " is more than " +
                          std::to_string(kMaxRenderPixels) + " pixels");
    } else if (name == "-spp")
      s_.options.spp = static_cast<int>(integer(o, 1, 1 << 20));
    else if (name == "-depth") s_.options.max_depth = static_cast<int>(integer(o, 0, 1 << 16));
    else if (name == "-seed") s_.options.seed = static_cast<uint32_t>(integer(o, 0, 0xFFFFFFFFll));
    else if (name == "-threads") s_.options.threads = static_cast<int>(integer(o, 0, 1024));
    else if (name == "-gamma") {
      const float g = number(o);
      if (!(g > 0.0f && g <= 100.0f)) fail(o.where, "-gamma: must be above 0 and at most 100");
      s_.tone.gamma = g;
    } else if (name == "-renderer") renderer(o);
    else if (name == "-accel")
      given(o), s_.accel.accel = take(o, "an acceleration structure").text;
    else if (name == "-tri")
      given(o), s_.accel.tri = take(o, "a triangle layout").text;
    else if (name == "-isa") {
      given(o);  // whether the CPU runs it is known when the scene is built
      const Token& t = take(o, "an ISA name");
      const std::optional<Isa> isa = parse_isa(t.text);
      if (!isa)
        fail(t.where,
             "-isa: unknown ISA '" + scene_io::shown(t.text) + "' (scalar, sse4, avx2 or avx512)");
      s_.accel.isa = isa;
    } else if (name == "-kernels") {
      given(o);  // whether Embree is there, and takes the other options, too
      const Token& t = take(o, "kernels (rtk or embree)");
      if (t.text != "rtk" && t.text != "embree")
        fail(t.where,
             "-kernels: unknown kernels '" + scene_io::shown(t.text) + "' (rtk or embree)");
      s_.kernels = t.text;
    } else if (name == "-sampler") {
      const Token& t = take(o, "a sampler name");
      at(o, [&] { s_.options.sampler = parse_sampler_type(t.text); }, &t);
    } else if (name == "-filter") {
      const Token& t = take(o, "a filter name");
      at(o, [&] { s_.options.filter = parse_filter_type(t.text); }, &t);
    } else if (name == "-ambientlight") {
      const Color l = color(o);
      at(o, [&] { sc.add_light(std::make_shared<AmbientLight>(l)); });
    } else if (name == "-pointlight") {
      const Vec3f p = vec3(o);
      const Color i = color(o);
      at(o, [&] { sc.add_light(std::make_shared<PointLight>(p, i)); });
    } else if (name == "-spotlight") {
      const Vec3f p = vec3(o), d = vec3(o);
      const Color i = color(o);
      const float inner = number(o), outer = number(o);
      at(o, [&] { sc.add_light(std::make_shared<SpotLight>(p, d, i, inner, outer)); });
    } else if (name == "-directionallight" || name == "-dirlight") {
      const Vec3f d = vec3(o);
      const Color e = color(o);
      at(o, [&] { sc.add_light(std::make_shared<DirectionalLight>(d, e)); });
    } else if (name == "-distantlight") {
      const Vec3f d = vec3(o);
      const Color l = color(o);
      const float angle = number(o);
      at(o, [&] { sc.add_light(std::make_shared<DistantLight>(d, l, angle)); });
    } else if (name == "-trianglelight" || name == "-quadlight") {
      const Vec3f p = vec3(o), u = vec3(o), v = vec3(o);
      const Color l = color(o);
      at(o, [&] {
        if (name == "-quadlight") {
          sc.add_area_light(make_quad_light(p, u, v, l), l);
        } else {
          const std::shared_ptr<const TriangleLight> t = std::make_shared<TriangleLight>(p, p + u, p + v, l);
          sc.add_area_light({&t, 1}, l);
        }
      });
    } else if (name == "-hdrilight") {
      const Color l = color(o);
      const std::filesystem::path path = file(o);
      const TextureConventions& c = s_.conventions;
      at(o, [&] {
        sc.add_light(std::make_shared<EnvironmentLight>(
            load_environment_image(path.string(), c.encoding), l, Frame({1, 0, 0}, {0, 0, 1}, {0, 1, 0}),
            c.embree11_environment ? EnvironmentMapping::embree11 : EnvironmentMapping::rtk));
      });
      s_.files.push_back(path);
    } else if (name == "-trisphere") {
      const Vec3f p = vec3(o);
      const float r = number(o);
      const int theta = static_cast<int>(integer(o, 2, 4096)), phi = static_cast<int>(integer(o, 3, 4096));
      if (!(r > 0.0f)) fail(o.where, "-trisphere: the radius must be above 0");
      generated_ += 2ull * theta * phi;
      if (generated_ > kMaxGeneratedTriangles)
        fail(o.where, "-trisphere: the spheres of the scripts would make more than " +
                          std::to_string(kMaxGeneratedTriangles) + " triangles");
      add_sphere(p, r, theta, phi);
    } else if (name == "-o") {
      // An output that cannot be written is found now, before any rendering.
      const Token& t = take(o, "a file name");
      const std::filesystem::path path = dir_ / t.text;
      try {
        check_output_path(path);
      } catch (const FileError& e) {
        fail(t.where, std::string("-o: ") + e.what());
      }
      ScriptOutput out;
      out.path = path;
      out.state = s_.options_read;
      out.options = s_.options;
      out.tone = s_.tone;
      out.camera = sc.camera;
      out.accel = s_.accel;
      out.kernels = s_.kernels;
      s_.output_states.push_back(std::move(out));
      s_.after_last_output.clear();
    } else if (name == "-conventions") {
      // The images read after it: Embree 1.1's conventions (the guide's scenes were made for
      // them) or RTK's (chapter 12's TextureConventions says how they differ).
      const Token& t = take(o, "embree1.1 or rtk");
      if (t.text == "embree1.1")
        s_.conventions = TextureConventions::embree11();
      else if (t.text == "rtk")
        s_.conventions = TextureConventions{};
      else
        fail(t.where, "-conventions: unknown conventions '" + scene_io::shown(t.text) + "' (embree1.1 or rtk)");
    } else if (name == "-righthanded" || name == "-lefthanded") {
      // Embree 1.1's camera is left-handed (chapter 11); Embree 2 and 3 added the choice, and
      // Embree 3's scripts expect right-handed. RTK's own scenes say which they are.
      cam.right_handed = name == "-righthanded";
    } else if (name == "-backplate") {
      // Embree 1.1's backplate: an image camera rays see where they meet nothing, read by
      // the conventions in effect and stretched over the frame.
      const std::filesystem::path path = file(o);
      keep_scene_for_outputs();
      const TextureConventions& c = s_.conventions;
      at(o, [&] {
        sc.backplate = load_image_texture(path.string(), c.encoding, WrapMode::clamp, c.lookup, TextureOrigin::bottom);
      });
      s_.files.push_back(path);
    } else if (name == "-refine") {
      // The viewer's progressive refinement at start (its r key toggles it).
      s_.refine = integer(o, 0, 1) != 0;
    } else if (name == "-fullscreen") {
      s_.fullscreen = true;  // the viewer's window fills the screen
    } else if (name == "-time") {
      // A decimal number of seconds: NaN, infinity, zero and negative times are refused.
      const Token& t = take(o, "a number of seconds");
      const double seconds = scene_io::parse_float(t.text, t.where, o.text, 0.0f, 1e6f);
      if (!(seconds > 0.0))
        fail(t.where, "-time: " + scene_io::shown(t.text) + " seconds is not above 0");
      s_.time_limit = seconds;
    } else if (name == "-reference") {
      // The converged image must be there and linear; it is read when the render ends, but a
      // missing or unreadable file is an error now, before any work.
      const Token& t = take(o, "an image file");
      const std::filesystem::path path = dir_ / t.text;
      // The formats that keep linear floats, named as write_image names them.
      bool linear = false;
      try {
        const ImageFormat format = image_format_from_path(path.string());
        linear = format == ImageFormat::pfm || format == ImageFormat::hdr || format == ImageFormat::exr;
      } catch (const std::invalid_argument&) {
      }
      if (!linear)
        fail(t.where, "-reference " + scene_io::shown(t.text) +
                          ": needs a linear image, .pfm, .hdr or .exr (8-bit images are tone-mapped)");
      if (!std::filesystem::is_regular_file(path))
        fail(t.where, "-reference: cannot open '" + path.string() + "'");
      s_.reference = path;
    } else if (name == "-vignetting") {
      // Embree 1.1's switch, read as the natural cos^4 falloff of a real camera (chapter 11).
      cam.vignetting = integer(o, 0, 1) != 0;
    } else if (name == "-display") {
      warn(o.where, o.text + ": the viewer is opened by running rtk without -o");
    } else {
      fail(o.where, "unknown option '" + scene_io::shown(o.text) + "'");
    }
  }

  // The guide's -trisphere: a red matte sphere tessellated in latitude and longitude rings.
  void add_sphere(Vec3f centre, float radius, int num_theta, int num_phi) {
    RenderScene& sc = s_.scene;
    ParameterList params;
    params.set("reflectance", Color(1.0f, 0.0f, 0.0f));
    const uint32_t material = sc.add_material(make_material("Matte", params));
    const uint32_t base = static_cast<uint32_t>(sc.mesh.vertices.size());
    for (int i = 0; i <= num_theta; ++i)
      for (int j = 0; j < num_phi; ++j) {
        const float theta = i * kPi / num_theta, phi = j * 2.0f * kPi / num_phi;
        const Vec3f d{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
        sc.mesh.vertices.push_back(centre + d * radius);
        if (!sc.normals.empty()) sc.normals.push_back(d);
        if (!sc.uvs.empty()) sc.uvs.push_back({float(j) / num_phi, float(i) / num_theta});
        if (sc.has_motion()) sc.vertices_t1.push_back(centre + d * radius);
      }
    auto at = [&](int i, int j) { return base + static_cast<uint32_t>(i * num_phi + (j % num_phi)); };
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
      sc.mesh.triangles.push_back({a, b, c});
      sc.triangle_material.push_back(material);
      sc.triangle_light.push_back(kNoLight);
    };
    for (int i = 1; i <= num_theta; ++i)
      for (int j = 1; j <= num_phi; ++j) {
        if (i > 1) add(at(i, j - 1), at(i - 1, j), at(i - 1, j - 1));
        if (i < num_theta) add(at(i, j), at(i - 1, j), at(i, j - 1));
      }
  }

  // [ch14-script-outputs]
  // Before the scene changes, the outputs named so far keep a copy of it as it is (one copy,
  // shared by all of them); an output named after the last change renders the final scene.
  void keep_scene_for_outputs() {
    std::shared_ptr<const RenderScene> copy;
    for (ScriptOutput& out : s_.output_states)
      if (!out.scene) {
        if (!copy) copy = std::make_shared<const RenderScene>(s_.scene);
        out.scene = copy;
      }
  }

  // [ch14-script-outputs]

  static std::string where_text(const Where& w) {
    return w.line ? w.file + ":" + std::to_string(w.line) : w.file;
  }

  // Records where an option was given (under `key`, or its own name), for the checks that
  // can only be made once everything is read.
  void given(const Token& option, std::string_view key = {}) {
    std::string_view name = key.empty() ? std::string_view(option.text) : key;
    if (name.starts_with("--")) name.remove_prefix(1);
    s_.given_at[std::string(name)] = option.where;
  }

  SceneScript& s_;
  const WarningHandler& warn_;
  uint64_t generated_ = 0;
  int depth_;
  const std::vector<Token>* tokens_ = nullptr;
  std::filesystem::path dir_;
  size_t pos_ = 0;
  size_t last_first_vertex_ = 0, last_first_triangle_ = 0;
  bool has_last_ = false;
};

}  // namespace

// [scene-script-help]
// One line per option, in the order of a script's life: files, camera, image, renderer,
// kernels, lights, output, what is read and ignored.
constexpr ScriptOptionHelp kScriptOptions[] = {
    {"-c", "FILE.ecs", "read a command script (its files are relative to it)"},
    {"-i", "FILE.obj|FILE.xml", "load geometry: OBJ with its MTL materials, or an Embree XML scene"},
    {"-motion", "FILE.obj", "the previous -i at shutter time 1 (motion blur)"},
    {"-trisphere", "x y z r numTheta numPhi", "a red matte sphere of triangles"},
    {"-vp", "x y z", "camera position (default 0 0 0)"},
    {"-vi", "x y z", "point of interest, seen at the image centre (default 1 0 0)"},
    {"-vd", "x y z", "view direction (instead of -vi)"},
    {"-vu", "x y z", "up direction (default 0 1 0)"},
    {"-fov", "degrees", "vertical field of view (default 64); also -angle"},
    {"-angle", "degrees", "the same as -fov"},
    {"-radius", "r", "lens radius: 0 a pinhole, more a thin lens (depth of field)"},
    {"-focaldistance", "d", "distance in focus (default 0: the point of interest's)"},
    {"-lefthanded", "", "Embree 1.1's camera, right = cross(up, view) (the default)"},
    {"-righthanded", "", "Embree 3's camera: the same view mirrored left to right"},
    {"-size", "w h", "image size in pixels (default 512 512)"},
    {"-spp", "n", "samples per pixel (default 1)"},
    {"-depth", "n", "most scattering events on a path (default 10)"},
    {"-gamma", "g", "display gamma of 8-bit outputs (default 1)"},
    {"-renderer", "NAME [{ key = value ... }]", "pathtracer (pt) { depth spp minContribution rrDepth } or debug (eye light)"},
    {"-seed", "n", "random seed: another, equally good image"},
    {"-sampler", "independent|sobol", "sample generator (default sobol)"},
    {"-filter", "box|tent|bspline", "pixel filter (default box)"},
    {"-threads", "n", "worker threads (default 0: every core)"},
    {"-accel", "SPEC", "acceleration structure: bvh2, bvh4, bvh8[.objectsplit|.spatialsplit], bvh4mb"},
    {"-tri", "SPEC", "triangle layout and intersector, e.g. triangle4.moeller"},
    {"-isa", "scalar|sse4|avx2|avx512", "the kernels' instruction set (default: the best the CPU runs)"},
    {"-kernels", "rtk|embree", "who traces the rays: RTK's kernels or Embree 3's"},
    {"-ambientlight", "r g b", "uniform light from every direction"},
    {"-pointlight", "x y z r g b", "point light: position and intensity"},
    {"-spotlight", "x y z dx dy dz r g b angleMin angleMax", "spot light: full intensity within angleMin degrees of its axis, none beyond angleMax"},
    {"-directionallight", "dx dy dz r g b", "light along a direction: direction and irradiance"},
    {"-dirlight", "dx dy dz r g b", "the same as -directionallight"},
    {"-distantlight", "dx dy dz r g b halfAngle", "a distant disk (the sun): direction, radiance, half angle"},
    {"-trianglelight", "px py pz ux uy uz vx vy vz r g b", "emitting triangle P, P+U, P+V of radiance L"},
    {"-quadlight", "px py pz ux uy uz vx vy vz r g b", "emitting parallelogram P, U, V of radiance L"},
    {"-hdrilight", "r g b FILE", "environment map scaled by L (.hdr .exr .pfm .ppm .png ...)"},
    {"-conventions", "embree1.1|rtk", "how later images are read (default embree1.1: t = 0 top, nearest, 8-bit linear, 1.1's sky)"},
    {"-o", "FILE", "render the state set up so far to .png .tga .ppm .hdr .pfm .exr"},
    {"-time", "SECONDS", "rtk render: render progressively until the time is spent (instead of -spp)"},
    {"-reference", "IMAGE", "rtk render: print the relative RMS error against this converged .pfm .hdr .exr"},
    {"-vignetting", "0|1", "natural vignetting: the image darkens as cos^4 of the angle to the view axis (default 0)"},
    {"-backplate", "FILE", "an image behind the scene, seen by camera rays that hit nothing"},
    {"-refine", "0|1", "the viewer refines progressively at start (1, the default) or not (0); its r key toggles it"},
    {"-display", "", "ignored: rtk without -o opens the viewer"},
    {"-fullscreen", "", "the viewer's window fills the screen"},
};
// [scene-script-help]

std::span<const ScriptOptionHelp> script_option_help() { return kScriptOptions; }

void read_script_file(const std::filesystem::path& path, SceneScript& script,
                      const WarningHandler& warn) {
  script.files.push_back(path);
  read_script_text(read_file(path, kMaxTextFileBytes), path, script, warn);
}

void read_script_text(std::string_view text, const std::filesystem::path& path, SceneScript& script,
                      const WarningHandler& warn) {
  const std::vector<Token> tokens = tokenize(text, path.string());
  ScriptReader(script, warn, 0).run(tokens, path.parent_path());
}

void read_script_args(std::span<const std::string_view> args, SceneScript& script, const WarningHandler& warn) {
  std::vector<Token> tokens;
  for (size_t i = 0; i < args.size(); ++i)
    tokens.push_back({std::string(args[i]), {"command line, argument " + std::to_string(i + 1), 0}});
  ScriptReader(script, warn, 0).run(tokens, {});
}

}  // namespace rtk
