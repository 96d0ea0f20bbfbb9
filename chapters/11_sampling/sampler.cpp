#include "11_sampling/sampler.h"

#include <stdexcept>
#include <string>

namespace rtk {

SamplerType parse_sampler_type(std::string_view name) {
  if (name == "independent") return SamplerType::independent;
  if (name == "sobol") return SamplerType::sobol;
  throw std::invalid_argument("unknown sampler '" + std::string(name) +
                              "' (supported: independent, sobol)");
}

void Sampler::start_pixel_sample(int x, int y, uint32_t index) {
  pixel_hash_ = hash_pixel(x, y, seed_);
  reversed_index_ = reverse_bits(index);
  dimension_ = 0;
  // The independent sampler's stream is a function of the pixel sample alone.
  if (type_ == SamplerType::independent) rng_.seed(hash_combine(pixel_hash_, index), pixel_hash_);
}

}  // namespace rtk
