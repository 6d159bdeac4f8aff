#include "topocut/exploration/simulated_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "exploration/seeded_random.h"
#include "exploration/simulated_world.h"
#include "topocut/core/error.h"
#include "topocut/exploration/explorer.h"
#include "topocut/scan/grid_ray.h"
#include "topocut/scan/laser_simulator.h"

namespace topocut {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Streams of SeededRandom beside the world's (simulated_world.cpp uses 1..6).
enum Stream : std::uint32_t { kSensorStream = 20, kStartStream, kNoiseStream, kDriftStream };

using Row = OptionRow<SimulatedMapOptions>;

template <typename Field>
Row number(const char* name, const char* value_name, OptionRange range, Field field, const char* help) {
  return {name, value_name, help, range, [field](const SimulatedMapOptions& o) { return static_cast<double>(field(o)); },
          [field](SimulatedMapOptions& o, double v) { field(o) = v; }};
}

// An angle field (radians) given in degrees.
template <typename Field>
Row degrees(const char* name, OptionRange range, Field field, const char* help) {
  return {name, "DEG", help, range, [field](const SimulatedMapOptions& o) { return field(o) / kDegree; },
          [field](SimulatedMapOptions& o, double v) { field(o) = v * kDegree; }};
}

// A whole-number field.
template <typename Field>
Row whole(const char* name, const char* value_name, Field field, const char* help) {
  const std::string shown = std::string("--") + name;
  return {name, value_name, help, OptionRange::kNonNegative, [field](const SimulatedMapOptions& o) { return static_cast<double>(field(o)); },
          [field, shown](SimulatedMapOptions& o, double v) {
            if (v != std::floor(v) || v > 1e9) throw Error(shown + " must be a whole number");
            field(o) = static_cast<int>(v);
          }};
}

void check_share(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0)) throw Error(std::string("--") + name + " must be a share in [0, 1]");
}

void check_from_to(double from, double to, const char* from_name, const char* to_name) {
  if (!(to >= from)) throw Error(std::string("--") + to_name + " must not be below --" + from_name);
}

}  // namespace

const std::vector<OptionRow<SimulatedMapOptions>>& simulated_map_option_rows() {
  using R = OptionRange;
  static const std::vector<Row> rows = {
      number("range-from", "M", R::kLength, [](auto& o) -> auto& { return o.range_from; },
             "lidar range limit in metres, drawn per seed in [range-from, range-to] (equal: fixed)"),
      number("range-to", "M", R::kLength, [](auto& o) -> auto& { return o.range_to; }, "upper end of the range draw"),
      degrees("angular-step-from", R::kPositive, [](auto& o) -> auto& { return o.angular_step_from; },
              "degrees between beams of the 360° scan, drawn per seed in [from, to]"),
      degrees("angular-step-to", R::kPositive, [](auto& o) -> auto& { return o.angular_step_to; }, "upper end of the angular step draw"),
      number("range-noise", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.range_noise; },
             "standard deviation of the Gaussian noise on every return, metres (0: exact)"),
      number("no-return-length", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.no_return_length; },
             "metres of free space a beam without a return (nothing within range) clears (0: none)"),
      number("occupied-ratio", "R", R::kFraction, [](auto& o) -> auto& { return o.occupied_ratio; },
             "a seen cell is occupied when this share of the beams that reached it ended there"),
      number("explore-range", "M", R::kLength, [](auto& o) -> auto& { return o.explore_range; },
             "range of the explorer's own laser that decides where the robot goes (frontiers), metres"),
      number("scan-step", "M", R::kLength, [](auto& o) -> auto& { return o.scan_step; }, "metres driven between two scans"),
      number("robot-radius", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.robot_radius; },
             "the robot keeps this far from walls and furniture, metres"),
      number("drift", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.drift; },
             "largest position error of the poses scans are mapped with, metres (0: exact poses)"),
      degrees("drift-angle", R::kNonNegative, [](auto& o) -> auto& { return o.drift_angle; },
              "largest heading error of those poses, degrees (0: exact)"),
      number("outside", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.outside; },
             "metres of open ground around the building, which the laser sees through windows (0: a solid exterior)"),
      number("outer-wall", "M", R::kLength, [](auto& o) -> auto& { return o.outer_wall; },
             "outer walls are kept at most this thick; farther non-free space reached from the border is exterior"),
      number("windows", "SHARE", R::kNonNegative, [](auto& o) -> auto& { return o.windows; },
             "share of the outer wall's length the laser sees through (windows, glass and open outer doors; 0: none)"),
      number("outside-obstacles", "N", R::kNonNegative, [](auto& o) -> auto& { return o.outside_obstacles; },
             "trees, posts and cars per 100 m² of open ground (0: none)"),
      number("closed-doors", "P", R::kNonNegative, [](auto& o) -> auto& { return o.closed_doors; },
             "probability that a door between people's rooms is closed (the room behind may stay unseen; 0: all open)"),
      number("max-door-width", "M", R::kLength, [](auto& o) -> auto& { return o.max_door_width; },
             "openings between rooms wider than this are not doors (never closed)"),
      number("furniture", "SHARE", R::kNonNegative, [](auto& o) -> auto& { return o.furniture; },
             "share of each room's floor under beds, sofas, shelves and desks pushed against walls (0: none)"),
      number("clutter", "N", R::kNonNegative, [](auto& o) -> auto& { return o.clutter; },
             "tables with chairs (seen as legs), bins and boxes per 10 m² of floor (0: none)"),
      number("door-clearance", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.door_clearance; },
             "metres around every door kept free of furniture and clutter"),
      whole("wall-change", "CELLS", [](auto& o) -> auto& { return o.wall_change; },
            "walls are thinned or thickened by up to this many cells, drawn per seed (0: as drawn)"),
      number("room-fill", "M", R::kLengthOrZero, [](auto& o) -> auto& { return o.room_fill; },
             "free map cells in no room this close to a room join it in the ground truth (0: none)"),
      whole("max-scans", "SCANS", [](auto& o) -> auto& { return o.max_scans; }, "stop the robot after this many scans"),
  };
  return rows;
}

void validate(const SimulatedMapOptions& o) {
  for (const Row& row : simulated_map_option_rows()) check_option_value(row.range, row.get(o), "--" + row.name);
  check_from_to(o.range_from, o.range_to, "range-from", "range-to");
  check_from_to(o.angular_step_from, o.angular_step_to, "angular-step-from", "angular-step-to");
  if (o.angular_step_to > std::numbers::pi) throw Error("--angular-step-to must be at most 180 degrees");
  if (o.angular_step_from < 0.01 * kDegree) throw Error("--angular-step-from must be at least 0.01 degrees");
  if (o.drift_angle > std::numbers::pi / 4) throw Error("--drift-angle must be at most 45 degrees");
  check_share(o.windows, "windows");
  check_share(o.closed_doors, "closed-doors");
  if (!(o.furniture <= 0.9)) throw Error("--furniture must be a share in [0, 0.9]");
  if (o.wall_change < 0 || o.wall_change > 5) throw Error("--wall-change must be 0 to 5 cells");
  if (o.max_scans < 1) throw Error("--max-scans must be at least 1");
}

namespace {

// Hit and miss counts per cell of the map's frame, filled beam by beam.
class HitCounter {
 public:
  HitCounter(int width, int height) : width_(width), height_(height), hits_(std::size_t(width) * height, 0), misses_(hits_.size(), 0) {}

  // One beam from (pu, pv) (continuous cell coordinates, rows from the bottom) along (du, dv): the
  // cells before length (cells) missed, the cell at length hit when hit is set.
  void beam(double pu, double pv, double du, double dv, double length, bool hit) {
    // A return at a cell boundary (the simulator's ranges end on the first blocking cell's edge)
    // belongs to the cell behind it, whatever the rounding.
    if (hit) length += 1e-6;
    const int end_u = static_cast<int>(std::floor(pu + length * du)), end_v = static_cast<int>(std::floor(pv + length * dv));
    walk_grid_ray(width_, height_, pu, pv, du, dv, 0.0, length, [&](int column, int row, double) {
      if (hit && column == end_u && row == end_v) return false;
      ++misses_[index(column, row)];
      return true;
    });
    if (hit && end_u >= 0 && end_v >= 0 && end_u < width_ && end_v < height_) ++hits_[index(end_u, end_v)];
  }

  // kUnknown where no beam came, kOccupied where at least ratio of the beams that came ended.
  cv::Mat cells(double ratio) const {
    cv::Mat out(height_, width_, CV_8UC1);
    for (int r = 0; r < height_; ++r)
      for (int c = 0; c < width_; ++c) {
        const std::size_t i = index(c, height_ - 1 - r);
        const double seen = static_cast<double>(hits_[i]) + misses_[i];
        out.at<unsigned char>(r, c) = seen == 0 ? kUnknown : (hits_[i] >= ratio * seen ? kOccupied : kFree);
      }
    return out;
  }

 private:
  std::size_t index(int column, int bottom_row) const { return std::size_t(bottom_row) * width_ + column; }
  int width_, height_;
  std::vector<std::uint32_t> hits_, misses_;
};

// The error of the pose a scan is mapped with: a random walk per metre driven, pulled back toward
// zero over about ten metres (as loop closures do) and held within the bounds.
class PoseDrift {
 public:
  PoseDrift(double bound, double angle_bound, std::uint32_t seed) : bound_(bound), angle_bound_(angle_bound), rng_(seed, kDriftStream) {}

  Pose2 apply(const Pose2& truth, double driven) {
    const double pull = std::exp(-driven / 10.0), spread = std::sqrt(driven);
    x_ = pull * x_ + 0.5 * bound_ * spread * rng_.normal();
    y_ = pull * y_ + 0.5 * bound_ * spread * rng_.normal();
    theta_ = std::clamp(pull * theta_ + 0.5 * angle_bound_ * spread * rng_.normal(), -angle_bound_, angle_bound_);
    const double length = std::hypot(x_, y_);
    if (length > bound_) x_ *= bound_ / length, y_ *= bound_ / length;
    return {truth.x + x_, truth.y + y_, truth.theta + theta_};
  }

 private:
  double bound_, angle_bound_;
  SeededRandom rng_;
  double x_ = 0.0, y_ = 0.0, theta_ = 0.0;
};

// A drivable cell of the largest 4-connected drivable region (of equal ones, the first in raster
// order: OpenCV's label numbers depend on its thread count), drawn by the seed.
Point2 start_position(const SimulatedWorld& w, std::uint32_t seed) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(w.drivable, labels, stats, centroids, 4, CV_32S);
  std::vector<char> met(static_cast<std::size_t>(n), 0);
  int best = 0;
  for (auto it = labels.begin<int>(); it != labels.end<int>(); ++it) {
    const int i = *it;
    if (i == 0 || met[static_cast<std::size_t>(i)]) continue;
    met[static_cast<std::size_t>(i)] = 1;
    if (best == 0 || stats.at<int>(i, cv::CC_STAT_AREA) > stats.at<int>(best, cv::CC_STAT_AREA)) best = i;
  }
  if (best == 0) throw Error("the plan's rooms leave the robot nowhere to stand (try a smaller --robot-radius)");
  SeededRandom rng(seed, kStartStream);
  std::uint64_t k = rng.below(static_cast<std::uint64_t>(stats.at<int>(best, cv::CC_STAT_AREA)));
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (labels.at<int>(r, c) == best && k-- == 0) return cell_center_world(w.world, c, r);
  throw Error("internal: no start cell drawn");
}

// Drives the Explorer through the world and maps every scan of the lidar (range, step drawn per
// seed) from drifting pose estimates into hit and miss counts.
void explore_and_map(const SimulatedWorld& w, const SimulatedMapOptions& o, std::uint32_t seed, SimulatedMap& out) {
  ExplorationOptions explore;
  explore.range = o.explore_range;
  explore.step = o.scan_step;
  explore.max_scans = o.max_scans;
  explore.start = start_position(w, seed);
  Explorer explorer(w.world, w.drivable, explore);

  LaserSpec spec;
  spec.field_of_view = 2.0 * std::numbers::pi;
  spec.angular_resolution = out.angular_step;
  spec.range_max = out.range;
  // Noise is drawn here, not by the simulator: its std::normal_distribution differs between
  // standard libraries, and the maps must not.
  spec.noise_stddev = 0.0;
  const std::vector<double> angles = beam_angles(spec);
  SeededRandom noise(seed, kNoiseStream);
  PoseDrift drift(o.drift, o.drift_angle, seed);
  const double res = w.world.resolution;
  HitCounter counter(w.world.width(), w.world.height());
  Point2 last = *explore.start;
  while (explorer.next()) {
    const Pose2 truth = explorer.pose();
    const Pose2 believed = drift.apply(truth, std::hypot(truth.x - last.x, truth.y - last.y));
    last = {truth.x, truth.y};
    const SimulatedScan scan = simulate_scan(w.world, truth, spec);
    const double pu = (believed.x - w.world.origin.x) / res, pv = (believed.y - w.world.origin.y) / res;
    for (std::size_t i = 0; i < angles.size(); ++i) {
      const double a = believed.theta + angles[i];
      const bool hit = scan.hit[i] >= 0;
      const double range = hit ? scan.scan.ranges[i] + o.range_noise * noise.normal() : o.no_return_length;
      if (range <= 0.0) continue;
      counter.beam(pu, pv, std::cos(a), std::sin(a), range / res, hit);
    }
  }
  out.map.cells = counter.cells(o.occupied_ratio);
  out.scans = explorer.scans();
  out.path_length = explorer.path_length();
}

// People's rooms on the map's free cells: each free cell takes the room it lies in, or one within
// room_fill; then a cell 8-touching a room of a smaller label is cleared, so the rooms stay apart
// for an 8-connected flood fill.
cv::Mat carry_rooms(const cv::Mat& rooms, const cv::Mat& map_cells, double fill_cells) {
  cv::Mat out = cv::Mat::zeros(rooms.size(), CV_32SC1);
  rooms.copyTo(out, map_cells == kFree);
  if (fill_cells > 0.0 && cv::countNonZero(rooms) > 0) {
    cv::Mat distance, nearest;
    cv::distanceTransform((rooms == 0), distance, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
    std::vector<int> room_of(static_cast<std::size_t>(rooms.total()) + 1, 0);
    for (int r = 0; r < rooms.rows; ++r)
      for (int c = 0; c < rooms.cols; ++c)
        if (rooms.at<int>(r, c) > 0) room_of[static_cast<std::size_t>(nearest.at<int>(r, c))] = rooms.at<int>(r, c);
    for (int r = 0; r < rooms.rows; ++r)
      for (int c = 0; c < rooms.cols; ++c)
        if (out.at<int>(r, c) == 0 && map_cells.at<unsigned char>(r, c) == kFree && distance.at<float>(r, c) <= fill_cells)
          out.at<int>(r, c) = room_of[static_cast<std::size_t>(nearest.at<int>(r, c))];
  }
  const cv::Mat before = out.clone();
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c) {
      const int room = before.at<int>(r, c);
      if (room == 0) continue;
      for (int dr = -1; dr <= 1 && out.at<int>(r, c) != 0; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int nr = r + dr, nc = c + dc;
          if (nr < 0 || nc < 0 || nr >= out.rows || nc >= out.cols) continue;
          const int other = before.at<int>(nr, nc);
          if (other != 0 && other < room) {
            out.at<int>(r, c) = 0;
            break;
          }
        }
    }
  return out;
}

// rooms renumbered 1..N in raster order of their first cells, and the input's label of each (index
// 0 unused): what is drawn per room, and which of two touching rooms gives way, then depends on the
// rooms themselves, not on how they were numbered (OpenCV's parallel labelling numbers them by its
// thread count).
cv::Mat canonical_rooms(const cv::Mat& rooms, std::vector<int>& original) {
  std::map<int, int> number;
  original.assign(1, 0);
  cv::Mat out(rooms.size(), CV_32SC1);
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c) {
      const int room = rooms.at<int>(r, c);
      int& mine = out.at<int>(r, c);
      if (room == 0) {
        mine = 0;
        continue;
      }
      const auto [it, added] = number.emplace(room, static_cast<int>(original.size()));
      if (added) original.push_back(room);
      mine = it->second;
    }
  return out;
}

// seed mixed with a hash of the plan's cells (FNV-1a), through std::seed_seq (fixed by the standard).
std::uint32_t plan_seed(const OccupancyGrid& plan, std::uint32_t seed) {
  std::uint32_t hash = 2166136261u;
  auto add = [&](std::uint32_t byte) { hash = (hash ^ byte) * 16777619u; };
  for (int r = 0; r < plan.height(); ++r) {
    const unsigned char* row = plan.cells.ptr<unsigned char>(r);
    for (int c = 0; c < plan.width(); ++c) add(row[c]);
    add(0xffu);
  }
  std::seed_seq sequence{seed, hash};
  std::uint32_t mixed = 0;
  sequence.generate(&mixed, &mixed + 1);
  return mixed;
}

}  // namespace

SimulatedMap simulate_map(const OccupancyGrid& plan, const cv::Mat& rooms, const SimulatedMapOptions& options,
                          std::uint32_t seed) {
  validate(plan);
  validate(options);
  if (rooms.type() != CV_32SC1) throw Error("the room labels must be 32-bit integers (0 = no room)");
  if (rooms.size() != plan.cells.size())
    throw Error("the ground truth (" + std::to_string(rooms.cols) + " x " + std::to_string(rooms.rows) +
                ") differs in size from the plan (" + std::to_string(plan.width()) + " x " + std::to_string(plan.height()) + ")");
  double low = 0.0, high = 0.0;
  cv::minMaxLoc(rooms, &low, &high);
  if (low < 0) throw Error("the room labels must not be negative");

  // The seed's draws also depend on the plan, so that a folder converted with seeds 1..N does not
  // give every plan the same N sensors.
  seed = plan_seed(plan, seed);
  std::vector<int> original;
  SimulatedWorld world = build_simulated_world(plan, canonical_rooms(rooms, original), options, seed);
  SimulatedMap out;
  SeededRandom sensor(seed, kSensorStream);
  out.range = sensor.uniform(options.range_from, options.range_to);
  out.angular_step = sensor.uniform(options.angular_step_from, options.angular_step_to);
  out.map.resolution = world.world.resolution;
  out.map.origin = world.world.origin;
  explore_and_map(world, options, seed, out);
  out.rooms = carry_rooms(world.rooms, out.map.cells, options.room_fill / plan.resolution);
  for (auto it = out.rooms.begin<int>(); it != out.rooms.end<int>(); ++it) *it = original[static_cast<std::size_t>(*it)];
  out.offset = world.offset;
  out.wall_change = world.wall_change;
  out.doors = world.doors;
  out.closed_doors = world.closed_doors;
  out.windows = world.windows;
  out.world = std::move(world.world);
  out.drivable = std::move(world.drivable);
  out.exterior = std::move(world.exterior);
  out.glass = std::move(world.glass);
  return out;
}

cv::Mat map_image(const SimulatedMap& simulated) {
  cv::Mat image(simulated.map.cells.size(), CV_8UC1, cv::Scalar(205));
  image.setTo(0, simulated.map.cells == kOccupied);
  image.setTo(255, simulated.map.cells == kFree);
  return image;
}

cv::Mat world_image(const SimulatedMap& simulated) {
  cv::Mat image = cv::Mat::zeros(simulated.world.cells.size(), CV_8UC1);
  image.setTo(160, simulated.world.cells == kFree);
  image.setTo(230, (simulated.world.cells == kFree) & (simulated.exterior == 0) & (simulated.glass == 0));
  image.setTo(255, simulated.drivable);
  image.setTo(90, simulated.glass);
  return image;
}

cv::Mat rooms_image(const SimulatedMap& simulated) {
  cv::Mat image = cv::Mat::zeros(simulated.rooms.size(), CV_8UC1);
  image.setTo(255, simulated.rooms > 0);
  return image;
}

}  // namespace topocut
