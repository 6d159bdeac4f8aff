#include "topocut/walls/wall_map.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/value_ranges.h"

namespace topocut {

namespace {

constexpr int kShift = 4;  // sub-pixel bits for OpenCV drawing
constexpr double kScale = 1 << kShift;

}  // namespace

void validate(const WallMapOptions& options) { check_option_rows(wall_map_option_rows(), options); }

namespace {

struct Ray {
  Point2 from, to;
};

// The stretch of each beam known to be free: up to one cell (plus short_of_hit metres) short of a
// hit, or along a beam without return up to the no-return limit.
std::vector<Ray> free_rays(std::span<const PosedScan> scans, const WallMapOptions& o, double short_of_hit = 0.0) {
  std::vector<Ray> rays;
  for (const PosedScan& posed : scans) {
    const Scan& scan = posed.scan;
    const Pose2& pose = posed.pose;
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) continue;
    const Point2 from{pose.x, pose.y};
    for (std::size_t i = 0; i < scan.size() && i < scan.angles.size(); ++i) {
      double reach = 0.0;
      const double r = scan.ranges[i];
      if (scan.is_valid(i)) {
        reach = std::min(r - o.resolution - short_of_hit, o.max_free_range);
      } else if (r == std::numeric_limits<double>::infinity() && std::isfinite(scan.angles[i])) {
        reach = std::min(o.no_return_free_range, o.max_free_range);
      }
      if (reach <= 0.0) continue;
      const double a = pose.theta + scan.angles[i];
      rays.push_back({from, {from.x + reach * std::cos(a), from.y + reach * std::sin(a)}});
    }
  }
  return rays;
}

cv::Point to_pixel(const OccupancyGrid& grid, const Point2& p) {
  // Pixel centres at integer coordinates, row 0 on top, kShift fractional bits.
  const double column = (p.x - grid.origin.x) / grid.resolution - 0.5;
  const double row = grid.height() - 0.5 - (p.y - grid.origin.y) / grid.resolution;
  return {static_cast<int>(std::lround(column * kScale)), static_cast<int>(std::lround(row * kScale))};
}

cv::Rect cell_box(const OccupancyGrid& grid, const Point2& p) {
  const int column = static_cast<int>(std::floor((p.x - grid.origin.x) / grid.resolution));
  const int row = grid.height() - 1 - static_cast<int>(std::floor((p.y - grid.origin.y) / grid.resolution));
  return {column, row, 1, 1};
}

// The frame covering the poses, the rays' ends and the walls' polygons, plus the margin; all unknown.
OccupancyGrid unknown_frame(std::span<const PosedScan> scans, const std::vector<Ray>& rays,
                            const std::vector<Segment2>& walls, const WallMapOptions& options) {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  auto extend = [&](const Point2& p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  };
  for (const PosedScan& s : scans) extend({s.pose.x, s.pose.y});
  for (const Ray& r : rays) extend(r.to);
  for (const Segment2& w : walls)
    for (const Point2& p : wall_polygon(w, options.wall_thickness)) extend(p);
  if (!(min_x <= max_x)) throw Error("there is nothing to map: no scan with a finite pose and no wall");

  OccupancyGrid grid;
  grid.resolution = options.resolution;
  grid.origin = {min_x - options.margin, min_y - options.margin};
  const double columns = std::ceil((max_x - min_x + 2.0 * options.margin) / options.resolution) + 1.0;
  const double rows = std::ceil((max_y - min_y + 2.0 * options.margin) / options.resolution) + 1.0;
  if (columns * rows > static_cast<double>(options.max_cells) || columns > 1e6 || rows > 1e6)
    throw Error("the map would span " + std::to_string(max_x - min_x) + " m by " + std::to_string(max_y - min_y) +
                " m, " + std::to_string(static_cast<long long>(columns * rows)) + " cells at " +
                std::to_string(options.resolution) + " m per cell (more than the limit of " +
                std::to_string(options.max_cells) + "); check the poses or use a coarser resolution");
  grid.cells = cv::Mat(static_cast<int>(rows), static_cast<int>(columns), CV_8UC1, cv::Scalar(kUnknown));
  return grid;
}

void draw_rays(const OccupancyGrid& grid, const std::vector<Ray>& rays, cv::Mat& seen) {
  for (const Ray& r : rays) cv::line(seen, to_pixel(grid, r.from), to_pixel(grid, r.to), cv::Scalar(255), 1, cv::LINE_8, kShift);
}

// Cells under a wall polygon are occupied; the centre line is also drawn 4-connected so that no
// free path crosses a wall diagonally.
// (Drawn with `value` into target, an image of grid's frame.)
void draw_walls(const OccupancyGrid& grid, cv::Mat& target, const std::vector<Segment2>& walls, double thickness,
                unsigned char value) {
  for (const Segment2& wall : walls) {
    std::vector<cv::Point> corners;
    for (const Point2& p : wall_polygon(wall, thickness)) corners.push_back(to_pixel(grid, p));
    cv::fillConvexPoly(target, corners, cv::Scalar(value), cv::LINE_8, kShift);
    cv::line(target, to_pixel(grid, wall.a), to_pixel(grid, wall.b), cv::Scalar(value), 1, cv::LINE_4, kShift);
  }
}

void draw_walls(OccupancyGrid& grid, const std::vector<Segment2>& walls, double thickness) {
  draw_walls(grid, grid.cells, walls, thickness, kOccupied);
}

}  // namespace

Ring wall_polygon(const Segment2& wall, double thickness) {
  const double length = distance(wall.a, wall.b);
  const Point2 u = length > 0.0 ? (wall.b - wall.a) / length : Point2{1.0, 0.0};
  const Point2 n{-u.y, u.x};
  const double h = 0.5 * thickness;
  // Capped by half the thickness at both ends so that walls meeting at a corner close it.
  return {wall.a - h * u - h * n, wall.b + h * u - h * n, wall.b + h * u + h * n, wall.a - h * u + h * n};
}

OccupancyGrid build_wall_map(std::span<const PosedScan> scans, std::span<const Wall> walls, const WallMapOptions& options) {
  validate(options);
  const std::vector<Ray> rays = free_rays(scans, options);
  std::vector<Segment2> lines;
  lines.reserve(walls.size());
  for (const Wall& w : walls) lines.push_back(w.segment);
  OccupancyGrid grid = unknown_frame(scans, rays, lines, options);
  cv::Mat seen = cv::Mat::zeros(grid.cells.size(), CV_8UC1);
  draw_rays(grid, rays, seen);
  grid.cells.setTo(cv::Scalar(kFree), seen);
  draw_walls(grid, lines, options.wall_thickness);
  return grid;
}

IncrementalWallMap::IncrementalWallMap(std::span<const PosedScan> scans, std::span<const WallSegment> segments,
                                       const WallMapOptions& options,
                                       const std::optional<OccupancyEvidenceOptions>& evidence)
    : options_(options) {
  validate(options);
  if (evidence) validate(*evidence);
  std::vector<Segment2> lines;
  lines.reserve(segments.size());
  for (const WallSegment& s : segments) lines.push_back(s.segment);
  grid_ = unknown_frame(scans, free_rays(scans, options), lines, options);
  seen_ = cv::Mat::zeros(grid_.cells.size(), CV_8UC1);
  if (evidence) {
    hits_ = cv::Mat::zeros(grid_.cells.size(), CV_8UC1);
    evidence_.emplace(grid_.cells.size(), *evidence);
    miss_margin_ = evidence->miss_margin;
  }
}

cv::Rect IncrementalWallMap::add(const PosedScan& scan, std::span<const WallSegment> segments) {
  const std::vector<Ray> rays = free_rays(std::span<const PosedScan>(&scan, 1), options_, evidence_ ? miss_margin_ : 0.0);
  std::vector<Segment2> lines;
  for (const WallSegment& s : segments) lines.push_back(s.segment);
  // Everything this scan draws lies in the box of its rays' ends, its pose and its walls' corners.
  const cv::Rect all(0, 0, grid_.width(), grid_.height());
  cv::Rect box = cell_box(grid_, {scan.pose.x, scan.pose.y});
  for (const Ray& r : rays) box |= cell_box(grid_, r.to);
  for (const Segment2& line : lines)
    for (const Point2& p : wall_polygon(line, options_.wall_thickness)) box |= cell_box(grid_, p);
  box = (box + cv::Size(2, 2) - cv::Point(1, 1)) & all;
  if (box.empty()) return {};
  draw_rays(grid_, rays, seen_);
  if (evidence_) {
    // One scan's walls win over its own rays: a cell is a hit or a miss, never both.
    draw_walls(grid_, hits_, lines, options_.wall_thickness, 255);
    const cv::Rect changed = evidence_->add(box, hits_, seen_, grid_.cells);
    seen_(box).setTo(cv::Scalar(0));
    hits_(box).setTo(cv::Scalar(0));
    return changed;
  }
  const cv::Mat before = grid_.cells(box).clone();
  // Walls win over rays, including earlier walls: a ray frees only cells no wall has claimed.
  cv::Mat window = grid_.cells(box);
  window.setTo(cv::Scalar(kFree), seen_(box) & (window != kOccupied));
  seen_(box).setTo(cv::Scalar(0));
  draw_walls(grid_, lines, options_.wall_thickness);
  const cv::Mat differs = before != grid_.cells(box);
  const cv::Rect changed = cv::boundingRect(differs);
  return changed.empty() ? cv::Rect() : changed + box.tl();
}

}  // namespace topocut
