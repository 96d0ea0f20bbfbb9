#include "io/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

#include "io/file_error.h"

namespace rtk {

namespace {

// A file descriptor closed when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  /// Closes now and reports whether the close succeeded (it may report a delayed write error).
  bool close() {
    const int fd = fd_;
    fd_ = -1;
    return ::close(fd) == 0;
  }

 private:
  int fd_;
};

std::string reason() { return std::strerror(errno); }

std::string bytes_text(std::uint64_t n) { return std::to_string(n) + " bytes"; }

// What a file of this type is, for a refusal; empty for the types that can be read.
const char* unreadable_kind(mode_t mode) {
  if (S_ISREG(mode) || S_ISFIFO(mode)) return "";
  if (S_ISDIR(mode)) return "is a folder, not a file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a file (it may never end)";
  return "is not a regular file or a pipe";
}

// Writes all of `bytes` to `fd`, retrying after interruptions and short writes.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

}  // namespace

// [io-read-file]
std::string read_file(const std::filesystem::path& path, std::uint64_t max_bytes) {
  const std::string name = path.string();
  Descriptor file(::open(name.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.get() < 0) throw FileError(name, 0, "cannot open: " + reason());
  // The type and size of what was opened, not of what the name meant a moment before.
  struct stat info {};
  if (::fstat(file.get(), &info) != 0) throw FileError(name, 0, "cannot read: " + reason());
  if (const char* kind = unreadable_kind(info.st_mode); *kind) throw FileError(name, 0, kind);
  const bool regular = S_ISREG(info.st_mode);
  auto too_large = [&](const std::string& size) {
    return FileError(
        name, 0, size + ", more than the " + bytes_text(max_bytes) + " this kind of file may have");
  };
  if (regular && static_cast<std::uint64_t>(info.st_size) > max_bytes)
    throw too_large(bytes_text(static_cast<std::uint64_t>(info.st_size)));
  // Read in blocks up to the limit: a pipe has no size, and a file may grow while it is read.
  std::string bytes;
  if (regular) bytes.reserve(static_cast<size_t>(info.st_size));
  char block[1 << 16];
  for (;;) {
    const ssize_t n = ::read(file.get(), block, sizeof block);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(name, 0, "read error: " + reason());
    if (n == 0) break;
    if (bytes.size() + static_cast<std::uint64_t>(n) > max_bytes)
      throw too_large("more than " + bytes_text(max_bytes));
    bytes.append(block, static_cast<size_t>(n));
  }
  return bytes;
}
// [io-read-file]

// [io-write-file]
void write_file(const std::filesystem::path& target, std::string_view bytes) {
  const std::string name = target.string();
  // A symbolic link keeps pointing where it did: the file it names is replaced.
  std::error_code ec;
  const std::filesystem::path path = std::filesystem::is_symlink(target, ec)
                                         ? std::filesystem::weakly_canonical(target, ec)
                                         : target;
  // A device or a pipe cannot be replaced by a rename: it is written in place.
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) {
    if (S_ISDIR(info.st_mode)) throw FileError(name, 0, "cannot write: it is a folder");
    Descriptor file(::open(path.c_str(), O_WRONLY | O_CLOEXEC));
    if (file.get() < 0) throw FileError(name, 0, "cannot open for writing: " + reason());
    if (!write_all(file.get(), bytes) || !file.close())
      throw FileError(name, 0, "write error: " + reason());
    return;
  }
  // A temporary name in the same folder (a rename never crosses file systems), unique to this
  // process and call; the file is created with the permissions a new file would get.
  static std::atomic<unsigned> counter{0};
  std::string hidden = ".";
  hidden += path.filename().string();
  hidden += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  std::filesystem::path temp = path;
  temp.replace_filename(hidden);
  const std::string temp_name = temp.string();
  Descriptor file(::open(temp_name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
  if (file.get() < 0) throw FileError(name, 0, "cannot create: " + reason());
  auto fail = [&](const std::string& what) {
    const std::string message = what + reason();
    ::unlink(temp_name.c_str());
    return FileError(name, 0, message);
  };
  if (!write_all(file.get(), bytes)) throw fail("write error: ");
  // close() may report what write() could not (a full disk on a network file system).
  if (!file.close()) throw fail("write error: ");
  if (::rename(temp_name.c_str(), path.c_str()) != 0) throw fail("cannot replace the file: ");
}
// [io-write-file]

void check_output_path(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (name.empty()) throw FileError("(empty name)", 0, "an output file needs a name");
  struct stat info {};
  const bool exists = ::stat(name.c_str(), &info) == 0;
  if (exists && S_ISDIR(info.st_mode)) throw FileError(name, 0, "cannot write: it is a folder");
  if (exists && ::access(name.c_str(), W_OK) != 0)
    throw FileError(name, 0, "cannot write: " + reason());
  if (exists && !S_ISREG(info.st_mode)) return;
  // A regular file is written beside its target and renamed: the folder must take new files.
  std::error_code ec;
  std::filesystem::path folder =
      (std::filesystem::is_symlink(path, ec) ? std::filesystem::weakly_canonical(path, ec) : path)
          .parent_path();
  if (folder.empty()) folder = ".";
  struct stat dir {};
  if (::stat(folder.c_str(), &dir) != 0)
    throw FileError(name, 0,
                    "cannot write: the folder '" + folder.string() + "' " +
                        (errno == ENOENT ? std::string("does not exist") : reason()));
  if (!S_ISDIR(dir.st_mode))
    throw FileError(name, 0, "cannot write: '" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw FileError(name, 0, "cannot write into the folder '" + folder.string() + "': " + reason());
}

}  // namespace rtk
