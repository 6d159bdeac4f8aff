// The incremental segmenter on the shared datasets (../shared/datasets; skipped with a message when
// absent): every map given at once gets segment()'s rooms cell for cell (without the leave-out rows
// until it is at rest, with them once it is), and a real map revealed in
// growing windows with a moving origin (windowed updates among them) ends, segmented again as a
// whole at rest, on segment()'s rooms of the final map. The join of io (reading the maps) with segmentation.
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmentation_rules.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

const std::string kDatasets = std::string(TOPOCUT_SHARED_DIR "/datasets");

// The maps of a dataset folder: images and ROS YAMLs, without ground truths and without the images
// a YAML names.
std::vector<std::string> maps_in(const std::string& folder) {
  std::vector<std::string> out;
  if (!fs::is_directory(folder)) return out;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string path = entry.path().string(), ext = entry.path().extension().string();
    if (path.find("_gt_segmentation") != std::string::npos) continue;
    if (ext == ".yaml" || ((ext == ".png" || ext == ".pgm") && !fs::exists(entry.path().parent_path() /
                                                                           (entry.path().stem().string() + ".yaml"))))
      out.push_back(path);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Whether a and b are one partition of the same cells (labels equal under a renaming).
bool same_partition(const cv::Mat& a, const cv::Mat& b) {
  std::map<int, int> forward, backward;
  for (int r = 0; r < a.rows; ++r) {
    const int* pa = a.ptr<int>(r);
    const int* pb = b.ptr<int>(r);
    for (int c = 0; c < a.cols; ++c) {
      if ((pa[c] == 0) != (pb[c] == 0)) return false;
      if (pa[c] == 0) continue;
      if (forward.emplace(pa[c], pb[c]).first->second != pb[c] || backward.emplace(pb[c], pa[c]).first->second != pa[c])
        return false;
    }
  }
  return true;
}

TEST(IncrementalDatasets, EveryMapGivenAtOnceGetsBatchRoomsCellForCell) {
  std::vector<std::string> maps;
  for (const char* set : {"bormann", "real_maps", "real_maps_gt"}) {
    const std::vector<std::string> found = maps_in(kDatasets + "/" + set);
    maps.insert(maps.end(), found.begin(), found.end());
  }
  if (maps.empty()) GTEST_SKIP() << "no datasets under " << kDatasets << " (see its README)";
  for (const std::string& path : maps) {
    SCOPED_TRACE(path);
    const OccupancyGrid grid = load_map(path);
    IncrementalSegmenter segmenter;
    // While the map may grow, a whole-map update leaves out nothing (a windowed update would give it a
    // room back); at rest, batch's rooms, fans left out.
    const Segmentation& s = segmenter.update(grid);
    const Segmentation growing = segment(grid, without_leave_out(SegmentOptions{}));
    EXPECT_EQ(cv::countNonZero(s.labels != growing.labels), 0);
    EXPECT_EQ(s.rooms.size(), growing.rooms.size());
    EXPECT_EQ(s.passages.size(), growing.passages.size());
    const Segmentation& rest = segmenter.resegment();
    const Segmentation batch = segment(grid);
    EXPECT_TRUE(same_partition(rest.labels, batch.labels));  // the ids carried from the update
    EXPECT_EQ(cv::countNonZero((rest.labels == 0) != (batch.labels == 0)), 0);
    EXPECT_EQ(rest.rooms.size(), batch.rooms.size());
    EXPECT_EQ(rest.passages.size(), batch.passages.size());
  }
}

TEST(IncrementalDatasets, RealMapsRevealedInGrowingWindowsEndOnBatchRooms) {
  const std::vector<std::string> maps = maps_in(kDatasets + "/real_maps_gt");
  if (maps.empty()) GTEST_SKIP() << "no real_maps_gt under " << kDatasets << " (see its README)";
  for (const std::string& path : maps) {
    SCOPED_TRACE(path);
    const OccupancyGrid world = load_map(path);
    IncrementalSegmenter segmenter;
    OccupancyGrid grid;
    // Eight windows: the first ones more than double the free space (whole-map updates), the last
    // ones add less than half of it, so the windowed path runs before the rest.
    constexpr int kWindows = 8;
    int windowed = 0;
    for (int k = 1; k <= kWindows; ++k) {
      // Grows from the lower-right corner towards the upper left: the origin moves every time.
      const int w = world.width() * k / kWindows, h = world.height() * k / kWindows;
      const cv::Rect window(world.width() - w, 0, w, h);
      grid = OccupancyGrid{world.cells(window).clone(), world.resolution,
                           {world.origin.x + window.x * world.resolution,
                            world.origin.y + (world.height() - window.br().y) * world.resolution}};
      segmenter.update(grid);
      windowed += segmenter.last_update().kind == IncrementalUpdateReport::Kind::kIncremental;
    }
    EXPECT_GE(windowed, 1);  // the rest below follows windowed rooms, not only whole-map ones
    const Segmentation& rest = segmenter.resegment();
    const Segmentation batch = segment(grid);
    EXPECT_TRUE(same_partition(rest.labels, batch.labels));
    EXPECT_EQ(rest.rooms.size(), batch.rooms.size());
  }
}

}  // namespace
}  // namespace topocut
