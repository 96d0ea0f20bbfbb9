/// \file
/// Samplers: where the renderer's random numbers come from. Both kinds are pure functions of
/// (pixel, sample index, dimension, seed), so the image is the same for any thread count and
/// any tile order.
#pragma once

#include <cstdint>
#include <string_view>

#include "11_sampling/rng.h"
#include "11_sampling/sobol.h"
#include "11_sampling/vec2.h"

namespace rtk {

/// The two sample generators of chapter 11.
enum class SamplerType {
  independent,  ///< uniform random numbers (PCG32 seeded by the hash of pixel and sample)
  sobol,        ///< Owen-scrambled (0,2)-sequence, one independently scrambled pair per dimension
};

/// Parses "independent" or "sobol"; throws std::invalid_argument naming both otherwise.
SamplerType parse_sampler_type(std::string_view name);

/// A sample generator for one thread. Copy it into each thread; call start_pixel_sample before
/// each camera path, then take numbers in a fixed order (get_pixel_2d, then get_1d/get_2d).
/// The n-th call after start_pixel_sample gets the n-th dimension, whatever happened before.
///
/// The Sobol variant gives each dimension (a 1D number or a 2D pair) its own shuffled and
/// Owen-scrambled copy of the (0,2)-sequence ("padding", Kollig and Keller 2002; the shuffle
/// is Burley 2020's nested uniform scramble of the index). For 2^m samples in a pixel each
/// pair is then a (0,m,2)-net: every elementary interval of area 2^-m holds one point. A
/// dimension costs one 64-bit hash for its seeds, three LK hashes and a few table loads
/// (sobol_owen), the same for every dimension index.
class Sampler {
 public:
  /// A sampler of the given type; the seed selects a different, equally good image.
  explicit Sampler(SamplerType type = SamplerType::sobol, uint32_t seed = 0)
      : type_(type), seed_(seed) {}

  /// Starts sample `index` of pixel (x, y): resets the dimension counter.
  void start_pixel_sample(int x, int y, uint32_t index);

  /// The next 1D number in [0, 1).
  float get_1d() {
    if (type_ == SamplerType::independent) return rng_.next_float();
    return to_unit_float(sobol_owen_1d(reversed_index_, next_seeds()));
  }
  /// The next 2D point in [0, 1)^2.
  Vec2f get_2d() {
    if (type_ == SamplerType::independent) {
      const float u = rng_.next_float();
      return {u, rng_.next_float()};
    }
    const std::array<uint32_t, 2> p = sobol_owen(reversed_index_, next_seeds());
    return {to_unit_float(p[0]), to_unit_float(p[1])};
  }
  /// Steps past the next 1D number without computing it: what follows is what get_1d()
  /// would have left. A renderer that knows it will not use a number (a pinhole camera's lens
  /// position, a point light's sample) skips it, so that dimension d still means the same
  /// thing in every path, at the cost of a counter rather than of the hashes.
  void skip_1d() {
    if (type_ == SamplerType::independent)
      rng_.skip();
    else
      ++dimension_;
  }
  /// Steps past the next 2D point without computing it (see skip_1d).
  void skip_2d() {
    if (type_ == SamplerType::independent) {
      rng_.skip();
      rng_.skip();
    } else {
      ++dimension_;
    }
  }

  /// The film position within the pixel: by convention the first 2D point of a pixel sample.
  Vec2f get_pixel_2d() { return get_2d(); }

  /// The type this sampler was made with.
  SamplerType type() const { return type_; }

  /// The scramble seeds of the next Sobol dimension (and counts it): sobol_owen_reference with
  /// these seeds and the sample index is what get_2d returns, as 32-bit fractions.
  SobolSeeds next_seeds() {
    // [ch11-seeds]
    // One splitmix64 step from the pixel's hash: the pixel's dimensions are a Weyl sequence
    // through a mixer, so dimension d costs the same for every d. Its two halves and a
    // multiply of it are the three seeds.
    const uint64_t h = mix64(pixel_hash_ + ++dimension_ * 0x9e3779b97f4a7c15ull);
    return {static_cast<uint32_t>(h), static_cast<uint32_t>(h >> 32),
            static_cast<uint32_t>((h * 0xd1b54a32d192ed03ull) >> 32)};
    // [ch11-seeds]
  }

 private:
  SamplerType type_;
  uint32_t seed_;
  uint64_t pixel_hash_ = 0;
  uint32_t reversed_index_ = 0;  // the sample index, bit-reversed once for all dimensions
  uint32_t dimension_ = 0;
  Pcg32 rng_;
};

}  // namespace rtk
