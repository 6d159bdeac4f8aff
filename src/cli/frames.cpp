#include "cli/frames.h"

#include <cstdio>
#include <filesystem>

#include "topocut/core/error.h"
#include "topocut/evaluation/exploration_frame.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/output_files.h"

namespace topocut::cli {

const std::vector<OptionRow<FrameSequenceOptions>>& frame_option_rows() {
  static const std::vector<OptionRow<FrameSequenceOptions>> rows = {
      field_row("frame-every", "N", OptionRange::kCount, &FrameSequenceOptions::every,
                "with --frames: only every N-th update (and the last)")};
  return rows;
}

const std::vector<TextRow<FrameSequenceOptions>>& frame_folder_rows() {
  static const std::vector<TextRow<FrameSequenceOptions>> rows = {
      path_row("frames", "DIR", TextKind::kOutput, &FrameSequenceOptions::folder,
               "write a PNG frame of every update into this folder (created if missing)")};
  return rows;
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


void FrameWriter::update(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms,
                         const std::vector<Point2>& path, const Pose2& pose) {
  if (!folder_.empty() && (update - 1) % every_ == 0) write(update, scan, grid, rooms, path, pose);
}

void FrameWriter::finish(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms,
                         const std::vector<Point2>& path, const Pose2& pose) {
  if (!folder_.empty() && update > 0 && last_written_ != update) write(update, scan, grid, rooms, path, pose);
}

void FrameWriter::write(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms,
                        const std::vector<Point2>& path, const Pose2& pose) {
  FrameOptions options;
  options.range = range_;
  options.caption = "update " + std::to_string(update) + ", scan " + std::to_string(scan) + ", " +
                    std::to_string(rooms.rooms.size()) + " rooms";
  write_frame(folder_, update, render_exploration_frame(grid, rooms, path, pose, options));
  ++written_;
  last_written_ = update;
}

}  // namespace topocut::cli
