#include "io/replay_files.h"

#include <bit>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "io/file_error.h"
#include "io/read_file.h"

namespace rtk {

// The records are the structs' memory, so the file's byte order is the machine's. Every target
// of this project is little-endian; a big-endian port would swap here.
static_assert(std::endian::native == std::endian::little, "replay files are little-endian");
static_assert(std::is_trivially_copyable_v<Ray> && sizeof(Ray) == 36);
static_assert(std::is_trivially_copyable_v<Hit> && sizeof(Hit) == 16);

namespace {

constexpr size_t kHeaderBytes = 16;  // 8-byte magic + uint64 count

// The magic as printable text for a message: bytes outside ASCII's printable range as \xNN.
std::string printable(std::string_view bytes) {
  std::string out;
  for (unsigned char c : bytes) {
    if (c >= 0x20 && c < 0x7f) {
      out += char(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
    }
  }
  return out;
}

// "not a .rays file: it begins with 'HITS0001', not 'RAYS0001'"
std::string not_a(std::string_view bytes, std::string_view magic) {
  std::string kind = "." + std::string(magic.substr(0, 4));
  for (char& c : kind) c = char(std::tolower(static_cast<unsigned char>(c)));
  return "not a " + kind + " file: it begins with '" + printable(bytes.substr(0, magic.size())) +
         "', not '" + std::string(magic) + "'";
}

template <class Record>
std::vector<Record> parse_records(std::string_view bytes, std::string_view name, std::string_view magic) {
  const std::string file(name);
  if (bytes.size() < kHeaderBytes) {
    if (bytes.size() >= magic.size() && bytes.substr(0, magic.size()) != magic)
      throw FileError(file, 0, not_a(bytes, magic));
    throw FileError(file, 0, "truncated: " + std::to_string(bytes.size()) +
                                 " bytes, shorter than the 16-byte header");
  }
  if (bytes.substr(0, magic.size()) != magic) throw FileError(file, 0, not_a(bytes, magic));
  uint64_t count = 0;
  std::memcpy(&count, bytes.data() + 8, sizeof count);
  const uint64_t payload = bytes.size() - kHeaderBytes;
  // Compare in a way that cannot overflow: a damaged count may be anything up to 2^64 - 1.
  if (count > payload / sizeof(Record) || count * sizeof(Record) != payload) {
    const bool truncated = count > payload / sizeof(Record);
    throw FileError(file, 0,
                    std::string(truncated ? "truncated" : "count mismatch") + ": the header announces " +
                        std::to_string(count) + " records of " + std::to_string(sizeof(Record)) +
                        " bytes, but " + std::to_string(payload) + " bytes follow it");
  }
  std::vector<Record> records(count);
  if (count) std::memcpy(records.data(), bytes.data() + kHeaderBytes, payload);
  return records;
}

template <class Record>
std::string format_records(std::span<const Record> records, std::string_view magic) {
  std::string out(kHeaderBytes + records.size_bytes(), '\0');
  std::memcpy(out.data(), magic.data(), 8);
  const uint64_t count = records.size();
  std::memcpy(out.data() + 8, &count, sizeof count);
  if (!records.empty()) std::memcpy(out.data() + kHeaderBytes, records.data(), records.size_bytes());
  return out;
}

}  // namespace

std::optional<ReplayFile> replay_file_kind(std::string_view bytes) {
  if (bytes.starts_with(kRaysMagic)) return ReplayFile::rays;
  if (bytes.starts_with(kHitsMagic)) return ReplayFile::hits;
  if (bytes.starts_with(kOcclMagic)) return ReplayFile::occl;
  return std::nullopt;
}

std::vector<Ray> parse_rays(std::string_view bytes, std::string_view name) {
  return parse_records<Ray>(bytes, name, kRaysMagic);
}

std::vector<Hit> parse_hits(std::string_view bytes, std::string_view name) {
  return parse_records<Hit>(bytes, name, kHitsMagic);
}

std::vector<uint8_t> parse_occlusion(std::string_view bytes, std::string_view name) {
  std::vector<uint8_t> occluded = parse_records<uint8_t>(bytes, name, kOcclMagic);
  for (size_t i = 0; i < occluded.size(); ++i)
    if (occluded[i] > 1)
      throw FileError(std::string(name), 0, "record " + std::to_string(i) + " is " +
                                                std::to_string(occluded[i]) + ", not 0 or 1");
  return occluded;
}

std::vector<Ray> read_rays(const std::filesystem::path& path) {
  return parse_rays(read_file(path), path.string());
}
std::vector<Hit> read_hits(const std::filesystem::path& path) {
  return parse_hits(read_file(path), path.string());
}
std::vector<uint8_t> read_occlusion(const std::filesystem::path& path) {
  return parse_occlusion(read_file(path), path.string());
}

std::string format_rays(std::span<const Ray> rays) { return format_records(rays, kRaysMagic); }
std::string format_hits(std::span<const Hit> hits) { return format_records(hits, kHitsMagic); }
std::string format_occlusion(std::span<const uint8_t> occluded) {
  return format_records(occluded, kOcclMagic);
}

void write_rays(const std::filesystem::path& path, std::span<const Ray> rays) {
  write_file(path, format_rays(rays));
}
void write_hits(const std::filesystem::path& path, std::span<const Hit> hits) {
  write_file(path, format_hits(hits));
}
void write_occlusion(const std::filesystem::path& path, std::span<const uint8_t> occluded) {
  write_file(path, format_occlusion(occluded));
}

}  // namespace rtk
