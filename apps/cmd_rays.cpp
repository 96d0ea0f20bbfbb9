// `rtk rays`: writes a .rays file for a scene (lib/replay/ray_generator.h says what each kind
// of ray is and where the camera and the light stand).
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "01_base/timer.h"
#include "commands.h"
#include "io/obj_loader.h"
#include "io/read_file.h"
#include "io/replay_files.h"
#include "json_line.h"
#include "options.h"
#include "output_checks.h"
#include "replay/ray_generator.h"

namespace rtk::cli {

int run_rays(std::span<const std::string_view> args) {
  const Options options("rays", args, {.with_value = {"i", "kind", "n", "seed", "o"}, .flags = {}});
  const std::string scene = options.required("i");
  const std::string kind_name = options.required("kind");
  const std::optional<RayKind> kind = parse_ray_kind(kind_name);
  if (!kind)
    throw options.error("option -kind: unknown kind '" + kind_name +
                        "' (expected primary, diffuse, shadow or random)");
  options.required("n");
  // No more rays than a .rays file that read_file can read back (kMaxFileBytes, 4 GiB).
  const uint64_t count = options.get_count("n", 0, 1, (kMaxFileBytes - 16) / sizeof(Ray));
  const uint64_t seed = options.get_count("seed", 1, 0, std::numeric_limits<uint64_t>::max());
  const std::string output = options.required("o");
  check_output_option("o", output);
  check_not_an_input("o", output, "the input of -i", scene);

  const TriangleMesh mesh = load_obj(scene);
  Timer timer;
  std::vector<Ray> rays;
  try {
    rays = generate_rays(mesh, *kind, count, seed);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(scene + ": " + e.what());
  }
  const double seconds = timer.seconds();
  write_rays(output, rays);
  JsonLine()
      .add("op", "rays")
      .add("kind", kind_name)
      .add("rays", rays.size())
      .add("seed", seed)
      .add("scene", scene)
      .add("triangles", mesh.size())
      .add("output", output)
      .add("seconds", seconds)
      .print();
  return 0;
}

}  // namespace rtk::cli
