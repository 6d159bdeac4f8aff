#pragma once
// The frames `explore` and `walls --incremental` both write: one PNG per update (or every N-th),
// the sequence always ending on the finished map.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/core/option_text.h"
#include "topocut/core/segmentation.h"
#include "topocut/scan/scan.h"

namespace topocut::cli {

// Where a run's frames go and how often: the folder (frame_folder_rows()) and the interval
// (frame_option_rows()) are rows, spelt alike in every command that writes frames.
struct FrameSequenceOptions {
  std::string folder;  // empty: no frames
  int every = 1;       // a frame of every every-th update (and the last)
};

// --frame-every, for explore and walls --incremental.
const std::vector<OptionRow<FrameSequenceOptions>>& frame_option_rows();
// --frames DIR, for the same commands.
const std::vector<TextRow<FrameSequenceOptions>>& frame_folder_rows();

// Creates the frames folder (throws Error if it cannot) and checks that a frame can be written
// there without touching an input of the run.
void prepare_frames_folder(const std::string& folder, const std::vector<std::string>& inputs);

// Writes folder/frame_NNNNN.png atomically.
void write_frame(const std::string& folder, int update, const cv::Mat& image);

// Writes the frames of a run into folder (nothing when folder is empty): render_exploration_frame()
// with the laser range drawn (0: none) and the caption "update U, scan S, R rooms".
class FrameWriter {
 public:
  FrameWriter(const FrameSequenceOptions& options, double range) : folder_(options.folder), every_(options.every), range_(range) {}

  // The frame of an update, when it is due: the first and every every-th after it.
  void update(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms, const std::vector<Point2>& path,
              const Pose2& pose);
  // The frame of the run's last update, unless update() wrote it already.
  void finish(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms, const std::vector<Point2>& path,
              const Pose2& pose);
  int written() const { return written_; }

 private:
  void write(int update, int scan, const OccupancyGrid& grid, const Segmentation& rooms, const std::vector<Point2>& path,
             const Pose2& pose);

  std::string folder_;
  int every_ = 1;
  double range_ = 0.0;
  int written_ = 0;
  int last_written_ = 0;
};

}  // namespace topocut::cli
