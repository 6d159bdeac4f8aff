#pragma once
// Reading inputs within bounds: only regular files (or "-", standard input, where a command takes
// it), never more bytes than a limit, so that a FIFO, a device such as /dev/zero or a huge file ends
// in one clear error instead of a hang or exhausted memory.
#include <cstdint>
#include <string>

namespace topocut {

// Byte limits of the text inputs (docs/limits.md): far above any real file of the kind, far below
// what would exhaust memory once parsed.
inline constexpr std::uint64_t kMaxMapYamlBytes = 1ull << 20;       // ROS map_server YAML: 1 MiB
inline constexpr std::uint64_t kMaxPolygonJsonBytes = 4ull << 20;   // decompose's polygon JSON: 4 MiB
inline constexpr std::uint64_t kMaxScanCsvBytes = 64ull << 20;      // one scan as CSV: 64 MiB (4 million beams)
inline constexpr std::uint64_t kMaxConfigYamlBytes = 1ull << 20;    // --config FILE.yaml: 1 MiB
inline constexpr std::uint64_t kMaxMergeModelBytes = 4ull << 20;    // --merge-model FILE: 4 MiB (the shipped one is ~0.5 MiB)

// Throws Error naming `what` and path unless path is an existing regular file (symlinks followed).
// Opening never blocks (a FIFO is refused, not waited on).
void require_regular_file(const std::string& path, const std::string& what);

// The whole content of the regular file path ("-": standard input, if allow_stdin). Throws Error
// naming `what`, path and the limit if it is not a regular file, holds more than max_bytes, or cannot
// be read.
std::string read_input_file(const std::string& path, const std::string& what, std::uint64_t max_bytes,
                            bool allow_stdin = false);

// "N bytes" as the largest whole unit (KiB, MiB, GiB) for messages about limits.
std::string byte_size_text(std::uint64_t bytes);

// The inputs of one run: while a record is open, every regular file that read_input_file() or
// require_regular_file() opens is noted by its identity (device and inode, whatever the name it was
// reached by), so that the run's outputs can be checked against all of them (io/output_files.h
// does, at its check, at each write and at the final commit). One record per process; thread-safe.
class InputRecord {
 public:
  InputRecord();
  ~InputRecord();
  InputRecord(const InputRecord&) = delete;
  InputRecord& operator=(const InputRecord&) = delete;
};

// Whether the existing file at path is one the open record noted (false without a record).
bool is_recorded_input(const std::string& path);

}  // namespace topocut
