#pragma once
// What `explore` and `walls --incremental` both print about an incremental run, and their frames.
#include <iosfwd>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/exploration/exploration_run.h"

namespace topocut::cli {

// Per-update incremental times (CPU and wall clock), batch on the same updates when compared, and
// the speed-up of the medians and of the totals.
void print_update_times(std::ostream& out, const std::vector<UpdateRecord>& updates);

// Creates the frames folder (throws Error if it cannot) and checks that a frame can be written
// there without touching an input of the run.
void prepare_frames_folder(const std::string& folder, const std::vector<std::string>& inputs);

// Writes folder/frame_NNNNN.png atomically.
void write_frame(const std::string& folder, int update, const cv::Mat& image);

}  // namespace topocut::cli
