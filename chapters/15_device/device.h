/// \file
/// The device API: the renderer behind opaque, reference-counted handles, in the functional
/// style of the Embree 1.1 guide (section 5): create an object of some kind and type, set its
/// parameters, commit it. A commit makes a new immutable version of the object from the
/// parameters set so far; whoever holds the previous version (a scene that was committed with
/// it, a frame being rendered) keeps it unchanged. The parameters of every type are listed in
/// chapter 15's reference.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "01_base/vec3.h"
#include "12_materials/material.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/scene.h"
#include "image/image.h"
#include "image/tonemap.h"
#include "14_pathtracer/accel_kernels.h"

namespace rtk {

// [ch15-kinds]
/// What an object of the device is. The type string given at creation selects the variant
/// within the kind (a "Plastic" material, a "sphere" shape, a "quad" light).
enum class ObjectKind { camera, material, texture, light, shape, scene, renderer, framebuffer };
// [ch15-kinds]

/// The kind's name as messages spell it ("camera", "shape", ...).
const char* kind_name(ObjectKind kind);

class Handle;
namespace device_detail {
struct Object;
const Object& object_of(const Handle& handle);
}  // namespace device_detail

// [ch15-handle]
/// An opaque reference to an object of a Device. Copying a handle retains the object,
/// destroying or reassigning it releases it; the object (its buffered parameters) is freed
/// with its last handle, and each committed version with the last object that uses it (a
/// scene keeps the versions of the shapes it was committed with). A default handle is null.
/// Handles may outlive their device.
class Handle {
 public:
  Handle() = default;
  /// Whether the handle refers to an object.
  explicit operator bool() const { return object_ != nullptr; }
  /// The object's kind; throws std::invalid_argument for a null handle.
  ObjectKind kind() const;
  /// The type the object was created with (e.g. "trianglemesh"); throws for a null handle.
  const std::string& type() const;
  /// How many handles (including parameters of other objects) refer to the object; 0 if null.
  long use_count() const { return object_ ? object_.use_count() : 0; }
  /// Whether two handles refer to the same object.
  bool operator==(const Handle& other) const { return object_ == other.object_; }

 private:
  friend class Device;
  friend const device_detail::Object& device_detail::object_of(const Handle& handle);
  explicit Handle(std::shared_ptr<device_detail::Object> object) : object_(std::move(object)) {}
  std::shared_ptr<device_detail::Object> object_;
};
// [ch15-handle]

/// A parameter value as set() buffers it: scalars, 3-vectors, strings, flat arrays (vertex
/// positions are 3 floats per vertex, triangles 3 ints per triangle), handles and lists of
/// handles.
using DeviceValue = std::variant<int, float, Vec3f, std::string, std::vector<float>,
                                 std::vector<int>, Handle, std::vector<Handle>>;

/// What the device counts, for tests and leak checks.
struct DeviceCounts {
  long objects = 0;   ///< objects alive (they live while a handle refers to them)
  long versions = 0;  ///< committed versions alive (they live while something uses them)
};

// [ch15-device]
/// The device: creates objects, buffers their parameters, commits them and renders frames.
/// Every call may come from any thread; set() and commit() on one object are serialised, and
/// a commit never changes a version another thread is rendering with. Errors throw
/// std::invalid_argument with a message naming the object ("shape #3 'trianglemesh'") and the
/// parameter.
class Device {
 public:
  /// A device whose warnings (an approximated material, an ignored material parameter) go to
  /// `warn`, or nowhere if it is empty, and whose scenes are traced by the kernels `kernels`
  /// builds at each scene commit: RTK's own (make_rtk_kernels) if it is empty. Another factory
  /// runs the same renderer on other kernels (`rtk render -kernels embree`).
  explicit Device(WarningHandler warn = {}, KernelFactory kernels = {});
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  /// Creates an object of `kind`. Throws for a type the kind does not have (see the chapter's
  /// reference); the parameters are checked at commit.
  Handle create(ObjectKind kind, std::string_view type);
  /// The guide's new_X calls: create(ObjectKind::X, type).
  Handle new_camera(std::string_view type) { return create(ObjectKind::camera, type); }
  Handle new_material(std::string_view type) { return create(ObjectKind::material, type); }
  Handle new_texture(std::string_view type) { return create(ObjectKind::texture, type); }
  Handle new_light(std::string_view type) { return create(ObjectKind::light, type); }
  Handle new_shape(std::string_view type) { return create(ObjectKind::shape, type); }
  Handle new_scene(std::string_view type = "default") { return create(ObjectKind::scene, type); }
  Handle new_renderer(std::string_view type) { return create(ObjectKind::renderer, type); }
  Handle new_framebuffer(std::string_view type = "rgb") {
    return create(ObjectKind::framebuffer, type);
  }

  // [ch15-import]
  /// A scene of type "imported" whose geometry, materials and lights are `scene`'s, as the
  /// scene-file readers of lib/scene make it (the guide's loaders, too, hand whole files to
  /// the device): `rtk render` and the viewer go through here. Its camera is not used (frames
  /// take a camera object). Like any scene it renders only once committed, takes the
  /// parameters `accel`, `tri`, `isa` and `threads`, and refuses `shapes` and `lights`.
  Handle import_scene(RenderScene scene);
  // [ch15-import]

  /// Buffers a parameter (replacing an earlier value of the same name). Nothing is checked or
  /// built until commit(); committed versions do not see it.
  void set(const Handle& object, std::string_view name, DeviceValue value);
  /// An int is stored as an int (an exact match, so that a literal 0 is not taken for a null
  /// string).
  void set(const Handle& object, std::string_view name, int value) { set(object, name, DeviceValue(value)); }
  /// A double is stored as a float (so that set(h, "fov", 45.0) reads naturally).
  void set(const Handle& object, std::string_view name, double value) {
    set(object, name, DeviceValue(static_cast<float>(value)));
  }
  /// A string literal is stored as a string.
  void set(const Handle& object, std::string_view name, const char* value) {
    set(object, name, DeviceValue(std::string(value)));
  }
  /// Removes a buffered parameter (its default applies again at the next commit).
  void unset(const Handle& object, std::string_view name);

  /// Makes a new immutable version of the object from its buffered parameters; objects named
  /// by handle parameters contribute their current committed versions. Throws, leaving the
  /// previous version in place, for an unknown or mistyped parameter, a missing required
  /// one, an invalid value, or a handle parameter whose object was never committed.
  void commit(const Handle& object);
  /// Whether the object has a committed version.
  bool committed(const Handle& object) const;

  /// Renders one frame: clears the framebuffer and path traces the scene's committed version
  /// through the camera's with the renderer's options (RenderOptions; width and height are the
  /// framebuffer's). All four objects must be committed. Returns what the frame did and took.
  /// `stop`, when given, is chapter 14's RenderOptions::stop: once it reads true the frame
  /// skips the tiles it has not begun (RenderStats::stopped() then says so).
  RenderStats render_frame(const Handle& renderer, const Handle& camera, const Handle& scene,
                           const Handle& framebuffer, const std::atomic<bool>* stop = nullptr);
  /// Progressive refinement: adds samples first_sample .. first_sample + count - 1 of every
  /// pixel to the framebuffer without clearing it (the renderer's spp is not used). Calls with
  /// consecutive ranges give exactly the image of one call over the whole range.
  RenderStats render_samples(const Handle& renderer, const Handle& camera, const Handle& scene,
                             const Handle& framebuffer, uint32_t first_sample, uint32_t count,
                             const std::atomic<bool>* stop = nullptr);
  /// What the scene's committed version is traced with, e.g. "accel bvh8.objectsplit, tri
  /// triangle8.moeller, isa avx2 (...); build 0.002 s, 0.1 MB".
  std::string kernels_summary(const Handle& scene) const;
  /// The ray kernels of the scene's committed version (for picking a point with a ray); the
  /// pointer keeps that version alive.
  std::shared_ptr<const RayKernels> kernels(const Handle& scene) const;
  /// The framebuffer's current image (linear radiance, one colour per pixel).
  Image read_image(const Handle& framebuffer) const;
  /// Writes the framebuffer's image to `path` (format from the extension, lib/image).
  void write_image(const Handle& framebuffer, const std::string& path, const ToneMap& tone = {}) const;

  /// The objects and versions of this device that are alive.
  DeviceCounts counts() const;

 private:
  RenderStats render(const Handle& renderer, const Handle& camera, const Handle& scene,
                     const Handle& framebuffer,
                     std::optional<std::pair<uint32_t, uint32_t>> samples,
                     const std::atomic<bool>* stop);
  struct State;
  std::shared_ptr<State> state_;
};
// [ch15-device]

}  // namespace rtk
