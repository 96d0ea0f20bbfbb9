// Compares two 8-bit images channel by channel: exit 0 when they have the same size and no
// channel differs by more than TOLERANCE (in 8-bit steps), 1 otherwise, 2 for an error.
// The viewer's end-to-end test uses it on the window's screenshot and the offline render.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "image/image_io.h"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: compare_screenshot A.png B.png TOLERANCE\n");
    return 2;
  }
  try {
    const rtk::Image a = rtk::read_image(argv[1]);
    const rtk::Image b = rtk::read_image(argv[2]);
    const int tolerance = std::stoi(argv[3]);
    if (a.width != b.width || a.height != b.height) {
      std::printf("sizes differ: %dx%d and %dx%d\n", a.width, a.height, b.width, b.height);
      return 1;
    }
    int worst = 0;
    long long differing = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      const float da[3] = {a.pixels[i].r, a.pixels[i].g, a.pixels[i].b};
      const float db[3] = {b.pixels[i].r, b.pixels[i].g, b.pixels[i].b};
      for (int c = 0; c < 3; ++c) {
        // read_image gives stored 8-bit values / 255: back to whole steps.
        const int d = static_cast<int>(std::lround(std::fabs(da[c] - db[c]) * 255.0f));
        worst = d > worst ? d : worst;
        differing += d != 0;
      }
    }
    std::printf("%dx%d: largest difference %d (tolerance %d), %lld channels differ\n", a.width,
                a.height, worst, tolerance, differing);
    return worst <= tolerance ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare_screenshot: %s\n", e.what());
    return 2;
  }
}
