#include "01_base/cpu_features.h"

#include <cpuid.h>

#include <cstring>
#include <stdexcept>

namespace rtk {

std::string_view isa_name(Isa isa) {
  switch (isa) {
    case Isa::scalar: return "scalar";
    case Isa::sse4: return "sse4";
    case Isa::avx2: return "avx2";
    case Isa::avx512: return "avx512";
  }
  return "unknown";
}

std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa isa : kAllIsas)
    if (isa_name(isa) == name) return isa;
  return std::nullopt;
}

namespace {

struct CpuidRegisters {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
};

CpuidRegisters cpuid(unsigned leaf, unsigned subleaf = 0) {
  CpuidRegisters r;
  __cpuid_count(leaf, subleaf, r.eax, r.ebx, r.ecx, r.edx);
  return r;
}

bool bit(unsigned value, int index) { return (value >> index) & 1u; }

// xgetbv is only legal once cpuid reports OSXSAVE; it tells which register files the operating
// system saves, which is what decides whether AVX instructions may run at all.
uint64_t read_xcr0() {
  unsigned eax = 0, edx = 0;
  __asm__ volatile("xgetbv" : "=a"(eax), "=d"(edx) : "c"(0));
  return (uint64_t(edx) << 32) | eax;
}

CpuFeatures detect() {
  CpuFeatures f;
  const CpuidRegisters leaf0 = cpuid(0);
  char vendor[13] = {};
  std::memcpy(vendor + 0, &leaf0.ebx, 4);
  std::memcpy(vendor + 4, &leaf0.edx, 4);
  std::memcpy(vendor + 8, &leaf0.ecx, 4);
  f.vendor = vendor;

  const CpuidRegisters leaf1 = cpuid(1);
  f.sse42 = bit(leaf1.ecx, 20);
  f.popcnt = bit(leaf1.ecx, 23);
  f.fma = bit(leaf1.ecx, 12);
  f.f16c = bit(leaf1.ecx, 29);
  // [ch01-os-state]
  const bool osxsave = bit(leaf1.ecx, 27);
  f.avx = bit(leaf1.ecx, 28);
  if (osxsave) {
    const uint64_t xcr0 = read_xcr0();
    f.os_saves_ymm = (xcr0 & 0x6) == 0x6;
    f.os_saves_zmm = f.os_saves_ymm && (xcr0 & 0xE0) == 0xE0;
  }
  // [ch01-os-state]
  if (leaf0.eax >= 7) {
    const CpuidRegisters leaf7 = cpuid(7, 0);
    f.bmi1 = bit(leaf7.ebx, 3);
    f.avx2 = bit(leaf7.ebx, 5);
    f.bmi2 = bit(leaf7.ebx, 8);
    f.avx512f = bit(leaf7.ebx, 16);
    f.avx512dq = bit(leaf7.ebx, 17);
    f.avx512cd = bit(leaf7.ebx, 28);
    f.avx512bw = bit(leaf7.ebx, 30);
    f.avx512vl = bit(leaf7.ebx, 31);
  }
  const CpuidRegisters ext0 = cpuid(0x80000000);
  if (ext0.eax >= 0x80000001) f.lzcnt = bit(cpuid(0x80000001).ecx, 5);
  if (ext0.eax >= 0x80000004) {
    char brand[49] = {};
    for (unsigned i = 0; i < 3; ++i) {
      const CpuidRegisters r = cpuid(0x80000002 + i);
      std::memcpy(brand + 16 * i + 0, &r.eax, 4);
      std::memcpy(brand + 16 * i + 4, &r.ebx, 4);
      std::memcpy(brand + 16 * i + 8, &r.ecx, 4);
      std::memcpy(brand + 16 * i + 12, &r.edx, 4);
    }
    f.brand = brand;
    while (!f.brand.empty() && f.brand.back() == ' ') f.brand.pop_back();
    while (!f.brand.empty() && f.brand.front() == ' ') f.brand.erase(0, 1);
  }
  return f;
}

}  // namespace

const CpuFeatures& cpu_features() {
  static const CpuFeatures features = detect();
  return features;
}

bool isa_supported(Isa isa, const CpuFeatures& f) {
  switch (isa) {
    case Isa::scalar: return true;
    case Isa::sse4: return f.sse42 && f.popcnt;
    case Isa::avx2:
      return isa_supported(Isa::sse4, f) && f.avx && f.avx2 && f.fma && f.bmi1 && f.bmi2 &&
             f.lzcnt && f.f16c && f.os_saves_ymm;
    case Isa::avx512:
      return isa_supported(Isa::avx2, f) && f.avx512f && f.avx512cd && f.avx512bw &&
             f.avx512dq && f.avx512vl && f.os_saves_zmm;
  }
  return false;
}

Isa best_isa(const CpuFeatures& f) {
  Isa best = Isa::scalar;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa, f)) best = isa;
  return best;
}

std::vector<Isa> supported_isas(const CpuFeatures& f) {
  std::vector<Isa> result;
  for (Isa isa : kAllIsas)
    if (isa_supported(isa, f)) result.push_back(isa);
  return result;
}

Isa choose_isa(std::string_view requested) {
  if (requested.empty()) return best_isa();
  const std::optional<Isa> isa = parse_isa(requested);
  if (!isa)
    throw std::invalid_argument("-isa: unknown variant '" + std::string(requested) +
                                "' (choose scalar, sse4, avx2 or avx512)");
  if (!isa_supported(*isa))
    throw std::invalid_argument("-isa: this CPU cannot run '" + std::string(requested) +
                                "' (the best it can run is " +
                                std::string(isa_name(best_isa())) + ")");
  return *isa;
}

}  // namespace rtk
