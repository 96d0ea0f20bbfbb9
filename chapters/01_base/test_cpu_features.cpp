#include <doctest/doctest.h>

#include <stdexcept>

#include "01_base/cpu_features.h"

using namespace rtk;

TEST_CASE("ch01: ISA names round-trip through the parser") {
  for (Isa isa : kAllIsas) CHECK(parse_isa(isa_name(isa)) == isa);
  CHECK_FALSE(parse_isa("sse2").has_value());
  CHECK_FALSE(parse_isa("").has_value());
}

TEST_CASE("ch01: the supported variants form a chain from scalar to the best") {
  const std::vector<Isa> isas = supported_isas();
  REQUIRE(!isas.empty());
  CHECK(isas.front() == Isa::scalar);
  CHECK(isas.back() == best_isa());
  // Each variant needs everything the one below it needs.
  for (size_t i = 0; i < isas.size(); ++i) CHECK(int(isas[i]) == int(i));
}

TEST_CASE("ch01: a variant's requirements include the OS register state") {
  CpuFeatures f;
  f.sse42 = f.popcnt = f.avx = f.avx2 = f.fma = f.bmi1 = f.bmi2 = f.lzcnt = f.f16c = true;
  f.avx512f = f.avx512cd = f.avx512bw = f.avx512dq = f.avx512vl = true;
  // The CPU has AVX-512, but an OS that does not save the wide registers may not use it.
  f.os_saves_ymm = true;
  f.os_saves_zmm = false;
  CHECK(best_isa(f) == Isa::avx2);
  f.os_saves_ymm = false;
  CHECK(best_isa(f) == Isa::sse4);
  f.sse42 = false;
  CHECK(best_isa(f) == Isa::scalar);
}

TEST_CASE("ch01: -isa forces a variant, and refuses names and variants it cannot honour") {
  CHECK(choose_isa("") == best_isa());
  CHECK(choose_isa("scalar") == Isa::scalar);
  CHECK_THROWS_WITH_AS(choose_isa("neon"), doctest::Contains("-isa"), std::invalid_argument);
  for (Isa isa : kAllIsas) {
    if (isa_supported(isa)) {
      CHECK(choose_isa(isa_name(isa)) == isa);
    } else {
      CHECK_THROWS_WITH_AS(choose_isa(isa_name(isa)), doctest::Contains("cannot run"),
                           std::invalid_argument);
    }
  }
}
