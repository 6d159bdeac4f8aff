#pragma once
// The stages of `topocut segment` timed one by one (the calls segment() makes) in process CPU time,
// beside the contour floor (decode the image, threshold, cv::findContours) timed the same way:
// shared by segment_stages_benchmark and extreme_maps_benchmark.
#include <time.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/evaluation/room_defects.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut::benchmarks {

// CPU time of the whole process (OpenCV's worker threads too), in milliseconds.
inline double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// Per stage, one time per run (ms).
struct StageTimes {
  std::vector<double> floor, load, free_space, clean, polygons, decompose, merge, rooms, total;
  int vertices = 0, pieces = 0, rooms_found = 0;
};

// One run of the pipeline on the map at path, stage by stage, each stage's time appended to t; the
// free space is timed once more on its own (not part of the total) so that the cleaning's share can
// be told apart. With no_crop the stages run on the whole grid instead of segmentation_box().
inline Segmentation time_stages(const std::string& path, const MapLoadOptions& load, const SegmentOptions& options,
                                bool no_crop, StageTimes& t) {
  const double t0 = cpu_ms();
  contour_floor_ms(path, load.free_min, 1);
  t.floor.push_back(cpu_ms() - t0);

  const double a = cpu_ms();
  const OccupancyGrid grid = load_map(path, load);
  const double b = cpu_ms();
  // As segment() does: the stages run on the known cells' box (the labels are placed back into the
  // whole map in the labels column).
  const cv::Rect box = segmentation_box(grid, options);
  const OccupancyGrid part = no_crop || box.size() == grid.cells.size() ? grid : crop(grid, box);
  const SegmentationInput input = segmentation_input(part, options);
  const double c = cpu_ms();
  const FreeSpacePolygons polygons = free_space_polygons(input.floor, grid.resolution, options.contours);
  const double d = cpu_ms();
  std::vector<PieceSet> raw;
  for (const FreeSpaceComponent& component : polygons.components)
    raw.push_back(decompose_pieces(component, grid.resolution, options));
  const double e = cpu_ms();
  PieceSet pieces;
  for (std::size_t i = 0; i < raw.size(); ++i)
    pieces.append(merge_rooms(polygons.components[i], raw[i], input.labelled.cells, grid.resolution, options.merge));
  const double f = cpu_ms();
  Segmentation s = rooms_from_pieces(input.labelled, pieces, options.labels);
  if (part.cells.size() != grid.cells.size()) {
    // As segment() places them (uncrop(), written here with OpenCV so that older builds time the same).
    cv::Mat labels(grid.cells.size(), CV_32SC1);
    labels.rowRange(0, box.y).setTo(0);
    labels.rowRange(box.y + box.height, labels.rows).setTo(0);
    labels.rowRange(box.y, box.y + box.height).colRange(0, box.x).setTo(0);
    labels.rowRange(box.y, box.y + box.height).colRange(box.x + box.width, labels.cols).setTo(0);
    s.labels.copyTo(labels(box));
    s.labels = labels;
  }
  const double g = cpu_ms();
  segmentation_free_space(part, options);
  t.free_space.push_back(cpu_ms() - g);
  t.load.push_back(b - a);
  t.clean.push_back(c - b);
  t.polygons.push_back(d - c);
  t.decompose.push_back(e - d);
  t.merge.push_back(f - e);
  t.rooms.push_back(g - f);
  t.total.push_back(g - a);
  t.vertices = 0;
  for (const FreeSpaceComponent& component : polygons.components) {
    t.vertices += static_cast<int>(component.polygon.outer.size());
    for (const Ring& hole : component.polygon.holes) t.vertices += static_cast<int>(hole.size());
  }
  t.pieces = 0;
  for (const PieceSet& set : raw) t.pieces += static_cast<int>(set.pieces.size());
  t.rooms_found = static_cast<int>(s.rooms.size());
  return s;
}

inline double least(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// Each stage's least time over the runs (ms), in pipeline order, the floor first and the total last;
// "clean" is the front end (free space and cleaning) less the free space timed alone.
inline std::vector<std::pair<std::string, double>> least_stage_ms(const StageTimes& t) {
  return {{"floor", least(t.floor)},
          {"load", least(t.load)},
          {"free", least(t.free_space)},
          {"clean", std::max(0.0, least(t.clean) - least(t.free_space))},
          {"polygons", least(t.polygons)},
          {"decompose", least(t.decompose)},
          {"merge", least(t.merge)},
          {"labels", least(t.rooms)},
          {"total", least(t.total)}};
}

}  // namespace topocut::benchmarks
