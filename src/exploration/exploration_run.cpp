#include "topocut/exploration/exploration_run.h"

#include "topocut/core/error.h"

namespace topocut {

ExplorationRun run_exploration(const OccupancyGrid& ground_truth, const ExplorationRunOptions& options) {
  if (options.batch_every < 1) throw Error("batch comparison needs an interval of at least one update");
  Explorer explorer(ground_truth, options.exploration);
  GridReplayOptions replay;
  replay.incremental = options.incremental;
  replay.compare_batch = options.compare_batch;
  replay.batch_every = options.batch_every;
  replay.use_hint = options.use_hint;
  replay.progress_every = 250;
  replay.progress = options.progress;
  if (options.on_update) {
    replay.on_update = [&](const ReplayFrame& frame) {
      options.on_update(ExplorationFrame{frame.update, explorer, frame.grid, frame.segmentation});
    };
  }
  ExplorationRun run;
  static_cast<GridReplay&>(run) = replay_grids(steps_of(explorer), replay);
  run.stop_reason = explorer.stop_reason();
  run.path_length = explorer.path_length();
  run.final_pose = explorer.pose();
  run.window = explorer.window();
  run.known_free_cells = cv::countNonZero(run.final_map.cells == kFree);
  if (!run.path.empty()) run.reachable_free_cells = reachable_free_cells(ground_truth, run.path.front());
  return run;
}

cv::Mat labels_in_frame(const cv::Mat& labels, const cv::Rect& window, const cv::Size& frame) {
  if (labels.type() != CV_32SC1 || labels.size() != window.size() || (window & cv::Rect(cv::Point(0, 0), frame)) != window)
    throw Error("the labels do not fit the given window of the frame");
  cv::Mat out = cv::Mat::zeros(frame, CV_32SC1);
  labels.copyTo(out(window));
  return out;
}

}  // namespace topocut
