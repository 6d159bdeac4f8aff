#include "topocut/core/input_file.h"

#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// Closes the descriptor it owns.
class Descriptor {
 public:
  explicit Descriptor(int fd, bool owned) : fd_(fd), owned_(owned) {}
  ~Descriptor() {
    if (owned_ && fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
  bool owned_;
};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// The open record: file identities (device, inode), under a lock because commands read inputs on
// several threads (evaluate --threads).
std::mutex record_mutex;
bool record_open = false;
std::set<std::pair<dev_t, ino_t>> recorded;

void note(const struct stat& info) {
  const std::lock_guard<std::mutex> lock(record_mutex);
  if (record_open) recorded.emplace(info.st_dev, info.st_ino);
}

// O_NONBLOCK: opening a FIFO without a writer must not wait; the descriptor is checked before reading.
int open_regular(const std::string& path, const std::string& what) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int error = errno;
    if (error == ENOENT) throw FileError(error, path, "cannot read " + what + " " + quoted(path) + ": no such file");
    throw FileError(error, path, "cannot read " + what + " " + quoted(path) + ": " + std::strerror(error));
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    const bool directory = S_ISDIR(info.st_mode);
    ::close(fd);
    const std::string message = "cannot read " + what + " " + quoted(path) + ": ";
    if (directory) throw FileError(EISDIR, path, message + "it is a directory");
    throw Error(message + "not a regular file (a device, FIFO or socket)");
  }
  note(info);
  return fd;
}

std::string too_large(const std::string& what, const std::string& path, std::uint64_t max_bytes) {
  return "cannot read " + what + " " + quoted(path) + ": larger than the limit of " + byte_size_text(max_bytes);
}

}  // namespace

std::string byte_size_text(std::uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int unit = 0;
  while (unit < 4 && bytes >= 1024 && bytes % 1024 == 0) {
    bytes /= 1024;
    ++unit;
  }
  return std::to_string(bytes) + " " + units[unit];
}

void require_regular_file(const std::string& path, const std::string& what) {
  ::close(open_regular(path, what));
}

std::string read_input_file(const std::string& path, const std::string& what, std::uint64_t max_bytes, bool allow_stdin) {
  if (path.empty()) throw Error("no " + what + " given");
  const bool from_stdin = allow_stdin && path == "-";
  const Descriptor fd(from_stdin ? STDIN_FILENO : open_regular(path, what), !from_stdin);
  std::string contents;
  struct stat info {};
  if (!from_stdin && ::fstat(fd.get(), &info) == 0) {
    if (static_cast<std::uint64_t>(info.st_size) > max_bytes) throw Error(too_large(what, path, max_bytes));
    contents.reserve(static_cast<std::size_t>(info.st_size));
  }
  char chunk[1 << 16];
  while (true) {
    const ssize_t got = ::read(fd.get(), chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw Error("cannot read " + what + " " + quoted(path) + ": " + std::strerror(errno));
    if (got == 0) break;
    // Checked while reading too: a file may grow, and standard input has no size in advance.
    if (contents.size() + static_cast<std::size_t>(got) > max_bytes) throw Error(too_large(what, path, max_bytes));
    contents.append(chunk, static_cast<std::size_t>(got));
  }
  return contents;
}

InputRecord::InputRecord() {
  const std::lock_guard<std::mutex> lock(record_mutex);
  if (record_open) throw Error("internal: only one InputRecord may be open at a time");
  record_open = true;
  recorded.clear();
}

InputRecord::~InputRecord() {
  const std::lock_guard<std::mutex> lock(record_mutex);
  record_open = false;
  recorded.clear();
}

bool is_recorded_input(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return false;
  const std::lock_guard<std::mutex> lock(record_mutex);
  return record_open && recorded.count({info.st_dev, info.st_ino}) > 0;
}

}  // namespace topocut
