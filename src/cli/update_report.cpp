#include "cli/update_report.h"

#include <cstdio>
#include <filesystem>
#include <ostream>

#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"

namespace topocut::cli {

namespace {

std::string fmt(const char* pattern, double a, double b = 0.0) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

}  // namespace

void print_update_times(std::ostream& out, const std::vector<UpdateRecord>& updates) {
  std::vector<double> inc, inc_wall, batch, paired;
  for (const UpdateRecord& u : updates) {
    inc.push_back(u.incremental_ms);
    inc_wall.push_back(u.incremental_wall_ms);
    if (u.batch_ms >= 0.0) {
      batch.push_back(u.batch_ms);
      paired.push_back(u.incremental_ms);
    }
  }
  const UpdateTimes inc_t = update_times(inc), wall_t = update_times(inc_wall), batch_t = update_times(batch),
                    paired_t = update_times(paired);
  out << "incremental per update: " << fmt("median %.3f ms, p95 %.3f ms, ", inc_t.median, inc_t.p95)
      << fmt("max %.2f ms (total %.1f ms; CPU time)\n", inc_t.max, inc_t.total)
      << "  wall clock:           " << fmt("median %.3f ms, p95 %.3f ms, ", wall_t.median, wall_t.p95)
      << fmt("max %.2f ms\n", wall_t.max);
  if (batch_t.count == 0) return;
  out << "batch per update:       " << fmt("median %.3f ms, p95 %.3f ms, ", batch_t.median, batch_t.p95)
      << fmt("max %.2f ms (", batch_t.max) << batch_t.count << " updates compared)\n";
  if (paired_t.median > 0.0 && paired_t.total > 0.0)
    out << "speed-up on the same updates: "
        << fmt("%.1fx (medians), %.1fx (totals)\n", batch_t.median / paired_t.median, batch_t.total / paired_t.total);
}

void prepare_frames_folder(const std::string& folder, const std::vector<std::string>& inputs) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder)) throw Error("cannot create the frames folder " + folder);
  check_outputs({(std::filesystem::path(folder) / "frame_00001.png").string()}, inputs);
}

void write_frame(const std::string& folder, int update, const cv::Mat& image) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", update);
  write_image_atomically((std::filesystem::path(folder) / name).string(), image);
}

}  // namespace topocut::cli
