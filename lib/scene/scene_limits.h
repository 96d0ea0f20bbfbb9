/// \file
/// The limits of the scene readers (.ecs scripts, XML, OBJ/MTL), each a clean error that names
/// the file and line where it is crossed. They keep a small hostile file from crashing RTK
/// (nesting that overflows the stack) or from filling the memory (references that double at
/// every level), and each is listed in the README.
#pragma once

#include <cstdint>

namespace rtk {

/// Scripts that include scripts (`-c`): at most this many deep, which also stops a script that
/// includes itself.
inline constexpr int kMaxScriptIncludeDepth = 32;

/// XML files that include XML files (`<xml src>`, `<extern src>`): at most this many deep.
inline constexpr int kMaxXmlIncludeDepth = 16;

/// XML elements nested inside each other, counting every `<ref>` followed as one more level:
/// the reader descends the scene graph recursively, and this bounds its stack.
inline constexpr int kMaxXmlDepth = 256;

/// The most triangles a scene may make rather than read: the copies that `<ref>` expands, the
/// tessellations of `<Sphere>` and `-trisphere`. Checked before each expansion, so that a file
/// of references that double at every level is refused before it has used the memory, and
/// never holds more than this many generated triangles: about 100 bytes each, and as much
/// again in the acceleration structure (a million of them already take tens of seconds to
/// build and render on two cores; 2^22 once ran for minutes from a 2 KB file).
inline constexpr std::uint64_t kMaxGeneratedTriangles = std::uint64_t(1) << 20;

/// The most pixels `-size W H` may ask for: 2^26 (8192 x 8192), about 2 GB of framebuffer and
/// images (each side may be up to 32,768, as chapter 14's renderer allows).
inline constexpr std::uint64_t kMaxRenderPixels = std::uint64_t(1) << 26;

}  // namespace rtk
