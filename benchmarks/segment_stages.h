#pragma once
// The stages of `topocut segment` in process CPU time (segment()'s own stage times, segment_times.h),
// beside the contour floor (decode the image, threshold, cv::findContours) timed the same way:
// shared by segment_stages_benchmark and extreme_maps_benchmark.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/clock.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut::benchmarks {

// CPU time of the whole process (OpenCV's worker threads too), in milliseconds.
inline double cpu_ms() { return process_cpu_ms(); }

// Per stage, one time per run (ms): the floor, loading, segment()'s own stages (SegmentTimes) and, timed
// again on their own for a closer look at the front end, the free space, the cleaning and the polygons.
struct StageTimes {
  std::vector<double> floor, load, free_space, clean, polygons, total;
  std::vector<SegmentTimes> stages;
  int vertices = 0, rooms_found = 0;
};

// One run of `topocut segment`'s work on the map at path: its contour floor, load_map() and segment()
// (its stages read from the process CPU clock), each appended to t; then the front end's parts once
// more on their own (not in the total).
inline Segmentation time_stages(const std::string& path, const MapLoadOptions& load, const SegmentOptions& options, StageTimes& t) {
  const double t0 = cpu_ms();
  contour_floor_ms(path, load.free_min, 1);
  t.floor.push_back(cpu_ms() - t0);

  const double a = cpu_ms();
  const OccupancyGrid grid = load_map(path, load);
  const double b = cpu_ms();
  SegmentTimes stages;
  stages.clock = cpu_ms;
  Segmentation s = segment(grid, options, nullptr, &stages);
  t.load.push_back(b - a);
  t.stages.push_back(stages);
  t.total.push_back(cpu_ms() - a);

  // The front end's parts, on the box segment() works on.
  const cv::Rect box = segmentation_box(grid, options);
  const OccupancyGrid part = box.size() == grid.cells.size() ? grid : crop(grid, box);
  const double c = cpu_ms();
  segmentation_free_space(part, options);
  const double d = cpu_ms();
  const SegmentationInput input = segmentation_input(part, options);
  const double e = cpu_ms();
  const FreeSpacePolygons polygons = free_space_polygons(input.floor, grid.resolution, options.contours);
  const double f = cpu_ms();
  t.free_space.push_back(d - c);
  t.clean.push_back(std::max(0.0, (e - d) - (d - c)));
  t.polygons.push_back(f - e);
  t.vertices = 0;
  for (const FreeSpaceComponent& component : polygons.components) {
    t.vertices += static_cast<int>(component.polygon.outer.size());
    for (const Ring& hole : component.polygon.holes) t.vertices += static_cast<int>(hole.size());
  }
  t.rooms_found = static_cast<int>(s.rooms.size());
  return s;
}

inline double least(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// The columns of least_stage_ms(), in its order: the floor, loading, segment()'s stages, the front
// end's parts ("free", "clean", "polygons": timed again on their own, part of "front end") and the
// total (loading and segment()).
inline std::vector<std::string> stage_names() {
  std::vector<std::string> names{"floor", "load"};
  for (std::size_t k = 0; k < kSegmentStages; ++k) names.push_back(stage_name(static_cast<SegmentStage>(k)));
  for (const char* name : {"free", "clean", "polygons", "total"}) names.push_back(name);
  return names;
}

// Each column's least time over the runs (ms), named by stage_names().
inline std::vector<std::pair<std::string, double>> least_stage_ms(const StageTimes& t) {
  std::vector<double> values{least(t.floor), least(t.load)};
  for (std::size_t k = 0; k < kSegmentStages; ++k) {
    std::vector<double> stage;
    for (const SegmentTimes& run : t.stages) stage.push_back(run.ms[k]);
    values.push_back(least(stage));
  }
  for (const std::vector<double>* v : {&t.free_space, &t.clean, &t.polygons, &t.total}) values.push_back(least(*v));
  const std::vector<std::string> names = stage_names();
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t k = 0; k < names.size(); ++k) out.emplace_back(names[k], values[k]);
  return out;
}

}  // namespace topocut::benchmarks
