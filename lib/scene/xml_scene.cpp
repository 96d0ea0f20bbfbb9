#include "scene/xml_scene.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <optional>
#include <pugixml.hpp>
#include <set>

#include "13_lights/area_light.h"
#include "13_lights/distant_light.h"
#include "13_lights/environment_light.h"
#include "13_lights/point_light.h"
#include "15_device/sphere_mesh.h"
#include "io/file_error.h"
#include "io/read_file.h"
#include "scene/obj_scene.h"
#include "scene/parse_number.h"
#include "scene/scene_limits.h"

namespace rtk {

namespace {

using scene_io::Where;

// An affine map x' = c0 x + c1 y + c2 z + p (columns of the guide's 3x4 matrix).
struct Affine {
  Vec3f c0{1, 0, 0}, c1{0, 1, 0}, c2{0, 0, 1}, p{0, 0, 0};
  Vec3f vector(Vec3f v) const { return c0 * v.x + c1 * v.y + c2 * v.z; }
  Vec3f point(Vec3f v) const { return vector(v) + p; }
  // Normals go through the inverse transpose; the cofactor matrix is that times the
  // determinant, whose sign must be kept.
  Vec3f normal(Vec3f n) const {
    const float det = dot(c0, cross(c1, c2));
    const Vec3f m = cross(c1, c2) * n.x + cross(c2, c0) * n.y + cross(c0, c1) * n.z;
    const float len = std::sqrt(dot(m, m));
    return len > 0 ? m * ((det < 0 ? -1.0f : 1.0f) / len) : Vec3f{0, 0, 0};
  }
  Affine operator*(const Affine& b) const { return {vector(b.c0), vector(b.c1), vector(b.c2), point(b.p)}; }
  bool is_identity() const {
    return c0 == Vec3f{1, 0, 0} && c1 == Vec3f{0, 1, 0} && c2 == Vec3f{0, 0, 1} && p == Vec3f{0, 0, 0};
  }
};

// What all the files of one scene share: the triangles made rather than read so far
// (kMaxGeneratedTriangles).
struct SceneBudget {
  uint64_t generated = 0;
};

// One XML file being read: the document, the line table for messages, the side file of
// binary arrays (read when first needed) and the reused definitions.
class XmlReader {
 public:
  XmlReader(const std::filesystem::path& path, RenderScene& scene, const WarningHandler& warn,
            int include_depth, SceneBudget& budget, const TextureConventions& conventions)
      : conventions_(conventions),
        path_(path),
        file_(path.string()),
        scene_(scene),
        warn_(warn),
        include_depth_(include_depth),
        budget_(budget) {}

  void run() { run(read_file(path_)); }

  void run(std::string text) {
    text_ = std::move(text);
    // Line starts, so that pugixml's byte offsets become line numbers.
    line_starts_.push_back(0);
    for (size_t i = 0; i < text_.size(); ++i)
      if (text_[i] == '\n') line_starts_.push_back(i + 1);
    const pugi::xml_parse_result result = doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default);
    if (!result) throw FileError(file_, line_of(result.offset), std::string("malformed XML: ") + result.description());
    const pugi::xml_node root = doc_.child("scene");
    if (!root) throw FileError(file_, 1, "the root element must be <scene>");
    children(root, Affine{});
  }

 private:
  // A scene assigned to an id, and its place among the file's scene assignments.
  struct Assigned {
    pugi::xml_node node;
    size_t order;  // the how-manieth scene assignment of the file
  };

  size_t line_of(ptrdiff_t offset) const {
    if (offset < 0) return 0;
    return static_cast<size_t>(std::upper_bound(line_starts_.begin(), line_starts_.end(), size_t(offset)) -
                               line_starts_.begin());
  }
  Where where(const pugi::xml_node& n) const { return {file_, line_of(n.offset_debug())}; }
  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& message) const {
    throw FileError(file_, line_of(n.offset_debug()), message);
  }
  void warn(const pugi::xml_node& n, const std::string& message) const {
    if (warn_) warn_(file_ + ":" + std::to_string(line_of(n.offset_debug())) + ": " + message);
  }
  pugi::xml_node require(const pugi::xml_node& n, const char* name) const {
    const pugi::xml_node c = n.child(name);
    if (!c) fail(n, std::string("<") + n.name() + "> needs a <" + name + ">");
    return c;
  }
  // A file this one names, reported at the line that names it when it cannot be read or is
  // not valid as a whole (its own errors at its own lines pass unchanged).
  template <class Body>
  auto referenced(const pugi::xml_node& n, const std::string& what, Body&& body) {
    try {
      return body();
    } catch (const FileError& e) {
      if (e.line() != 0) throw;
      fail(n, what + ": " + e.what());
    }
  }
  // Counts the triangles a reference or a sphere is about to make against the scene's budget.
  void generate(const pugi::xml_node& n, uint64_t triangles) {
    if (budget_.generated + triangles > kMaxGeneratedTriangles)
      fail(n, "<" + std::string(n.name()) + ">: the scene would make more than " +
                  std::to_string(kMaxGeneratedTriangles) +
                  " triangles by references and spheres (" + std::to_string(budget_.generated) +
                  " so far)");
    budget_.generated += triangles;
  }

  // ---- Values -------------------------------------------------------------------------

  std::vector<std::string_view> tokens(const pugi::xml_node& n) const {
    std::vector<std::string_view> out;
    std::string_view s = n.child_value();
    size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      const size_t start = i;
      while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i > start) out.push_back(s.substr(start, i - start));
    }
    return out;
  }
  std::vector<float> numbers(const pugi::xml_node& n, size_t count) const {
    std::vector<float> out;
    for (std::string_view t : tokens(n)) out.push_back(scene_io::parse_float(t, where(n), n.name()));
    if (count && out.size() != count)
      fail(n, std::string("<") + n.name() + "> needs " + std::to_string(count) + " numbers, has " + std::to_string(out.size()));
    return out;
  }
  float number(const pugi::xml_node& n) const { return numbers(n, 1)[0]; }
  Vec3f vec3(const pugi::xml_node& n) const {
    const auto v = numbers(n, 3);
    return {v[0], v[1], v[2]};
  }
  int integer(const pugi::xml_node& n, int min, int max) const {
    const auto t = tokens(n);
    if (t.size() != 1) fail(n, std::string("<") + n.name() + "> needs one integer");
    return static_cast<int>(scene_io::parse_int(t[0], where(n), n.name(), min, max));
  }
  std::string quoted(const pugi::xml_node& n) const {
    std::string s = n.child_value();
    const size_t a = s.find('"'), b = s.rfind('"');
    if (a == std::string::npos || b == a) fail(n, std::string("<") + n.name() + "> needs a quoted string");
    return s.substr(a + 1, b - a - 1);
  }

  // An array of `width` numbers per element: inline text, or ofs/size in the side file.
  template <class T>
  std::vector<T> array(const pugi::xml_node& n, int width) const {
    std::vector<T> out;
    if (n.attribute("ofs") || n.attribute("size")) {
      const long long ofs = attribute_int(n, "ofs"), size = attribute_int(n, "size");
      const std::string& bin = side_file(n);
      // Checked by division: size * width * 4 may not fit in 64 bits.
      const uint64_t record = static_cast<uint64_t>(width) * 4;
      if (static_cast<uint64_t>(ofs) > bin.size() ||
          static_cast<uint64_t>(size) > (bin.size() - ofs) / record)
        fail(n, std::string("<") + n.name() + ">: " + std::to_string(size) + " elements of " +
                    std::to_string(record) + " bytes from byte " + std::to_string(ofs) +
                    " lie outside the binary file (" + std::to_string(bin.size()) + " bytes)");
      const uint64_t bytes = static_cast<uint64_t>(size) * record;
      out.resize(static_cast<size_t>(size) * width);
      if (bytes > 0) std::memcpy(out.data(), bin.data() + ofs, bytes);  // little-endian, as the machine
      if constexpr (std::is_same_v<T, float>)
        for (float f : out)
          if (!std::isfinite(f)) fail(n, std::string("<") + n.name() + ">: a number in the binary file is not finite");
      return out;
    }
    for (std::string_view t : tokens(n)) {
      if constexpr (std::is_same_v<T, float>) out.push_back(scene_io::parse_float(t, where(n), n.name()));
      else out.push_back(static_cast<int>(scene_io::parse_int(t, where(n), n.name(), 0, INT32_MAX)));
    }
    if (out.size() % width != 0)
      fail(n, std::string("<") + n.name() + ">: " + std::to_string(out.size()) + " numbers are not a multiple of " + std::to_string(width));
    return out;
  }

  // An attribute that must be a whole number, not negative: ofs and size of binary arrays.
  long long attribute_int(const pugi::xml_node& n, const char* name) const {
    const pugi::xml_attribute a = n.attribute(name);
    if (!a) fail(n, std::string("<") + n.name() + ">: ofs and size must both be given");
    return scene_io::parse_int(a.value(), where(n), std::string("<") + n.name() + " " + name + ">",
                               0, LLONG_MAX);
  }

  const std::string& side_file(const pugi::xml_node& n) const {
    if (!bin_) {
      std::filesystem::path a = path_, b = path_;
      a.replace_extension(".bin");
      b += ".bin";
      const std::filesystem::path& bin = std::filesystem::is_regular_file(a) ? a : b;
      if (!std::filesystem::is_regular_file(bin))
        fail(n, "binary array but no side file (" + a.string() + " or " + b.string() + ")");
      try {
        bin_ = read_file(bin);
      } catch (const FileError& e) {
        fail(n, std::string("binary array: ") + e.what());
      }
    }
    return *bin_;
  }

  // ---- Scene graph --------------------------------------------------------------------

  void children(const pugi::xml_node& parent, const Affine& xfm) {
    for (pugi::xml_node n : parent.children())
      if (n.type() == pugi::node_element) node(n, xfm);
  }

  // [ch14-xml-depth]
  // The reader descends the scene graph recursively, one call per level of elements and per
  // <ref> followed: the depth is bounded so that a file nested 12,000 deep is an error at the
  // element that goes too deep, not a stack overflow.
  void node(const pugi::xml_node& n, const Affine& xfm) {
    if (depth_ >= kMaxXmlDepth)
      fail(n, "<" + scene_io::shown(n.name()) + ">: elements and references nested more than " +
                  std::to_string(kMaxXmlDepth) + " deep");
    ++depth_;
    visit(n, xfm);
    --depth_;
  }
  // [ch14-xml-depth]

  void visit(const pugi::xml_node& n, const Affine& xfm) {
    const std::string name = n.name();
    if (name == "Group") children(n, xfm);
    else if (name == "Transform") transform(n, xfm);
    else if (name == "TriangleMesh") triangle_mesh(n, xfm);
    else if (name == "Sphere") sphere(n, xfm);
    else if (name == "PointLight" || name == "SpotLight" || name == "DirectionalLight" || name == "DistantLight" ||
             name == "AmbientLight" || name == "TriangleLight" || name == "QuadLight" || name == "HDRILight")
      light(n, xfm);
    else if (name == "assign") assign(n);
    else if (name == "ref") ref(n, xfm); else if (name == "obj" || name == "xml" || name == "extern") include(n, xfm);
    else if (name == "PerspectiveCamera") {
      if (!camera_warned_) warn(n, "<PerspectiveCamera> is ignored: the script's -vp, -vi, -vu and -fov place the camera");
      camera_warned_ = true;
    } else if (!skipped_.count(name)) {
      skipped_.insert(name);
      warn(n, "<" + scene_io::shown(name) + "> is not supported and is skipped");
    }
  }

  // A <ref> names the scene assigned to its id *before* the scene it appears in: Embree's
  // loaders resolve references as they parse, so a file may reassign an id to a scene that
  // refers to the id's previous meaning (cornell_box_4 made of four copies of cornell_box_4).
  // Resolving only earlier assignments also means that references can never form a cycle.
  // The assignment a <ref> names: the latest one of its id before the current scope.
  const Assigned& target_of(const pugi::xml_node& n) const {
    const std::string id = n.attribute("id").as_string();
    const Assigned* target = nullptr;
    if (auto it = scenes_.find(id); it != scenes_.end())
      for (const Assigned& a : it->second)
        if (a.order < scope_) target = &a;
    if (!target)
      fail(n, "<ref>: no scene assigned with id '" + scene_io::shown(id) + "' before this point");
    return *target;
  }

  // [ch14-xml-budget]
  // Every triangle a reference adds is a copy, counted against the budget before the copy is
  // made: the triangles an assigned scene holds are counted once, without reading it, so that
  // 3.6 KB of references that double at every level are refused at the first <ref>, before
  // anything is allocated.
  void ref(const pugi::xml_node& n, const Affine& xfm) {
    const Assigned& target = target_of(n);
    const uint64_t copies = triangles_in(target, depth_);
    if (budget_.generated + copies > kMaxGeneratedTriangles) generate(n, copies);
    const size_t outer = scope_;
    scope_ = target.order;
    ++in_reference_;
    node(target.node, xfm);
    --in_reference_;
    scope_ = outer;
  }
  // [ch14-xml-budget]

  // The triangles reading `n` would add, counted without reading it (included files count
  // for nothing here; they are charged once read). The count descends as the reading would,
  // and so has the same depth limit.
  uint64_t count_triangles(const pugi::xml_node& n, int depth) {
    if (depth >= kMaxXmlDepth)
      fail(n, "<" + scene_io::shown(n.name()) + ">: elements and references nested more than " +
                  std::to_string(kMaxXmlDepth) + " deep");
    const std::string_view name = n.name();
    if (name == "TriangleMesh") {
      const pugi::xml_node t = n.child("triangles");
      if (t.attribute("size")) return static_cast<uint64_t>(attribute_int(t, "size"));
      return tokens(t).size() / 3;
    }
    if (name == "Sphere") {
      const uint64_t theta = integer(require(n, "numTheta"), 2, 4096),
                     phi = integer(require(n, "numPhi"), 3, 4096);
      return 2 * theta * phi;
    }
    if (name == "ref") {
      const Assigned& target = target_of(n);
      const size_t outer = scope_;
      scope_ = target.order;
      const uint64_t count = triangles_in(target, depth + 1);
      scope_ = outer;
      return count;
    }
    uint64_t sum = 0;
    if (name == "Group" || name == "Transform")
      for (pugi::xml_node c : n.children())
        if (c.type() == pugi::node_element)
          sum = std::min(sum + count_triangles(c, depth + 1), uint64_t(1) << 62);
    return sum;
  }
  // The triangles of an assigned scene, counted once.
  uint64_t triangles_in(const Assigned& target, int depth) {
    if (const auto it = counted_.find(target.order); it != counted_.end()) return it->second;
    return counted_[target.order] = count_triangles(target.node, depth);
  }

  void transform(const pugi::xml_node& n, const Affine& xfm) {
    const pugi::xml_node first = n.first_child();
    if (!first || std::strcmp(first.name(), "AffineSpace") != 0) fail(n, "<Transform>: the first child must be an <AffineSpace>");
    const Affine inner = xfm * affine(first);
    for (pugi::xml_node c = first.next_sibling(); c; c = c.next_sibling())
      if (c.type() == pugi::node_element) node(c, inner);
  }

  Affine affine(const pugi::xml_node& n) const {
    Affine a;
    // Attribute values are read as strictly as element text: "abc" is not 0, "1 2 3 junk" is
    // not (1, 2, 3).
    auto attr_numbers = [&](const char* name, size_t count) {
      std::vector<float> v;
      const std::string what = std::string("<AffineSpace ") + name + ">";
      std::string_view text = n.attribute(name).as_string();
      while (!text.empty()) {
        const size_t start = text.find_first_not_of(" \t\r\n");
        if (start == std::string_view::npos) break;
        const size_t end = std::min(text.find_first_of(" \t\r\n", start), text.size());
        v.push_back(scene_io::parse_float(text.substr(start, end - start), where(n), what));
        text.remove_prefix(end);
      }
      if (v.size() != count)
        fail(n, what + ": needs " + std::to_string(count) + " number" + (count > 1 ? "s" : "") +
                    ", has " + std::to_string(v.size()));
      return v;
    };
    auto attr3 = [&](const char* name) {
      const auto v = attr_numbers(name, 3);
      return Vec3f{v[0], v[1], v[2]};
    };
    auto attr1 = [&](const char* name) { return attr_numbers(name, 1)[0]; };
    constexpr float deg = std::numbers::pi_v<float> / 180.0f;
    auto rotation = [&](Vec3f axis, float degrees) {
      const float len = std::sqrt(dot(axis, axis));
      if (!(len > 0)) fail(n, "<AffineSpace>: the rotation axis is zero");
      const Vec3f u = axis * (1.0f / len);
      const float c = std::cos(degrees * deg), s = std::sin(degrees * deg);
      auto col = [&](Vec3f e) { return e * c + cross(u, e) * s + u * (dot(u, e) * (1 - c)); };
      return Affine{col({1, 0, 0}), col({0, 1, 0}), col({0, 0, 1}), {0, 0, 0}};
    };
    if (n.attribute("translate")) a.p = attr3("translate");
    else if (n.attribute("scale")) {
      const Vec3f s = attr3("scale");
      a.c0 = {s.x, 0, 0}, a.c1 = {0, s.y, 0}, a.c2 = {0, 0, s.z};
    } else if (n.attribute("rotate_x"))
      a = rotation({1, 0, 0}, attr1("rotate_x"));
    else if (n.attribute("rotate_y"))
      a = rotation({0, 1, 0}, attr1("rotate_y"));
    else if (n.attribute("rotate_z"))
      a = rotation({0, 0, 1}, attr1("rotate_z"));
    else if (n.attribute("rotate"))
      a = rotation(attr3("axis"), attr1("rotate"));
    else {
      const auto m = numbers(n, 12);
      a.c0 = {m[0], m[4], m[8]}, a.c1 = {m[1], m[5], m[9]}, a.c2 = {m[2], m[6], m[10]}, a.p = {m[3], m[7], m[11]};
    }
    return a;
  }

  // ---- Materials ----------------------------------------------------------------------

  // The material of a shape: inline, by id, from a file, or the default grey Matte.
  uint32_t material(const pugi::xml_node& shape) {
    const pugi::xml_node m = shape.child("material");
    if (!m) return default_material();
    const std::string id = m.attribute("id").as_string();
    if (!m.first_child() && !id.empty()) {
      auto it = materials_.find(id);
      if (it == materials_.end())
        fail(m, "<material id=\"" + scene_io::shown(id) + "\">: no material assigned with that id");
      return it->second;
    }
    if (m.attribute("file")) {
      const std::filesystem::path p = path_.parent_path() / m.attribute("file").as_string();
      pugi::xml_document doc;
      const std::string text = referenced(m, "<material file>", [&] { return read_file(p); });
      const pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size());
      if (!r) fail(m, "<material file>: " + p.string() + ": malformed XML: " + r.description());
      const pugi::xml_node inner = doc.child("material");
      if (!inner) fail(m, "<material file>: " + p.string() + " has no <material> root");
      return define_material(inner, m);
    }
    const uint32_t index = define_material(m, m);
    if (!id.empty()) materials_[id] = index;  // 2.x: <material id="3"> defines and names
    return index;
  }

  uint32_t define_material(const pugi::xml_node& m, const pugi::xml_node& at) {
    const std::string name = quoted(require(m, "code"));
    ParameterList params;
    for (pugi::xml_node p : m.child("parameters").children()) {
      if (p.type() != pugi::node_element) continue;
      const std::string kind = p.name(), pname = p.attribute("name").as_string();
      if (pname.empty()) fail(p, "<" + kind + ">: needs a name attribute");
      if (kind == "int") params.set(pname, integer(p, INT32_MIN, INT32_MAX));
      else if (kind == "float") params.set(pname, number(p));
      else if (kind == "float2") {
        const auto v = numbers(p, 2);
        params.set(pname, Vec2f{v[0], v[1]});
      } else if (kind == "float3") {
        const auto v = numbers(p, 3);
        params.set(pname, Color(v[0], v[1], v[2]));
      } else if (kind == "texture") {
        const std::filesystem::path file = path_.parent_path() / quoted(p);
        // Opacity and height maps hold data: linear and interpolated, whatever the colours' conventions.
        TextureConventions c = conventions_;
        if (pname == "map_d" || pname == "map_Bump") {
          c.encoding = ColorEncoding::linear;
          c.lookup = TextureLookup::bilinear;
        }
        try {
          params.set(pname, std::shared_ptr<const Texture>(load_image_texture(file.string(), c)));
        } catch (const std::exception& e) {
          fail(p, "<texture name=\"" + pname + "\">: " + e.what());
        }
      } else fail(p, "<" + kind + ">: unknown parameter type (int, float, float2, float3, texture)");
    }
    try {
      return scene_.add_material(make_material(name, params, [&](const std::string& w) { warn(at, w); }));
    } catch (const std::invalid_argument& e) {
      fail(at, std::string("material \"") + name + "\": " + e.what());
    }
  }

  uint32_t default_material() {
    if (!default_material_) default_material_ = scene_.add_material(Material{});
    return *default_material_;
  }

  void assign(const pugi::xml_node& n) {
    const std::string type = n.attribute("type").as_string(), id = n.attribute("id").as_string();
    if (id.empty()) fail(n, "<assign>: needs an id");
    if (type == "material") {
      const pugi::xml_node m = n.child("material");
      if (!m) fail(n, "<assign type=\"material\">: needs a <material>");
      materials_[id] = define_material(m, m);
    } else if (type == "scene") {
      pugi::xml_node first;
      for (pugi::xml_node c : n.children())
        if (c.type() == pugi::node_element) { first = c; break; }
      if (!first) fail(n, "<assign type=\"scene\">: empty");
      scenes_[id].push_back({first, assignments_++});
    } else {
      fail(n, "<assign>: unknown type '" + type + "' (material, scene)");
    }
  }

  // ---- Geometry -----------------------------------------------------------------------

  // Appends triangles with their attributes, keeping the scene's per-vertex vectors as long
  // as its vertex list (absent attributes become zeros, as in the OBJ loader).
  void append(const std::vector<Vec3f>& p, const std::vector<Vec3f>& p1, const std::vector<Vec3f>& normals,
              const std::vector<Vec2f>& uvs, const std::vector<std::array<uint32_t, 3>>& tris, uint32_t material) {
    RenderScene& sc = scene_;
    const size_t old = sc.mesh.vertices.size();
    const auto first = static_cast<uint32_t>(old);
    if (!normals.empty() || !sc.normals.empty()) {
      sc.normals.resize(old, Vec3f{0, 0, 0});
      if (normals.empty()) sc.normals.resize(old + p.size(), Vec3f{0, 0, 0});
      else sc.normals.insert(sc.normals.end(), normals.begin(), normals.end());
    }
    if (!uvs.empty() || !sc.uvs.empty()) {
      sc.uvs.resize(old, Vec2f{});
      if (uvs.empty()) sc.uvs.resize(old + p.size(), Vec2f{});
      else sc.uvs.insert(sc.uvs.end(), uvs.begin(), uvs.end());
    }
    if (!p1.empty() || sc.has_motion()) {
      if (sc.vertices_t1.size() < old)  // vertices loaded before any motion stand still
        sc.vertices_t1.insert(sc.vertices_t1.end(), sc.mesh.vertices.begin() + sc.vertices_t1.size(), sc.mesh.vertices.end());
      const auto& t1 = p1.empty() ? p : p1;
      sc.vertices_t1.insert(sc.vertices_t1.end(), t1.begin(), t1.end());
    }
    sc.mesh.vertices.insert(sc.mesh.vertices.end(), p.begin(), p.end());
    for (const auto& t : tris) {
      sc.mesh.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
      sc.triangle_material.push_back(material);
      sc.triangle_light.push_back(kNoLight);
    }
  }

  void triangle_mesh(const pugi::xml_node& n, const Affine& xfm) {
    const std::vector<float> pos = array<float>(require(n, "positions"), 3);
    const size_t nv = pos.size() / 3;
    std::vector<Vec3f> p(nv), p1, normals;
    std::vector<Vec2f> uvs;
    for (size_t i = 0; i < nv; ++i) p[i] = xfm.point({pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]});
    // Finite numbers can overflow through a transform (1e30 scaled by 1e30).
    auto check_finite = [&](const std::vector<Vec3f>& points, const pugi::xml_node& at) {
      for (size_t i = 0; i < points.size(); ++i)
        if (!is_finite(points[i]))
          fail(at, std::string("<") + at.name() + ">: vertex " + std::to_string(i) +
                       " is not finite after the transforms");
    };
    check_finite(p, n.child("positions"));
    auto per_vertex = [&](const pugi::xml_node& c, size_t count) {
      if (count != 0 && count != nv)
        fail(c, std::string("<") + c.name() + ">: " + std::to_string(count) + " entries for " + std::to_string(nv) + " positions");
      return count != 0;
    };
    if (pugi::xml_node m = n.child("motions")) {
      const auto d = array<float>(m, 3);
      if (per_vertex(m, d.size() / 3))
        for (size_t i = 0; i < nv; ++i) p1.push_back(p[i] + xfm.vector({d[3 * i], d[3 * i + 1], d[3 * i + 2]}));
      check_finite(p1, m);
    }
    if (pugi::xml_node m = n.child("normals")) {
      const auto d = array<float>(m, 3);
      if (per_vertex(m, d.size() / 3))
        for (size_t i = 0; i < nv; ++i) normals.push_back(xfm.normal({d[3 * i], d[3 * i + 1], d[3 * i + 2]}));
    }
    if (pugi::xml_node m = n.child("texcoords")) {
      const auto d = array<float>(m, 2);
      if (per_vertex(m, d.size() / 2))
        for (size_t i = 0; i < nv; ++i) uvs.push_back({d[2 * i], d[2 * i + 1]});
    }
    const pugi::xml_node tn = require(n, "triangles");
    const std::vector<int> idx = array<int>(tn, 3);
    std::vector<std::array<uint32_t, 3>> tris;
    for (size_t i = 0; i < idx.size(); i += 3) {
      for (int k = 0; k < 3; ++k)
        if (static_cast<size_t>(idx[i + k]) >= nv)
          fail(tn, "<triangles>: vertex index " + std::to_string(idx[i + k]) + " of triangle " + std::to_string(i / 3) +
                       " is out of range (" + std::to_string(nv) + " positions)");
      tris.push_back({uint32_t(idx[i]), uint32_t(idx[i + 1]), uint32_t(idx[i + 2])});
    }
    if (in_reference_) generate(n, tris.size());
    append(p, p1, normals, uvs, tris, material(n));
  }

  void sphere(const pugi::xml_node& n, const Affine& xfm) {
    const Vec3f centre = vec3(require(n, "position"));
    const float radius = number(require(n, "radius"));
    const int theta = integer(require(n, "numTheta"), 2, 4096),
              phi = integer(require(n, "numPhi"), 3, 4096);
    generate(n, 2ull * theta * phi);
    SphereMesh s;
    try {
      s = tessellate_sphere(centre, radius, theta, phi);
    } catch (const std::invalid_argument& e) {
      fail(n, std::string("<Sphere>: ") + e.what());
    }
    std::vector<Vec3f> p1;
    for (Vec3f& v : s.vertices) v = xfm.point(v);
    for (Vec3f& v : s.normals) v = xfm.normal(v);
    if (pugi::xml_node m = n.child("motion")) {
      const Vec3f d = xfm.vector(vec3(m));
      for (const Vec3f& v : s.vertices) p1.push_back(v + d);
    }
    for (const auto& points : {s.vertices, p1})
      for (const Vec3f& v : points)
        if (!is_finite(v)) fail(n, "<Sphere>: a vertex is not finite after the transforms");
    append(s.vertices, p1, s.normals, {}, s.triangles, material(n));
  }

  // ---- Lights -------------------------------------------------------------------------

  void light(const pugi::xml_node& n, const Affine& xfm) {
    const std::string name = n.name();
    const Affine space = n.child("AffineSpace") ? xfm * affine(n.child("AffineSpace")) : xfm;
    auto color = [&](const char* c) {
      const Vec3f v = vec3(require(n, c));
      return Color(v.x, v.y, v.z);
    };
    try {
      if (name == "PointLight") {
        scene_.add_light(std::make_shared<PointLight>(space.p, color("I")));
      } else if (name == "SpotLight") {
        // Chapter 13's spot: at the frame's origin, pointing along its z axis.
        scene_.add_light(std::make_shared<SpotLight>(space.p, space.vector({0, 0, 1}), color("I"),
                                                     number(require(n, "angleMin")),
                                                     number(require(n, "angleMax"))));
      } else if (name == "DirectionalLight") {
        scene_.add_light(std::make_shared<DirectionalLight>(space.vector({0, 0, 1}), color("E")));
      } else if (name == "DistantLight") {
        scene_.add_light(std::make_shared<DistantLight>(space.vector({0, 0, 1}), color("L"), number(require(n, "halfAngle"))));
      } else if (name == "AmbientLight") {
        scene_.add_light(std::make_shared<AmbientLight>(color("L")));
      } else if (name == "TriangleLight" || name == "QuadLight") {
        const Color l = color("L");
        if (name == "QuadLight") {
          scene_.add_area_light(make_quad_light(space.p, space.c0, space.c1, l), l);
        } else {
          const std::shared_ptr<const TriangleLight> t =
              std::make_shared<TriangleLight>(space.p, space.p + space.c0, space.p + space.c1, l);
          scene_.add_area_light({&t, 1}, l);
        }
      } else {  // HDRILight: the map's x, z, y axes along the space's columns
        const std::filesystem::path file = path_.parent_path() / quoted(require(n, "image"));
        // The columns must make a frame: none zero (a zero scale would make NaN light), each
        // at right angles to the others (a shear has no orientation to give the map).
        const Vec3f x = space.c0, y = space.c1, z = space.c2;
        const float lx = length(x), ly = length(y), lz = length(z);
        if (!(lx > 0 && ly > 0 && lz > 0) || !std::isfinite(lx * ly * lz) ||
            std::fabs(dot(x, y)) > 1e-4f * lx * ly || std::fabs(dot(y, z)) > 1e-4f * ly * lz ||
            std::fabs(dot(z, x)) > 1e-4f * lz * lx)
          fail(n,
               "<HDRILight>: its AffineSpace must be a rotation (and scale), with no zero or "
               "sheared axis");
        const Frame frame(x / lx, z / lz, y / ly);
        const Color scale = color("L");
        scene_.add_light(std::make_shared<EnvironmentLight>(
            referenced(n, "<HDRILight> image",
                       [&] { return load_environment_image(file.string(), conventions_.encoding); }),
            scale, frame,
            conventions_.embree11_environment ? EnvironmentMapping::embree11 : EnvironmentMapping::rtk));
      }
    } catch (const FileError&) {
      throw;
    } catch (const std::exception& e) {
      fail(n, "<" + name + ">: " + e.what());
    }
  }

  // ---- Inclusion ----------------------------------------------------------------------

  void include(const pugi::xml_node& n, const Affine& xfm) {
    const std::string src = n.attribute("src").as_string();
    if (src.empty()) fail(n, std::string("<") + n.name() + ">: needs a src attribute");
    const size_t triangles_before = scene_.mesh.triangles.size();
    const std::filesystem::path p = path_.parent_path() / src;
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    const size_t first = scene_.mesh.vertices.size();
    const size_t lights_before = scene_.lights.size();
    const std::string what = std::string("<") + n.name() + " src=\"" + scene_io::shown(src) + "\">";
    if (ext == ".xml") {
      if (include_depth_ + 1 >= kMaxXmlIncludeDepth)
        fail(n, what + ": files nested more than " + std::to_string(kMaxXmlIncludeDepth) +
                    " deep (does it include itself?)");
      referenced(n, what, [&] { XmlReader(p, scene_, warn_, include_depth_ + 1, budget_, conventions_).run(); });
    } else if (ext == ".obj") {
      referenced(n, what, [&] { load_obj_scene(p, scene_, warn_, conventions_); });
    } else {
      fail(n, what + ": unknown file type (.xml, .obj)");
    }
    // A file included inside a reference is one more copy.
    if (in_reference_) generate(n, scene_.mesh.triangles.size() - triangles_before);
    // The included file's own coordinates go through this node's transform.
    if (!xfm.is_identity()) {
      for (size_t i = first; i < scene_.mesh.vertices.size(); ++i) scene_.mesh.vertices[i] = xfm.point(scene_.mesh.vertices[i]);
      for (size_t i = first; i < scene_.vertices_t1.size(); ++i) scene_.vertices_t1[i] = xfm.point(scene_.vertices_t1[i]);
      for (size_t i = first; i < scene_.normals.size(); ++i) scene_.normals[i] = xfm.normal(scene_.normals[i]);
      if (scene_.lights.size() != lights_before) warn(n, "lights of included files are not transformed");
    }
  }
  
  TextureConventions conventions_;
  std::filesystem::path path_;
  std::string file_;
  RenderScene& scene_;
  const WarningHandler& warn_;
  int include_depth_;
  SceneBudget& budget_;
  int depth_ = 0;                       // elements and references being read, one inside the other
  int in_reference_ = 0;                // references being expanded, one inside the other
  std::map<size_t, uint64_t> counted_;  // the triangles of each assignment, once counted
  std::string text_;
  std::vector<size_t> line_starts_;
  pugi::xml_document doc_;
  mutable std::optional<std::string> bin_;
  std::map<std::string, uint32_t> materials_;
  std::map<std::string, std::vector<Assigned>> scenes_;  // every assignment of each id, in order
  size_t assignments_ = 0;
  size_t scope_ = SIZE_MAX;  // references see the assignments made before this one

  std::optional<uint32_t> default_material_;
  std::set<std::string> skipped_;
  bool camera_warned_ = false;
};

}  // namespace

void load_xml_scene(const std::filesystem::path& path, RenderScene& scene, const WarningHandler& warn,
                    const TextureConventions& conventions) {
  read_xml_scene_text(read_file(path), path, scene, warn, conventions);
}

void read_xml_scene_text(std::string_view text, const std::filesystem::path& path,
                         RenderScene& scene, const WarningHandler& warn,
                         const TextureConventions& conventions) {
  SceneBudget budget;
  XmlReader(path, scene, warn, 0, budget, conventions).run(std::string(text));
  // An OBJ file included after a moving mesh added vertices without a time-1 position: they
  // stand still.
  if (scene.has_motion() && scene.vertices_t1.size() < scene.mesh.vertices.size())
    scene.vertices_t1.insert(scene.vertices_t1.end(), scene.mesh.vertices.begin() + scene.vertices_t1.size(),
                             scene.mesh.vertices.end());
}

}  // namespace rtk
