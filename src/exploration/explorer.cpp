#include "topocut/exploration/explorer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/scan/grid_ray.h"
#include "topocut/scan/laser_simulator.h"

namespace topocut {

namespace {


std::string format_point(const Point2& p) { return format("(%.3f, %.3f)", p.x, p.y); }

// Largest 4-connected component of a mask (CV_8UC1); ties go to the component found first.
cv::Mat largest_component(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 4, CV_32S);
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (best == 0 || stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = i;
  return best == 0 ? cv::Mat::zeros(mask.size(), CV_8UC1) : cv::Mat(labels == best);
}

}  // namespace

void validate(const ExplorationOptions& o) {
  if (!std::isfinite(o.range) || o.range <= 0.0) throw Error("the laser range must be a positive number of metres");
  if (!std::isfinite(o.angular_resolution) || o.angular_resolution <= 0.0 ||
      o.angular_resolution > std::numbers::pi)
    throw Error("the angular resolution must be a positive angle of at most 180 degrees");
  if (!std::isfinite(o.step) || o.step <= 0.0) throw Error("the step must be a positive number of metres");
  if (!std::isfinite(o.min_frontier) || o.min_frontier < 0.0)
    throw Error("the minimum frontier size must be a non-negative number of metres");
  if (o.max_scans < 1) throw Error("the scan cap must be at least 1");
  if (!std::isfinite(o.growth_margin) || o.growth_margin <= 0.0)
    throw Error("the growth margin must be a positive number of metres");
  if (o.start && (!std::isfinite(o.start->x) || !std::isfinite(o.start->y)))
    throw Error("the start position must be finite");
}

Explorer::Explorer(const OccupancyGrid& ground_truth, const ExplorationOptions& options)
    : Explorer(ground_truth, cv::Mat(), options) {}

Explorer::Explorer(const OccupancyGrid& ground_truth, const cv::Mat& drivable, const ExplorationOptions& options)
    : options_(options) {
  validate(ground_truth);
  validate(options);
  truth_ = ground_truth;
  truth_.cells = ground_truth.cells.clone();
  const int w = truth_.width(), h = truth_.height();
  cv::Mat free = truth_.cells == kFree;
  if (cv::countNonZero(free) == 0) throw Error("the map has no free space to explore");
  if (!drivable.empty()) {
    if (drivable.type() != CV_8UC1 || drivable.size() != truth_.cells.size())
      throw Error("the drivable mask must be an 8-bit single-channel image of the map's size");
    drivable_ = drivable != 0;
    free &= drivable_;
    if (cv::countNonZero(free) == 0) throw Error("the map has no drivable free space to explore");
  }

  cv::Point start_cell;
  if (options.start) {
    start_cell = world_to_cell(truth_, *options.start);
    if (start_cell.x < 0 || start_cell.y < 0 || start_cell.x >= w || start_cell.y >= h ||
        !free.at<unsigned char>(start_cell))
      throw Error("the start position " + format_point(*options.start) + " is not in the map's " +
                  (drivable_.empty() ? "free space" : "drivable free space"));
  } else {
    // Clearance of every free cell of the largest component (distance to the nearest non-free cell).
    const cv::Mat component = largest_component(free);
    cv::Mat padded, distance;
    cv::copyMakeBorder(component, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::distanceTransform(padded, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    distance = distance(cv::Rect(1, 1, w, h)).clone();
    double best = -1.0;
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c)
        if (distance.at<float>(r, c) > best) {
          best = distance.at<float>(r, c);
          start_cell = {c, r};
        }
    if (options.seed != 0) {
      const double wanted = std::min(0.3 / truth_.resolution, best / 2.0);
      std::vector<int> candidates;
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          if (component.at<unsigned char>(r, c) && distance.at<float>(r, c) >= wanted) candidates.push_back(r * w + c);
      std::mt19937 rng(options.seed);
      // Uniform index without std::uniform_int_distribution, whose algorithm is not fixed by the
      // standard: the same seed then gives the same start with every standard library.
      const std::uint64_t draw = (static_cast<std::uint64_t>(rng()) << 32) | rng();
      const int chosen = candidates[static_cast<std::size_t>(draw % candidates.size())];
      start_cell = {chosen % w, chosen / w};
    }
  }
  const Point2 centre = cell_center_world(truth_, start_cell.x, start_cell.y);
  pose_ = {options.start ? options.start->x : centre.x, options.start ? options.start->y : centre.y, 0.0};
  robot_cell_ = start_cell.y * w + start_cell.x;

  known_ = cv::Mat(truth_.cells.size(), CV_8UC1, cv::Scalar(kUnknown));
  min_frontier_cells_ = std::max(1, static_cast<int>(std::ceil(options.min_frontier / truth_.resolution - 1e-9)));
  visited_.assign(static_cast<std::size_t>(w) * h, 0);
  rejected_.assign(static_cast<std::size_t>(w) * h, 0);
  parent_.assign(static_cast<std::size_t>(w) * h, -1);
  published_.resolution = truth_.resolution;
  window_ = options.growing_map ? cv::Rect() : cv::Rect(0, 0, w, h);
  publish();
}

// Casts the beams on the ground truth, then updates the known map from the scan alone, as a
// mapper would: cells a beam passed through become free, the cell it hit occupied. Cells only ever
// leave the unknown state, so free space never shrinks.
void Explorer::scan() {
  const int w = truth_.width(), h = truth_.height();
  LaserSpec spec;
  spec.field_of_view = 2.0 * std::numbers::pi;
  spec.angular_resolution = options_.angular_resolution;
  spec.range_max = options_.range;
  spec.unknown_blocks = true;  // furniture drawn grey in the dataset stops the laser like walls do
  const SimulatedScan simulated = simulate_scan(truth_, pose_, spec);
  const std::vector<double> angles = beam_angles(spec);

  const double res = truth_.resolution;
  const double pu = (pose_.x - truth_.origin.x) / res;
  const double pv = (pose_.y - truth_.origin.y) / res;
  const double max_t = options_.range / res;
  int min_c = w, max_c = -1, min_r = h, max_r = -1;
  auto mark = [&](int column, int image_row, unsigned char value) {
    unsigned char& cell = known_.at<unsigned char>(image_row, column);
    if (cell != kUnknown) return;
    cell = value;
    min_c = std::min(min_c, column);
    max_c = std::max(max_c, column);
    min_r = std::min(min_r, image_row);
    max_r = std::max(max_r, image_row);
  };
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const int hit = simulated.hit[i];
    const double range = simulated.scan.ranges[i];
    // The same exact cell traversal as the simulator, from the robot's cell.
    const double a = pose_.theta + angles[i];
    // Never mark beyond the measured range, even if rounding made the two traversals differ.
    const double limit = hit >= 0 ? range / res : max_t;
    walk_grid_ray(w, h, pu, pv, std::cos(a), std::sin(a), 0.0, max_t, [&](int column, int row, double t) {
      const int image_row = h - 1 - row;
      if (image_row * w + column == hit || t > limit) return false;
      mark(column, image_row, kFree);
      return true;
    });
    if (hit >= 0) mark(hit % w, hit / w, kOccupied);
  }
  // The robot's own cell is free (it stands there), even if no beam started inside it.
  mark(robot_cell_ % w, robot_cell_ / w, kFree);
  ++scans_;
  path_.push_back({pose_.x, pose_.y});
  const cv::Rect changed = max_c < 0 ? cv::Rect() : cv::Rect(min_c, min_r, max_c - min_c + 1, max_r - min_r + 1);
  seen_box_ = changed.empty() ? seen_box_ : (seen_box_.empty() ? changed : (seen_box_ | changed));
  publish();
  changed_published_ = changed.empty() ? cv::Rect() : (changed - window_.tl());
}

// Publishes the known map: the full frame, or (growing) the seen cells plus a margin, snapped
// outward to multiples of the margin so that the grid grows in chunks and never shrinks.
void Explorer::publish() {
  const int w = truth_.width(), h = truth_.height();
  if (options_.growing_map && !seen_box_.empty()) {
    const int chunk = std::max(1, static_cast<int>(std::lround(options_.growth_margin / truth_.resolution)));
    auto floor_to = [&](int v) { return static_cast<int>(std::floor(static_cast<double>(v) / chunk)) * chunk; };
    auto ceil_to = [&](int v) { return static_cast<int>(std::ceil(static_cast<double>(v) / chunk)) * chunk; };
    const int x0 = std::max(0, floor_to(seen_box_.x - chunk));
    const int y0 = std::max(0, floor_to(seen_box_.y - chunk));
    const int x1 = std::min(w, ceil_to(seen_box_.x + seen_box_.width + chunk));
    const int y1 = std::min(h, ceil_to(seen_box_.y + seen_box_.height + chunk));
    const cv::Rect wanted = cv::Rect(x0, y0, x1 - x0, y1 - y0) | (window_.empty() ? cv::Rect(x0, y0, x1 - x0, y1 - y0) : window_);
    window_ = wanted;
  } else if (options_.growing_map && window_.empty()) {
    // Nothing seen yet: a one-chunk window around the robot.
    const cv::Point cell(robot_cell_ % w, robot_cell_ / w);
    window_ = cv::Rect(cell.x, cell.y, 1, 1);
  }
  published_.cells = known_(window_);
  published_.origin = {truth_.origin.x + window_.x * truth_.resolution,
                       truth_.origin.y + (h - window_.y - window_.height) * truth_.resolution};
}

bool Explorer::is_frontier(int index) const {
  const int w = known_.cols, h = known_.rows;
  const unsigned char* k = known_.ptr<unsigned char>(0);
  if (k[index] != kFree) return false;
  const int r = index / w, c = index % w;
  return (r > 0 && k[index - w] == kUnknown) || (r + 1 < h && k[index + w] == kUnknown) ||
         (c > 0 && k[index - 1] == kUnknown) || (c + 1 < w && k[index + 1] == kUnknown);
}

// Size of the 8-connected frontier cluster of index, counting up to limit. With mark, the cells
// counted get the stamp (so that a small cluster is not measured again in the same search).
int Explorer::frontier_cluster_size(int index, int limit, std::vector<std::uint32_t>* mark, std::uint32_t stamp) const {
  const int w = known_.cols, h = known_.rows;
  std::vector<int> stack{index}, seen{index};
  int count = 0;
  while (!stack.empty() && count < limit) {
    const int i = stack.back();
    stack.pop_back();
    ++count;
    if (mark) (*mark)[static_cast<std::size_t>(i)] = stamp;
    const int r = i / w, c = i % w;
    for (int dr = -1; dr <= 1; ++dr)
      for (int dc = -1; dc <= 1; ++dc) {
        const int nr = r + dr, nc = c + dc;
        if ((dr == 0 && dc == 0) || nr < 0 || nr >= h || nc < 0 || nc >= w) continue;
        const int j = nr * w + nc;
        if (std::find(seen.begin(), seen.end(), j) != seen.end() || !is_frontier(j)) continue;
        seen.push_back(j);
        stack.push_back(j);
      }
  }
  return count;
}

bool Explorer::target_still_frontier() const {
  if (route_.empty()) return false;
  const int target = route_.back();
  return is_frontier(target) && frontier_cluster_size(target, min_frontier_cells_, nullptr, 0) >= min_frontier_cells_;
}

// Breadth-first search over known free cells (8-connected, no corner cutting) from the robot to
// the nearest cell of a frontier cluster that is large enough; stores the route to it.
bool Explorer::plan() {
  const int w = known_.cols, h = known_.rows;
  const unsigned char* k = known_.ptr<unsigned char>(0);
  const unsigned char* drive = drivable_.empty() ? nullptr : drivable_.ptr<unsigned char>(0);
  ++generation_;
  const std::uint32_t stamp = generation_;
  std::vector<int> queue{robot_cell_};
  visited_[static_cast<std::size_t>(robot_cell_)] = stamp;
  parent_[static_cast<std::size_t>(robot_cell_)] = -1;
  static constexpr int kDr[8] = {-1, 1, 0, 0, -1, -1, 1, 1};
  static constexpr int kDc[8] = {0, 0, -1, 1, -1, 1, -1, 1};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (i != robot_cell_ && is_frontier(i) && rejected_[static_cast<std::size_t>(i)] != stamp) {
      if (frontier_cluster_size(i, min_frontier_cells_, &rejected_, stamp) >= min_frontier_cells_) {
        route_.clear();
        for (int j = i; j != -1; j = parent_[static_cast<std::size_t>(j)]) route_.push_back(j);
        std::reverse(route_.begin(), route_.end());
        route_position_ = 0;
        return true;
      }
    }
    const int r = i / w, c = i % w;
    for (int d = 0; d < 8; ++d) {
      const int nr = r + kDr[d], nc = c + kDc[d];
      if (nr < 0 || nr >= h || nc < 0 || nc >= w) continue;
      const int j = nr * w + nc;
      if (visited_[static_cast<std::size_t>(j)] == stamp || k[j] != kFree || (drive && !drive[j])) continue;
      if (d >= 4 && (k[r * w + nc] != kFree || k[nr * w + c] != kFree)) continue;
      visited_[static_cast<std::size_t>(j)] = stamp;
      parent_[static_cast<std::size_t>(j)] = i;
      queue.push_back(j);
    }
  }
  route_.clear();
  return false;
}

bool Explorer::next() {
  if (finished_) return false;
  if (scans_ == 0) {
    scan();
    return true;
  }
  if (!target_still_frontier() && !plan()) {
    finished_ = true;
    stop_reason_ = "no reachable frontier left";
    return false;
  }
  if (scans_ >= options_.max_scans) {
    finished_ = true;
    stop_reason_ = "scan cap reached (" + std::to_string(options_.max_scans) + " scans)";
    return false;
  }
  // Walk along the route for one step (at least one cell).
  const int w = known_.cols;
  const double res = truth_.resolution;
  double walked = 0.0;
  std::size_t position = route_position_;
  while (position + 1 < route_.size()) {
    const int a = route_[position], b = route_[position + 1];
    const double length = (a % w != b % w && a / w != b / w) ? std::numbers::sqrt2 * res : res;
    if (position > route_position_ && walked + length > options_.step + 1e-9) break;
    walked += length;
    ++position;
  }
  const int from = robot_cell_;
  robot_cell_ = route_[position];
  route_position_ = position;
  const Point2 centre = cell_center_world(truth_, robot_cell_ % w, robot_cell_ / w);
  const double heading = std::atan2(centre.y - pose_.y, centre.x - pose_.x);
  path_length_ += std::hypot(centre.x - pose_.x, centre.y - pose_.y);
  pose_ = {centre.x, centre.y, from == robot_cell_ ? pose_.theta : heading};
  scan();
  if (route_position_ + 1 >= route_.size()) route_.clear();  // arrived: the target is resolved
  return true;
}

int reachable_free_cells(const OccupancyGrid& ground_truth, const Point2& start) {
  validate(ground_truth);
  const cv::Point cell = world_to_cell(ground_truth, start);
  if (cell.x < 0 || cell.y < 0 || cell.x >= ground_truth.width() || cell.y >= ground_truth.height() ||
      ground_truth.cells.at<unsigned char>(cell) != kFree)
    return 0;
  cv::Mat labels;
  cv::connectedComponents(ground_truth.cells == kFree, labels, 4, CV_32S);
  return cv::countNonZero(labels == labels.at<int>(cell));
}

}  // namespace topocut
