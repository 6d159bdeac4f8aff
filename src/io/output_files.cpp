#include "topocut/io/output_files.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "output_staging.h"
#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {

// A file written by the run but not yet in place. Device targets keep their bytes in memory: they
// are written directly at commit, never renamed over.
struct Staged {
  std::string target;
  std::string temporary;  // empty for a device target
  std::string device_contents;
};

// Shared with the signal handler, which only reads it: every change happens with the handled
// signals blocked, so the handler never sees a vector half-way through a change.
std::vector<Staged> staged;
bool run_open = false;
constexpr int kHandledSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction previous_actions[std::size(kHandledSignals)];

class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int signal : kHandledSignals) sigaddset(&set, signal);
    sigprocmask(SIG_BLOCK, &set, &saved_);
  }
  ~SignalsBlocked() { sigprocmask(SIG_SETMASK, &saved_, nullptr); }
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

 private:
  sigset_t saved_;
};

// Removes the staged files, then dies of the signal as if no handler had been installed.
extern "C" void remove_staged_and_reraise(int signal) {
  for (const Staged& file : staged) {
    if (!file.temporary.empty()) ::unlink(file.temporary.c_str());
  }
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

std::string error_text(int code) { return std::strerror(code); }

// The run's record of its inputs (core/input_file.h), open while the OutputRun is.
std::optional<InputRecord> inputs_of_run;

std::string both_input_and_output(const std::string& output) {
  return "'" + output + "' is both an input and an output of this run; choose another output path";
}

// Every file the run has read so far, under any name, is refused as an output.
void refuse_if_input(const std::string& target) {
  if (is_recorded_input(target)) throw Error(both_input_and_output(target));
}

std::optional<struct stat> stat_of(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  return info;
}

bool is_character_device(const std::string& path) {
  const auto info = stat_of(path);
  return info && S_ISCHR(info->st_mode);
}

// Mode a new output gets: what a plain open() would give (0666 less the umask), or the mode of the
// file it replaces.
mode_t output_mode(const std::string& target) {
  if (const auto info = stat_of(target); info && S_ISREG(info->st_mode)) return info->st_mode & 07777;
  static const mode_t mask = [] {
    const mode_t m = ::umask(022);
    ::umask(m);
    return m;
  }();
  return 0666 & ~mask;
}

void write_all(int fd, const std::string& contents, const std::string& target) {
  std::size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error("cannot write '" + target + "': " + error_text(n < 0 ? errno : ENOSPC));
    done += static_cast<std::size_t>(n);
  }
}

void write_device(const std::string& target, const std::string& contents) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw Error("cannot write '" + target + "': " + error_text(errno));
  try {
    write_all(fd, contents, target);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) throw Error("cannot write '" + target + "': " + error_text(errno));
}

// A new file beside the target with an unpredictable name, created exclusively (O_EXCL never follows
// a symlink planted there), holding contents; returns its path.
std::string write_temporary(const std::string& target, const std::string& contents) {
  const fs::path path(target);
  const fs::path directory = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::string hidden = ".";  // appended, not "." + ...: GCC 12 warns falsely (-Wrestrict) on the latter
  hidden += path.filename().string();
  hidden += ".XXXXXX";
  std::string name = (directory / hidden).string();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) throw Error("cannot write '" + target + "': " + error_text(errno));
  try {
    write_all(fd, contents, target);
    if (::fchmod(fd, output_mode(target)) != 0) throw Error("cannot write '" + target + "': " + error_text(errno));
  } catch (...) {
    ::close(fd);
    ::unlink(name.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const int code = errno;
    ::unlink(name.c_str());
    throw Error("cannot write '" + target + "': " + error_text(code));
  }
  return name;
}

void put_in_place(const Staged& file) {
  if (file.temporary.empty()) {
    write_device(file.target, file.device_contents);
    return;
  }
  if (::rename(file.temporary.c_str(), file.target.c_str()) != 0) {
    const int code = errno;
    ::unlink(file.temporary.c_str());
    throw Error("cannot write '" + file.target + "': " + error_text(code));
  }
}

// Refuses targets that are neither regular files nor character devices (a directory, a FIFO that
// would block, a socket, a block device that must never be replaced).
void check_target_kind(const std::string& target) {
  const auto info = stat_of(target);
  if (!info || S_ISREG(info->st_mode) || S_ISCHR(info->st_mode)) return;
  if (S_ISDIR(info->st_mode)) throw Error("cannot write '" + target + "': it is a directory");
  throw Error("cannot write '" + target + "': it is not a regular file (a FIFO, socket or block device)");
}

void remove_all_staged() {
  SignalsBlocked blocked;
  for (const Staged& file : staged) {
    if (!file.temporary.empty()) ::unlink(file.temporary.c_str());
  }
  staged.clear();
}

}  // namespace

namespace detail {

void write_output(const std::string& path, const std::string& contents) {
  if (path.empty()) throw Error("output path is empty");
  check_target_kind(path);
  refuse_if_input(path);
  Staged file{path, {}, {}};
  if (is_character_device(path)) {
    file.device_contents = contents;
  } else {
    file.temporary = write_temporary(path, contents);
  }
  if (!run_open) {
    put_in_place(file);
    return;
  }
  SignalsBlocked blocked;
  for (Staged& earlier : staged) {
    if (earlier.target != path) continue;
    if (!earlier.temporary.empty()) ::unlink(earlier.temporary.c_str());
    earlier = std::move(file);
    return;
  }
  staged.push_back(std::move(file));
}

}  // namespace detail

namespace {

// What identifies a file whatever its name: device and inode when it exists, else its absolute,
// normalised path.
std::string file_identity(const std::string& path) {
  if (const auto info = stat_of(path)) {
    return "inode:" + std::to_string(info->st_dev) + ":" + std::to_string(info->st_ino);
  }
  std::error_code ignored;
  return "path:" + fs::weakly_canonical(fs::absolute(path), ignored).string();
}

}  // namespace

void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  std::vector<std::pair<std::string, std::string>> seen;  // identity, path
  for (const std::string& output : outputs) {
    if (output.empty()) throw Error("output path is empty");
    check_target_kind(output);
    if (is_character_device(output)) {
      if (::access(output.c_str(), W_OK) != 0) throw Error("cannot write '" + output + "': " + error_text(errno));
      continue;  // several outputs may go to /dev/null alike
    }
    check_writable(output);
    const std::string identity = file_identity(output);
    refuse_if_input(output);
    for (const std::string& input : inputs) {
      if (!input.empty() && file_identity(input) == identity) throw Error(both_input_and_output(output));
    }
    for (const auto& [other_identity, other] : seen) {
      if (other_identity == identity) throw Error("two outputs name the same file: '" + other + "' and '" + output + "'");
    }
    seen.emplace_back(identity, output);
  }
}

OutputRun::OutputRun() {
  if (run_open) throw Error("internal: only one OutputRun may be open at a time");
  SignalsBlocked blocked;
  run_open = true;
  inputs_of_run.emplace();
  struct sigaction action {};
  action.sa_handler = remove_staged_and_reraise;
  sigemptyset(&action.sa_mask);
  for (std::size_t i = 0; i < std::size(kHandledSignals); ++i) {
    ::sigaction(kHandledSignals[i], &action, &previous_actions[i]);
  }
}

OutputRun::~OutputRun() {
  remove_all_staged();
  SignalsBlocked blocked;
  for (std::size_t i = 0; i < std::size(kHandledSignals); ++i) {
    ::sigaction(kHandledSignals[i], &previous_actions[i], nullptr);
  }
  inputs_of_run.reset();
  run_open = false;
}

void OutputRun::commit() {
  // Inputs read after a file was staged (a dataset's images, a later frame's map) are checked here,
  // before anything is put in place.
  for (const Staged& file : staged) {
    if (!file.temporary.empty()) refuse_if_input(file.target);
  }
  SignalsBlocked blocked;
  std::size_t next = 0;
  try {
    for (; next < staged.size(); ++next) put_in_place(staged[next]);
  } catch (...) {
    staged.erase(staged.begin(), staged.begin() + static_cast<std::ptrdiff_t>(next + 1));
    throw;
  }
  staged.clear();
}

}  // namespace topocut
