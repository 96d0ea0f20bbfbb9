/// \file
/// What the CPU can do, and which variant of the kernels therefore runs.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtk {

/// The instruction-set variants every kernel is compiled for, from least to most capable.
/// Each one is also the name of the namespace its kernels live in (`rtk::avx2`, ...).
enum class Isa { scalar = 0, sse4 = 1, avx2 = 2, avx512 = 3 };

/// All variants, in increasing order of capability.
inline constexpr Isa kAllIsas[] = {Isa::scalar, Isa::sse4, Isa::avx2, Isa::avx512};

/// The name used on the command line and in the namespaces: "scalar", "sse4", "avx2", "avx512".
std::string_view isa_name(Isa isa);

/// Parses an ISA name; std::nullopt for a name that is not one of isa_name()'s.
std::optional<Isa> parse_isa(std::string_view name);

/// The CPU features RTK cares about, as reported by cpuid and, for the register state the
/// operating system saves on a context switch, by xgetbv.
struct CpuFeatures {
  std::string vendor;  ///< "GenuineIntel", "AuthenticAMD", ...
  std::string brand;   ///< the processor's brand string
  bool sse42 = false, popcnt = false;
  bool avx = false, avx2 = false, fma = false, bmi1 = false, bmi2 = false, lzcnt = false,
       f16c = false;
  bool avx512f = false, avx512cd = false, avx512bw = false, avx512dq = false,
       avx512vl = false;
  bool os_saves_ymm = false;  ///< XCR0 bits 1-2: the OS preserves AVX registers
  bool os_saves_zmm = false;  ///< XCR0 bits 5-7: the OS preserves AVX-512 registers
};

/// Reads the features of the CPU this process runs on (once; later calls return a copy).
const CpuFeatures& cpu_features();

/// Whether the CPU and operating system can run the given variant.
bool isa_supported(Isa isa, const CpuFeatures& features = cpu_features());

/// The most capable variant the machine can run.
Isa best_isa(const CpuFeatures& features = cpu_features());

/// Every variant the machine can run, scalar first.
std::vector<Isa> supported_isas(const CpuFeatures& features = cpu_features());

/// The variant to use given an optional `-isa NAME` request: the best one when the request is
/// empty. Throws std::invalid_argument naming the option for an unknown name, or for a variant
/// the CPU cannot run.
Isa choose_isa(std::string_view requested);

}  // namespace rtk
