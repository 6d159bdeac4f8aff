// Generates the small maps bundled in maps/: for each, a ROS map_server YAML with its PNG (free
// 254, occupied 0, unknown 205) and a ground-truth segmentation in the format of Bormann et al.'s
// dataset (rooms white, separated by black lines across the doors, 0 elsewhere).
//
//   generate_maps [OUTPUT_DIR]    (default: the current directory)
//
// Everything is drawn in metres (origin at the lower-left corner, y up) at 0.05 m per cell.
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/map_saver.h"

namespace {

using topocut::kFree;
using topocut::kOccupied;
using topocut::kUnknown;

constexpr double kResolution = 0.05;
constexpr double kWall = 0.2;  // wall thickness, metres

struct Box {
  double x0, y0, x1, y1;  // metres
};

class Drawing {
 public:
  Drawing(double width_m, double height_m)
      : cells_(static_cast<int>(std::lround(height_m / kResolution)), static_cast<int>(std::lround(width_m / kResolution)),
               CV_8UC1, cv::Scalar(kUnknown)) {}

  cv::Rect rect(const Box& b) const {
    const int c0 = static_cast<int>(std::lround(b.x0 / kResolution));
    const int c1 = static_cast<int>(std::lround(b.x1 / kResolution));
    const int r0 = cells_.rows - static_cast<int>(std::lround(b.y1 / kResolution));
    const int r1 = cells_.rows - static_cast<int>(std::lround(b.y0 / kResolution));
    return cv::Rect(c0, r0, c1 - c0, r1 - r0) & cv::Rect(0, 0, cells_.cols, cells_.rows);
  }
  void fill(const Box& b, unsigned char value) { cells_(rect(b)).setTo(value); }
  // A wall along the segment (horizontal or vertical), kWall thick, centred on it.
  void wall(double x0, double y0, double x1, double y1) {
    fill({std::min(x0, x1) - kWall / 2, std::min(y0, y1) - kWall / 2, std::max(x0, x1) + kWall / 2,
          std::max(y0, y1) + kWall / 2},
         kOccupied);
  }
  // An opening through a wall; remembered so the ground truth can close it with a black line.
  void door(const Box& b) {
    fill(b, kFree);
    doors_.push_back(b);
  }
  void disc(double x, double y, double radius, unsigned char value) {
    const cv::Point centre(static_cast<int>(std::lround(x / kResolution)),
                           cells_.rows - static_cast<int>(std::lround(y / kResolution)));
    cv::circle(cells_, centre, static_cast<int>(std::lround(radius / kResolution)), cv::Scalar(value), cv::FILLED, cv::LINE_8);
  }

  // Bormann-style ground truth: free cells white, doors black, everything else 0.
  cv::Mat ground_truth() const {
    cv::Mat gt = cv::Mat::zeros(cells_.size(), CV_8UC1);
    gt.setTo(255, cells_ == kFree);
    for (const Box& d : doors_) gt(rect(d)).setTo(0);
    return gt;
  }

  void save(const std::filesystem::path& dir, const std::string& name) const {
    topocut::OccupancyGrid grid{cells_, kResolution, {0.0, 0.0}};
    topocut::MapSaveOptions options;
    options.image_extension = ".png";
    topocut::save_map((dir / (name + ".yaml")).string(), grid, options);
    topocut::write_image_atomically((dir / (name + "_gt_segmentation.png")).string(), ground_truth());
    std::cout << "wrote " << (dir / name).string() << ".{yaml,png} and _gt_segmentation.png (" << cells_.cols << " x "
              << cells_.rows << " cells, " << doors_.size() << " doors)\n";
  }

 private:
  cv::Mat cells_;
  std::vector<Box> doors_;
};

// A corridor across the building with three rooms north of it, two south, and one door between
// two of the northern rooms: six ground-truth rooms, six doors.
void floorplan(const std::filesystem::path& dir) {
  Drawing d(20.0, 15.0);
  d.fill({0.5, 0.5, 19.5, 14.5}, kFree);
  d.wall(0.5, 0.5, 19.5, 0.5);
  d.wall(0.5, 14.5, 19.5, 14.5);
  d.wall(0.5, 0.5, 0.5, 14.5);
  d.wall(19.5, 0.5, 19.5, 14.5);
  d.wall(0.5, 6.0, 19.5, 6.0);   // corridor, south side
  d.wall(0.5, 8.0, 19.5, 8.0);   // corridor, north side
  d.wall(7.0, 8.0, 7.0, 14.5);   // between the northern rooms
  d.wall(13.0, 8.0, 13.0, 14.5);
  d.wall(9.0, 0.5, 9.0, 6.0);    // between the southern rooms
  d.wall(14.5, 0.5, 14.5, 3.0);  // a stub that makes the south-east room non-convex
  const double h = kWall / 2;
  d.door({3.0, 8.0 - h, 3.9, 8.0 + h});
  d.door({9.5, 8.0 - h, 10.4, 8.0 + h});
  d.door({15.5, 8.0 - h, 16.4, 8.0 + h});
  d.door({4.0, 6.0 - h, 4.9, 6.0 + h});
  d.door({12.0, 6.0 - h, 12.9, 6.0 + h});
  d.door({7.0 - h, 11.0, 7.0 + h, 11.9});
  d.save(dir, "floorplan");
}

// An L-shaped corridor, 2 m wide, arms of 11 m: one room in the ground truth (the classic case a
// convex decomposition cuts in two).
void corridor_l(const std::filesystem::path& dir) {
  Drawing d(15.0, 15.0);
  d.fill({2.0 - kWall, 2.0 - kWall, 4.0 + kWall, 13.0 + kWall}, kOccupied);
  d.fill({2.0 - kWall, 2.0 - kWall, 13.0 + kWall, 4.0 + kWall}, kOccupied);
  d.fill({2.0, 2.0, 4.0, 13.0}, kFree);
  d.fill({2.0, 2.0, 13.0, 4.0}, kFree);
  d.save(dir, "corridor_l");
}

// Two offices joined by a door, with furniture: free-standing pieces (table, chairs, a pillar, a
// sofa, a plant) are holes in the free space; pieces against walls (cabinet, shelf, an L-desk)
// dent the outer boundary. The ground truth leaves furniture out (it is not free space).
void furnished(const std::filesystem::path& dir) {
  Drawing d(18.0, 13.0);
  d.fill({0.5, 0.5, 17.5, 12.5}, kFree);
  d.wall(0.5, 0.5, 17.5, 0.5);
  d.wall(0.5, 12.5, 17.5, 12.5);
  d.wall(0.5, 0.5, 0.5, 12.5);
  d.wall(17.5, 0.5, 17.5, 12.5);
  d.wall(11.0, 0.5, 11.0, 12.5);
  d.door({11.0 - kWall / 2, 6.0, 11.0 + kWall / 2, 6.9});
  // Office 1.
  d.fill({4.0, 5.0, 6.5, 6.2}, kOccupied);  // table
  for (const double x : {4.3, 5.8}) {
    d.fill({x, 4.3, x + 0.45, 4.75}, kOccupied);  // chairs south of the table
    d.fill({x, 6.45, x + 0.45, 6.9}, kOccupied);  // and north of it
  }
  d.fill({1.0, 11.8, 3.5, 12.5}, kOccupied);  // cabinet against the north wall
  d.fill({0.5, 2.0, 1.0, 6.0}, kOccupied);    // shelf against the west wall
  d.disc(8.5, 9.5, 0.3, kOccupied);           // pillar
  // Office 2.
  d.fill({15.5, 9.0, 17.5, 9.7}, kOccupied);  // L-shaped desk against the east wall
  d.fill({16.7, 7.0, 17.5, 9.7}, kOccupied);
  d.fill({12.5, 1.5, 14.5, 2.3}, kOccupied);  // sofa
  d.disc(13.0, 10.0, 0.2, kOccupied);         // plant
  d.save(dir, "furnished");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::filesystem::path dir = argc > 1 ? argv[1] : ".";
    if (!std::filesystem::is_directory(dir)) {
      std::cerr << "generate_maps: error: '" << dir.string() << "' is not a directory\n";
      return 1;
    }
    floorplan(dir);
    corridor_l(dir);
    furnished(dir);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "generate_maps: error: " << e.what() << "\n";
    return 1;
  }
}
