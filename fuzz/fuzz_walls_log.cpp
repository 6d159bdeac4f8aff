// libFuzzer target: a CARMEN log file through read_carmen_log (plain or gzip, inflated as a stream)
// and the walls pipeline. The first byte chooses how the rest reaches the file: as it is (plain text,
// or a gzip stream from the corpus, possibly corrupt) or gzip-compressed here, so that the fuzzer
// explores log contents behind the gzip path too. Any input must give walls and a grid or a
// topocut::Error, within the reader's bounds.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include <zlib.h>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/io/carmen_log.h"
#include "topocut/walls/posed_scan.h"
#include "topocut/walls/walls_pipeline.h"

namespace {

std::string temporary_path() {
  static const std::string path = "/tmp/fuzz_walls_log." + std::to_string(static_cast<long>(::getpid())) + ".log";
  return path;
}

void write(const std::string& path, const std::uint8_t* data, std::size_t size, bool compress) {
  if (compress) {
    gzFile file = gzopen(path.c_str(), "wb1");
    if (size > 0) gzwrite(file, data, static_cast<unsigned>(size));
    gzclose(file);
    return;
  }
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (size > 0) std::fwrite(data, 1, size, file);
  std::fclose(file);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  if (size == 0) return 0;
  const std::string path = temporary_path();
  write(path, data + 1, size - 1, (data[0] & 1) != 0);
  CarmenReadOptions read;
  read.max_total_beams = 200000;  // keeps one run within the fuzzer's time and memory limits
  WallsOptions options;
  options.map.max_cells = 4'000'000;
  try {
    const CarmenLog log = read_carmen_log(path, read);
    for (const CarmenLaserScan& scan : log.scans)
      if (scan.ranges.size() < 2) fuzz::fail("accepted a scan with fewer than two beams");
    if (log.scans.empty()) return 0;
    const WallsResult result = walls_from_scans(posed_scans(log), options);
    if (result.grid.cells.empty()) fuzz::fail("walls_from_scans returned an empty grid");
  } catch (const Error&) {
  }
  return 0;
}
