#include "10_sampling/sampler.h"

#include <stdexcept>
#include <string>

#include "10_sampling/sobol.h"

namespace rtk {

SamplerType parse_sampler_type(std::string_view name) {
  if (name == "independent") return SamplerType::independent;
  if (name == "sobol") return SamplerType::sobol;
  throw std::invalid_argument("unknown sampler '" + std::string(name) +
                              "' (supported: independent, sobol)");
}

void Sampler::start_pixel_sample(int x, int y, uint32_t index) {
  pixel_hash_ = hash_pixel(x, y, seed_);
  index_ = index;
  dimension_ = 0;
  // The independent sampler's stream is a function of the pixel sample alone.
  if (type_ == SamplerType::independent) rng_.seed(hash_combine(pixel_hash_, index), pixel_hash_);
}

uint32_t Sampler::dimension_seed() {
  return static_cast<uint32_t>(hash_combine(pixel_hash_, dimension_++));
}

// [ch10-sampler-2d]
Vec2f Sampler::get_2d() {
  if (type_ == SamplerType::independent) {
    const float u = rng_.next_float();
    return {u, rng_.next_float()};
  }
  // Shuffle the index within its aligned block of 2^m (a nested uniform scramble keeps the
  // block), take that point of the (0,2)-sequence, and scramble both coordinates.
  const uint32_t seed = dimension_seed();
  const uint32_t shuffled = owen_scramble(index_, seed);
  const uint32_t x = owen_scramble(sobol_dim0(shuffled), static_cast<uint32_t>(mix64(seed + 1ull)));
  const uint32_t y = owen_scramble(sobol_dim1(shuffled), static_cast<uint32_t>(mix64(seed + 2ull)));
  return {to_unit_float(x), to_unit_float(y)};
}
// [ch10-sampler-2d]

float Sampler::get_1d() {
  if (type_ == SamplerType::independent) return rng_.next_float();
  const uint32_t seed = dimension_seed();
  const uint32_t shuffled = owen_scramble(index_, seed);
  return to_unit_float(
      owen_scramble(sobol_dim0(shuffled), static_cast<uint32_t>(mix64(seed + 1ull))));
}

}  // namespace rtk
