#include "15_device/device.h"

#include <stdexcept>

#include "15_device/device_objects.h"
#include "image/image_io.h"

namespace rtk {

using device_detail::Counters;
using device_detail::Object;

const char* kind_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::camera: return "camera";
    case ObjectKind::material: return "material";
    case ObjectKind::texture: return "texture";
    case ObjectKind::light: return "light";
    case ObjectKind::shape: return "shape";
    case ObjectKind::scene: return "scene";
    case ObjectKind::renderer: return "renderer";
    case ObjectKind::framebuffer: return "framebuffer";
  }
  return "object";
}

ObjectKind Handle::kind() const { return device_detail::object_of(*this).kind; }
const std::string& Handle::type() const { return device_detail::object_of(*this).type; }

struct Device::State {
  std::shared_ptr<Counters> counters = std::make_shared<Counters>();
  WarningHandler warn;
  KernelFactory kernels;
};

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("rtk device: " + message); }

// Which kinds an object may refer to. Every reference goes down this list (scene > shape and
// light > material > texture), so that handles in parameters can never form a cycle, which
// reference counting could not free.
bool may_refer_to(ObjectKind from, ObjectKind to) {
  switch (from) {
    case ObjectKind::scene: return to == ObjectKind::shape || to == ObjectKind::light;
    case ObjectKind::shape: return to == ObjectKind::material;
    case ObjectKind::material: return to == ObjectKind::texture;
    case ObjectKind::light: return to == ObjectKind::texture;
    default: return false;
  }
}

}  // namespace

Device::Device(WarningHandler warn, KernelFactory kernels) : state_(std::make_shared<State>()) {
  state_->warn = std::move(warn);
  state_->kernels = std::move(kernels);
}
Device::~Device() = default;

Handle Device::create(ObjectKind kind, std::string_view type) {
  if (!device_detail::known_type(kind, type))
    fail(std::string("unknown ") + kind_name(kind) + " type '" + std::string(type) + "' (known: " +
         device_detail::known_types(kind) + ")");
  return Handle(std::make_shared<Object>(state_->counters, kind, std::string(type)));
}

Handle Device::import_scene(RenderScene scene) {
  auto object = std::make_shared<Object>(state_->counters, ObjectKind::scene, "imported");
  object->imported = std::make_shared<const RenderScene>(std::move(scene));
  return Handle(std::move(object));
}

namespace {

// The object of a handle, checked to belong to the device that counts with `counters`.
Object& own(const std::shared_ptr<Counters>& counters, const Handle& h, const char* call) {
  if (!h) fail(std::string(call) + ": null handle");
  const Object& o = device_detail::object_of(h);
  if (o.counters != counters) fail(std::string(call) + ": " + o.describe() + " belongs to another device");
  // Objects are created non-const by create(); handles only hand them out as const.
  return const_cast<Object&>(o);
}

}  // namespace

void Device::set(const Handle& handle, std::string_view name, DeviceValue value) {
  Object& o = own(state_->counters, handle, "set");
  if (name.empty()) fail(o.describe() + ": set: the parameter name is empty");
  auto check = [&](const Handle& target) {
    if (!target) fail(o.describe() + ": parameter '" + std::string(name) + "': null handle");
    const Object& t = device_detail::object_of(target);
    if (t.counters != state_->counters)
      fail(o.describe() + ": parameter '" + std::string(name) + "': " + t.describe() + " belongs to another device");
    if (!may_refer_to(o.kind, t.kind))
      fail(o.describe() + ": parameter '" + std::string(name) + "': a " + kind_name(o.kind) +
           " cannot refer to a " + kind_name(t.kind));
  };
  if (const Handle* h = std::get_if<Handle>(&value)) check(*h);
  if (const auto* list = std::get_if<std::vector<Handle>>(&value))
    for (const Handle& h : *list) check(h);
  std::lock_guard lock(o.mutex);
  o.params.insert_or_assign(std::string(name), std::move(value));
}

void Device::unset(const Handle& handle, std::string_view name) {
  Object& o = own(state_->counters, handle, "unset");
  std::lock_guard lock(o.mutex);
  if (auto it = o.params.find(name); it != o.params.end()) o.params.erase(it);
}

// [ch15-commit]
void Device::commit(const Handle& handle) {
  Object& o = own(state_->counters, handle, "commit");
  // Copy the parameters and build outside the lock: a scene's build may take a while, and
  // set() on the same object (for the next version) should not wait for it.
  device_detail::ParamMap params;
  {
    std::lock_guard lock(o.mutex);
    params = o.params;
  }
  std::shared_ptr<const device_detail::Version> version = device_detail::build_version(o, params, {state_->warn, state_->kernels});
  // Swapping the pointer is the whole commit: whoever copied the old one keeps it.
  std::lock_guard lock(o.mutex);
  o.current = std::move(version);
}
// [ch15-commit]

bool Device::committed(const Handle& handle) const {
  Object& o = own(state_->counters, handle, "committed");
  std::lock_guard lock(o.mutex);
  return o.current != nullptr;
}

namespace {

// The current version of an object of `kind`, for the calls that read versions (`call`).
template <class V>
std::shared_ptr<const V> current_version(const Object& o, ObjectKind kind, const char* call, const char* role) {
  if (o.kind != kind)
    fail(std::string(call) + ": the " + role + " argument is a " + kind_name(o.kind) + " (" + o.describe() + ")");
  std::shared_ptr<const device_detail::Version> v;
  {
    std::lock_guard lock(o.mutex);
    v = o.current;
  }
  if (!v) fail(o.describe() + ": not committed");
  return std::static_pointer_cast<const V>(v);
}

}  // namespace

// [ch15-render-frame]
RenderStats Device::render_frame(const Handle& renderer, const Handle& camera, const Handle& scene,
                                 const Handle& framebuffer, const std::atomic<bool>* stop) {
  return render(renderer, camera, scene, framebuffer, std::nullopt, stop);
}

RenderStats Device::render_samples(const Handle& renderer, const Handle& camera,
                                   const Handle& scene, const Handle& framebuffer,
                                   uint32_t first_sample, uint32_t count,
                                   const std::atomic<bool>* stop) {
  return render(renderer, camera, scene, framebuffer, std::make_pair(first_sample, count), stop);
}

RenderStats Device::render(const Handle& renderer, const Handle& camera, const Handle& scene,
                           const Handle& framebuffer,
                           std::optional<std::pair<uint32_t, uint32_t>> samples,
                           const std::atomic<bool>* stop) {
  using namespace device_detail;
  // Take the four current versions: commits made while the frame renders go to the next one.
  const auto r = current_version<RendererVersion>(own(state_->counters, renderer, "render_frame"), ObjectKind::renderer, "render_frame", "renderer");
  const auto c = current_version<CameraVersion>(own(state_->counters, camera, "render_frame"), ObjectKind::camera, "render_frame", "camera");
  const auto s = current_version<SceneVersion>(own(state_->counters, scene, "render_frame"), ObjectKind::scene, "render_frame", "scene");
  const auto f = current_version<FramebufferVersion>(own(state_->counters, framebuffer, "render_frame"), ObjectKind::framebuffer, "render_frame", "framebuffer");
  // Chapter 14's Renderer reads the camera from the scene, so the frame renders a copy of the
  // committed scene with this camera; the acceleration structure is shared, not rebuilt.
  RenderScene frame_scene = s->scene;
  frame_scene.camera = c->params;
  RenderOptions options = r->options;
  std::lock_guard lock(f->mutex);
  options.width = f->framebuffer.width();
  options.height = f->framebuffer.height();
  options.stop = stop;
  const Renderer frame_renderer(frame_scene, *s->kernels, options);
  if (samples) return frame_renderer.render_pass(f->framebuffer, samples->first, samples->second);
  f->framebuffer.clear();
  return frame_renderer.render(f->framebuffer);
}
// [ch15-render-frame]

std::string Device::kernels_summary(const Handle& scene) const {
  using namespace device_detail;
  return current_version<SceneVersion>(own(state_->counters, scene, "kernels_summary"), ObjectKind::scene, "kernels_summary", "scene")
      ->kernels_summary;
}

std::shared_ptr<const RayKernels> Device::kernels(const Handle& scene) const {
  using namespace device_detail;
  const auto s = current_version<SceneVersion>(own(state_->counters, scene, "kernels"), ObjectKind::scene, "kernels", "scene");
  return std::shared_ptr<const RayKernels>(s, s->kernels.get());  // shares the version's ownership
}

Image Device::read_image(const Handle& framebuffer) const {
  using namespace device_detail;
  const auto f = current_version<FramebufferVersion>(own(state_->counters, framebuffer, "read_image"), ObjectKind::framebuffer, "read_image", "framebuffer");
  std::lock_guard lock(f->mutex);
  return f->framebuffer.resolve();
}

void Device::write_image(const Handle& framebuffer, const std::string& path, const ToneMap& tone) const {
  rtk::write_image(path, read_image(framebuffer), tone);
}

DeviceCounts Device::counts() const {
  return {state_->counters->objects.load(), state_->counters->versions.load()};
}

}  // namespace rtk
