/// \file
/// The device's insides: the object behind a handle (its buffered parameters and its current
/// committed version), the committed versions of each kind, and the parameter reader that
/// turns a buffered map into checked values with messages naming object and parameter.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "11_sampling/camera.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/scene.h"
#include "15_device/device.h"
#include "image/framebuffer.h"
#include "14_pathtracer/accel_kernels.h"

namespace rtk::device_detail {

/// What the device counts; shared by the device and everything it made, so that handles and
/// versions may outlive the device.
struct Counters {
  std::atomic<long> objects{0};
  std::atomic<long> versions{0};
  std::atomic<long> next_id{1};
};

/// A committed version: immutable once made (except a framebuffer's pixels).
struct Version {
  explicit Version(std::shared_ptr<Counters> c) : counters(std::move(c)) { ++counters->versions; }
  virtual ~Version() { --counters->versions; }
  Version(const Version&) = delete;
  Version& operator=(const Version&) = delete;
  std::shared_ptr<Counters> counters;
};

/// The parameters as buffered by set(), by name.
using ParamMap = std::map<std::string, DeviceValue, std::less<>>;

/// The object behind a handle.
struct Object {
  Object(std::shared_ptr<Counters> c, ObjectKind k, std::string t)
      : counters(std::move(c)), kind(k), type(std::move(t)), id(counters->next_id++) {
    ++counters->objects;
  }
  ~Object() { --counters->objects; }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;

  /// "shape #3 'trianglemesh'", for messages.
  std::string describe() const { return std::string(kind_name(kind)) + " #" + std::to_string(id) + " '" + type + "'"; }

  std::shared_ptr<Counters> counters;
  const ObjectKind kind;
  const std::string type;
  const long id;
  mutable std::mutex mutex;                // guards params and current
  ParamMap params;                         // what set() buffered
  std::shared_ptr<const Version> current;  // the last committed version, or null
  std::shared_ptr<const RenderScene> imported;  // an "imported" scene's content (import_scene)
};

struct CameraVersion final : Version {
  using Version::Version;
  CameraParams params;
};

struct TextureVersion final : Version {
  using Version::Version;
  std::shared_ptr<const Texture> texture;
};

struct MaterialVersion final : Version {
  using Version::Version;
  Material material;
};

/// A light: either one without geometry (`light`) or the emitting triangles of an area light
/// (which a scene adds to its mesh with an emitting material).
struct LightVersion final : Version {
  using Version::Version;
  std::shared_ptr<const Light> light;
  std::vector<std::shared_ptr<const TriangleLight>> triangles;
  Color radiance;
};

/// A shape's triangles with their attributes, in the shape's own vertex numbering.
struct ShapeVersion final : Version {
  using Version::Version;
  std::vector<Vec3f> vertices;
  std::vector<Vec3f> vertices_t1;  // empty if the shape stands still
  std::vector<Vec3f> normals;      // empty or one per vertex
  std::vector<Vec2f> uvs;          // empty or one per vertex
  std::vector<std::array<uint32_t, 3>> triangles;
  std::shared_ptr<const MaterialVersion> material;  // null: the default grey Matte
};

/// A scene ready to render: the merged RenderScene, its acceleration structure, and the
/// versions it was made from (kept alive with it).
struct SceneVersion final : Version {
  using Version::Version;
  RenderScene scene;
  std::unique_ptr<const RayKernels> kernels;
  std::string kernels_summary;
  std::vector<std::shared_ptr<const Version>> parts;
};

struct RendererVersion final : Version {
  using Version::Version;
  RenderOptions options;
};

/// The one kind whose version changes after commit: render_frame writes its pixels.
struct FramebufferVersion final : Version {
  FramebufferVersion(std::shared_ptr<Counters> c, int w, int h) : Version(std::move(c)), framebuffer(w, h) {}
  mutable std::mutex mutex;  // one frame at a time
  mutable Framebuffer framebuffer;
};

/// Reads the buffered parameters of one commit: typed getters that throw naming the object
/// and parameter, and a final check that every parameter was understood.
class ParamReader {
 public:
  ParamReader(const Object& object, const ParamMap& params) : object_(object), params_(params) {}

  /// Throws std::invalid_argument "rtk device: OBJECT: parameter 'NAME': MESSAGE".
  [[noreturn]] void fail(std::string_view name, const std::string& message) const;
  /// Throws std::invalid_argument "rtk device: OBJECT: MESSAGE".
  [[noreturn]] void fail(const std::string& message) const;

  bool has(std::string_view name) const { return params_.find(name) != params_.end(); }
  float get_float(std::string_view name, float fallback) const;       // int or float
  float require_float(std::string_view name) const;
  int get_int(std::string_view name, int fallback) const;
  Vec3f get_vec3(std::string_view name, Vec3f fallback) const;        // vec3, or a scalar for all three
  Vec3f require_vec3(std::string_view name) const;
  std::string get_string(std::string_view name, std::string fallback) const;
  /// A float array (empty if absent); its length must be a multiple of `group`.
  std::vector<float> get_floats(std::string_view name, size_t group) const;
  /// An int array (empty if absent); its length must be a multiple of `group`.
  std::vector<int> get_ints(std::string_view name, size_t group) const;
  /// The committed version of a handle parameter of kind `kind` (null if absent).
  std::shared_ptr<const Version> get_version(std::string_view name, ObjectKind kind) const;
  /// The committed versions of a list of handles (a single handle is a list of one).
  std::vector<std::shared_ptr<const Version>> get_versions(std::string_view name, ObjectKind kind) const;
  /// Material parameters: every parameter not read so far, converted to chapter 12's list.
  ParameterList remaining_as_material_parameters() const;
  /// Throws for the first parameter no getter asked for.
  void finish() const;

 private:
  const DeviceValue* find(std::string_view name) const;
  std::shared_ptr<const Version> version_of(std::string_view name, const Handle& h, ObjectKind kind) const;
  const Object& object_;
  const ParamMap& params_;
  mutable std::set<std::string, std::less<>> used_;
};

/// The object a handle refers to (so that the commit code can read it); throws for null.
const Object& object_of(const Handle& handle);

/// What a commit needs from its device besides the object: where warnings go, and how a
/// scene's kernels are built.
struct CommitContext {
  const WarningHandler& warn;
  const KernelFactory& kernels;
};

/// Makes a new committed version of `object` from `params` (commit_objects.cpp).
std::shared_ptr<const Version> build_version(const Object& object, const ParamMap& params,
                                             const CommitContext& context);

/// Whether an object of `kind` may be created with `type`.
bool known_type(ObjectKind kind, std::string_view type);
/// The types of a kind, for messages ("pinhole, thinlens").
std::string known_types(ObjectKind kind);

}  // namespace rtk::device_detail
