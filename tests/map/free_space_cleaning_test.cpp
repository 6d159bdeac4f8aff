// The real-map front end on a synthetic SLAM map whose every feature is known: laser rays through a
// window into the unknown go, a narrow walled corridor and a doorway stay, obstacle specks become
// floor, thin space between unknown blocks inside a room is removed but stays in the building.
#include <array>
#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/map/free_space_cleaning.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

struct Synthetic {
  cv::Mat cells;
  cv::Rect corridor, room_a, room_b, speck, gap;
  std::vector<cv::Point> ray_cells;  // free cells of the rays beyond the wall
};

// 300 x 200 cells of unknown; two walled 5 m rooms joined by a 0.5 m x 2 m walled corridor; five
// one-cell rays fanning up out of a window in room A's top wall; a 2 x 2 obstacle in room A; a
// 0.1 m free gap between two unknown blocks (partly seen cupboards, 0.4 x 0.9 m) inside room B.
Synthetic synthetic_map() {
  Synthetic s;
  s.cells = cv::Mat(200, 300, CV_8UC1, cv::Scalar(kUnknown));
  s.room_a = {20, 80, 100, 100};
  s.room_b = {160, 80, 100, 100};
  s.corridor = {120, 125, 40, 10};
  for (const cv::Rect& r : {s.room_a, s.room_b, s.corridor}) {
    cv::rectangle(s.cells, cv::Rect(r.x - 1, r.y - 1, r.width + 2, r.height + 2), cv::Scalar(kOccupied), cv::FILLED);
  }
  for (const cv::Rect& r : {s.room_a, s.room_b, s.corridor}) s.cells(r).setTo(kFree);
  // The window: a 20-cell gap in room A's top wall, rays fanning from its middle.
  s.cells(cv::Rect(60, 79, 20, 1)).setTo(kFree);
  for (int k = -2; k <= 2; ++k) {
    for (int t = 1; t <= 60; ++t) {
      const cv::Point p(70 + k * t / 4, 79 - t);
      if (p.y < 0) break;
      s.cells.at<unsigned char>(p) = kFree;
      s.ray_cells.push_back(p);
    }
  }
  s.speck = {50, 120, 2, 2};
  s.cells(s.speck).setTo(kOccupied);
  // Two unknown blocks 2 cells apart, against room B's bottom wall.
  s.cells(cv::Rect(200, 162, 8, 18)).setTo(kUnknown);
  s.cells(cv::Rect(210, 162, 8, 18)).setTo(kUnknown);
  s.gap = {208, 166, 2, 14};  // the gap below the floor's margin
  return s;
}

int count(const cv::Mat& mask) { return cv::countNonZero(mask); }

TEST(CleanFreeSpace, RaysGoCorridorsAndDoorsStay) {
  const Synthetic s = synthetic_map();
  const CleanedFreeSpace c = clean_free_space(s.cells == kFree, s.cells, kRes);
  ASSERT_EQ(c.floor.size(), s.cells.size());
  // The 0.5 m corridor is narrower than the 0.6 m disc but walled in: it stays, whole.
  EXPECT_EQ(count(c.floor(s.corridor)), s.corridor.area());
  // The rooms stay (their corners too), but for the cells around the unknown blocks.
  EXPECT_EQ(count(c.floor(s.room_a)), s.room_a.area());
  EXPECT_EQ(count(c.floor(s.room_b)), s.room_b.area() - 2 * 8 * 18 - s.gap.area());
  // Every ray cell beyond the wall is removed, outside the building; only the rays' roots within
  // the floor's margin (min_width / 4 beyond the disc's reach, here 3 cells) stay.
  for (const cv::Point& p : s.ray_cells) {
    if (p.y >= 73) continue;
    EXPECT_EQ(c.floor.at<unsigned char>(p), 0) << p;
    EXPECT_EQ(c.removed.at<unsigned char>(p), kCellRemovedOutside) << p;
  }
  // The obstacle speck is floor for the decomposition.
  EXPECT_EQ(count(c.floor(s.speck)), 4);
  EXPECT_EQ(count(c.removed(s.speck) == kCellObstacleSpeck), 4);
  // The gap between the unknown blocks is thin and bounded by unknown: removed, but inside.
  EXPECT_EQ(count(c.floor(s.gap)), 0);
  EXPECT_EQ(count(c.removed(s.gap) == kCellRemovedInside), s.gap.area());
  EXPECT_EQ(c.removed_cells, count(c.removed >= kCellRemovedInside));
  EXPECT_EQ(c.outside_cells, count(c.removed == kCellRemovedOutside));
  // Floor is free space plus obstacle specks, nothing else.
  EXPECT_EQ(count(c.floor & ~((s.cells == kFree) | (c.removed == kCellObstacleSpeck))), 0);
}

TEST(CleanFreeSpace, EachStepCanBeSwitchedOff) {
  const Synthetic s = synthetic_map();
  FreeSpaceCleaningOptions off;
  off.max_obstacle_speck = 0.0;
  off.min_width = 0.0;
  const CleanedFreeSpace c = clean_free_space(s.cells == kFree, s.cells, kRes, off);
  EXPECT_EQ(count(c.floor != (s.cells == kFree)), 0);
  EXPECT_EQ(c.removed_cells, 0);
  FreeSpaceCleaningOptions no_inside;
  no_inside.inside_closing = 0.0;
  const CleanedFreeSpace d = clean_free_space(s.cells == kFree, s.cells, kRes, no_inside);
  EXPECT_EQ(count(d.removed(s.gap) == kCellRemovedOutside), s.gap.area());
}

// The definition of an obstacle speck, by a labelling of every non-free region of the window the
// cleaning works in (the free cells' box grown by 2 cells when the inside test is off).
cv::Mat specks_by_definition(const cv::Mat& free, int max_side) {
  const cv::Rect box = cv::boundingRect(free);
  const cv::Rect window = cv::Rect(box.x - 2, box.y - 2, box.width + 4, box.height + 4) & cv::Rect(0, 0, free.cols, free.rows);
  cv::Mat labels, stats, centroids;
  const cv::Mat region = free(window) == 0;
  const int n = cv::connectedComponentsWithStats(region, labels, stats, centroids, 8, CV_32S);
  cv::Mat specks = cv::Mat::zeros(free.size(), CV_8UC1);
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    if (x > 0 && y > 0 && x + w < window.width && y + h < window.height && w <= max_side && h <= max_side)
      specks(window).setTo(255, labels == i);
  }
  return specks;
}

TEST(CleanFreeSpace, ObstacleSpecksAreTheSmallEnclosedNonFreeRegions) {
  // Rooms peppered with obstacles of every size and shape (diagonal chains, L shapes, clusters
  // touching the walls), at several densities: the cleaning's specks are exactly the definition's.
  cv::RNG rng(7);
  for (int trial = 0; trial < 12; ++trial) {
    cv::Mat cells(120, 160, CV_8UC1, cv::Scalar(kUnknown));
    cells(cv::Rect(10 + trial, 8, 130, 100)).setTo(kFree);
    const int obstacles = 40 + 60 * trial;
    for (int k = 0; k < obstacles; ++k) {
      const cv::Point p(rng.uniform(8, 152), rng.uniform(6, 112));
      const int kind = rng.uniform(0, 3);
      if (kind == 0) cells.at<unsigned char>(p) = kOccupied;
      if (kind == 1) cv::line(cells, p, p + cv::Point(rng.uniform(-8, 9), rng.uniform(-8, 9)), cv::Scalar(kOccupied));
      if (kind == 2) cells(cv::Rect(p, cv::Size(rng.uniform(1, 8), rng.uniform(1, 8))) & cv::Rect(0, 0, 160, 120)).setTo(kUnknown);
    }
    FreeSpaceCleaningOptions only_specks;
    only_specks.min_width = 0.0;
    only_specks.inside_closing = 0.0;
    const CleanedFreeSpace c = clean_free_space(cells == kFree, cells, kRes, only_specks);
    const cv::Mat expected = specks_by_definition(cells == kFree, 6);  // 0.3 m at 0.05 m a cell
    EXPECT_GT(count(expected), 0) << "trial " << trial;
    EXPECT_EQ(count((c.removed == kCellObstacleSpeck) != expected), 0) << "trial " << trial;
  }
}

// The cleaning as its definition reads, with OpenCV on whole images: specks by a labelling of the
// non-free regions, the thick part as an opening with OpenCV's elliptic disc and a margin of 3 x 3
// dilations, rays by a labelling of the thin part, the inside test as a square closing and a
// flood fill from a frame around the window.
struct Reference {
  cv::Mat floor, removed;
};

Reference reference_cleaning(const cv::Mat& free, const cv::Mat& cells, double resolution, const FreeSpaceCleaningOptions& o) {
  Reference out{cv::Mat::zeros(free.size(), CV_8UC1), cv::Mat::zeros(free.size(), CV_8UC1)};
  const cv::Rect box = cv::boundingRect(free);
  if (box.empty()) return out;
  const int margin = static_cast<int>(std::lround(o.inside_closing / resolution)) + 2;
  const cv::Rect window = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
                          cv::Rect(0, 0, free.cols, free.rows);
  const cv::Mat f = free(window) != 0, c = cells(window);
  cv::Mat specks = cv::Mat::zeros(f.size(), CV_8UC1);
  const int max_side = static_cast<int>(std::lround(o.max_obstacle_speck / resolution));
  cv::Mat labels, stats, centroids;
  const int regions = cv::connectedComponentsWithStats(f == 0, labels, stats, centroids, 8, CV_32S);
  for (int i = 1; i < regions && max_side > 0; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    if (x > 0 && y > 0 && x + w < f.cols && y + h < f.rows && w <= max_side && h <= max_side) specks.setTo(255, labels == i);
  }
  const cv::Mat solid = f | specks;
  const double radius = o.min_width / resolution / 2.0;
  cv::Mat thick = solid.clone();
  if (radius > 0.5) {
    const int r = std::max(1, static_cast<int>(std::lround(radius)));
    cv::morphologyEx(solid, thick, cv::MORPH_OPEN, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}),
                     cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    for (int i = 0; i < static_cast<int>(std::ceil(radius / 2.0)); ++i) {
      cv::dilate(thick, thick, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
      thick &= solid;
    }
  }
  const cv::Mat thin = solid & ~thick;
  cv::Mat rays = cv::Mat::zeros(f.size(), CV_8UC1);
  const int parts = cv::connectedComponents(thin, labels, 8, CV_32S);
  std::vector<long> unknown(static_cast<std::size_t>(parts), 0), occupied(static_cast<std::size_t>(parts), 0);
  cv::Mat framed;  // the window's cells with a frame of unknown around them
  cv::copyMakeBorder(c, framed, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(kUnknown));
  for (int y = 0; y < f.rows; ++y) {
    for (int x = 0; x < f.cols; ++x) {
      const int l = labels.at<int>(y, x);
      if (l == 0) continue;
      for (const cv::Point d : {cv::Point(0, -1), cv::Point(0, 1), cv::Point(-1, 0), cv::Point(1, 0)}) {
        const unsigned char state = framed.at<unsigned char>(y + 1 + d.y, x + 1 + d.x);
        unknown[static_cast<std::size_t>(l)] += state == kUnknown;
        occupied[static_cast<std::size_t>(l)] += state == kOccupied;
      }
    }
  }
  for (int l = 1; l < parts; ++l)
    if (unknown[static_cast<std::size_t>(l)] > occupied[static_cast<std::size_t>(l)]) rays.setTo(255, labels == l);
  const cv::Mat floor = solid & ~rays, lost = f & ~floor;
  cv::Mat removed = cv::Mat::zeros(f.size(), CV_8UC1);
  removed.setTo(kCellObstacleSpeck, specks & floor);
  removed.setTo(kCellRemovedOutside, lost);
  if (o.inside_closing > 0.0 && cv::countNonZero(lost) > 0) {
    const int n = std::max(1, static_cast<int>(std::lround(o.inside_closing / resolution / 2.0)));
    const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, {2 * n + 1, 2 * n + 1});
    cv::Mat closed;
    cv::dilate(floor | (c == kOccupied), closed, square, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::erode(closed, closed, square, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(255));
    cv::Mat outside;
    cv::copyMakeBorder(~closed, outside, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(255));
    cv::floodFill(outside, cv::Point(0, 0), cv::Scalar(0), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
    removed.setTo(kCellRemovedInside, (closed | (outside(cv::Rect(1, 1, f.cols, f.rows)) != 0)) & lost);
  }
  floor.copyTo(out.floor(window));
  removed.copyTo(out.removed(window));
  return out;
}

// A SLAM-like map: unknown around walled rooms (some walls missing), laser rays fanning out of
// gaps, clutter of occupied and unknown specks and blocks, free specks in the unknown.
cv::Mat slam_like_map(cv::RNG& rng) {
  const int rows = rng.uniform(150, 260), cols = rng.uniform(150, 260);
  cv::Mat cells(rows, cols, CV_8UC1, cv::Scalar(kUnknown));
  for (int k = rng.uniform(2, 6); k > 0; --k) {
    const cv::Rect room = cv::Rect(rng.uniform(10, cols - 60), rng.uniform(10, rows - 60), rng.uniform(20, 90), rng.uniform(20, 90)) &
                          cv::Rect(0, 0, cols, rows);
    cv::rectangle(cells, room, cv::Scalar(kOccupied), 1);
    cells(cv::Rect(room.x + 1, room.y + 1, room.width - 2, room.height - 2)).setTo(kFree);
    const cv::Point gap(room.x + rng.uniform(2, room.width - 8), room.y);
    cells(cv::Rect(gap, cv::Size(rng.uniform(2, 7), 1)) & cv::Rect(0, 0, cols, rows)).setTo(kFree);
    for (int ray = rng.uniform(0, 6); ray > 0; --ray)
      cv::line(cells, gap, gap + cv::Point(rng.uniform(-40, 41), -rng.uniform(5, 60)), cv::Scalar(kFree));
  }
  for (int k = rng.uniform(20, 200); k > 0; --k) {
    const cv::Point p(rng.uniform(0, cols), rng.uniform(0, rows));
    const unsigned char state = std::array<unsigned char, 3>{kOccupied, kUnknown, kFree}[static_cast<std::size_t>(rng.uniform(0, 3))];
    cells(cv::Rect(p, cv::Size(rng.uniform(1, 9), rng.uniform(1, 9))) & cv::Rect(0, 0, cols, rows)).setTo(state);
  }
  return cells;
}

TEST(CleanFreeSpace, IsTheDefinitionCellForCell) {
  // Random maps at resolutions that give discs of radius 2 to 16 cells and closings of 5 to 54.
  cv::RNG rng(11);
  long specks = 0, inside = 0, outside = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const cv::Mat cells = slam_like_map(rng);
    for (const double resolution : {0.15, 0.05, 0.037, 0.025, 0.0185}) {
      FreeSpaceCleaningOptions options;
      if (trial == 9) options.max_obstacle_speck = 0.0;
      const cv::Mat free = cells == kFree;
      const CleanedFreeSpace c = clean_free_space(free, cells, resolution, options);
      const Reference r = reference_cleaning(free, cells, resolution, options);
      EXPECT_EQ(count(c.floor != r.floor), 0) << "trial " << trial << ", " << resolution << " m";
      EXPECT_EQ(count(c.removed != r.removed), 0) << "trial " << trial << ", " << resolution << " m";
      EXPECT_EQ(c.removed_cells, count(r.removed >= kCellRemovedInside));
      EXPECT_EQ(c.outside_cells, count(r.removed == kCellRemovedOutside));
      EXPECT_EQ(c.speck_cells, count(r.removed == kCellObstacleSpeck));
      EXPECT_EQ(count(c.removed) + count(c.floor), count(c.removed(c.window)) + count(c.floor(c.window)));
      specks += count(r.removed == kCellObstacleSpeck);
      inside += c.removed_cells - c.outside_cells;
      outside += c.outside_cells;
    }
  }
  // The maps have every kind of cell the cleaning tells apart.
  EXPECT_GT(specks, 0);
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
}

TEST(CleanFreeSpace, CellsAfterCleaningAsTheLabellingSeesThem) {
  Synthetic s = synthetic_map();
  const cv::Rect unseen(30, 100, 2, 1);  // unknown cells in room A: a speck
  s.cells(unseen).setTo(kUnknown);
  const CleanedFreeSpace c = clean_free_space(s.cells == kFree, s.cells, kRes);
  const cv::Mat after = cells_after_cleaning(s.cells, c);
  EXPECT_EQ(count(after != s.cells), c.outside_cells + 2);
  EXPECT_EQ(count((c.removed == kCellRemovedOutside) & (after != kUnknown)), 0);
  EXPECT_EQ(count(after(unseen) == kFree), 2);
  EXPECT_EQ(count(after(s.speck) == kOccupied), 4);  // the occupied speck stays an obstacle
  // Nothing to change: the cells themselves.
  FreeSpaceCleaningOptions off;
  off.max_obstacle_speck = 0.0;
  off.min_width = 0.0;
  EXPECT_EQ(cells_after_cleaning(s.cells, clean_free_space(s.cells == kFree, s.cells, kRes, off)).data, s.cells.data);
}

TEST(CleanFreeSpace, BadInputIsAnError) {
  const cv::Mat cells(10, 10, CV_8UC1, cv::Scalar(kFree));
  EXPECT_THROW(clean_free_space(cv::Mat(), cells, kRes), Error);
  EXPECT_THROW(clean_free_space(cells == kFree, cv::Mat(5, 5, CV_8UC1), kRes), Error);
  EXPECT_THROW(clean_free_space(cells == kFree, cells, 0.0), Error);
  FreeSpaceCleaningOptions bad;
  bad.min_width = -1.0;
  EXPECT_THROW(clean_free_space(cells == kFree, cells, kRes, bad), Error);
}

TEST(CleanFreeSpace, PictureShowsWhatWasRemoved) {
  const Synthetic s = synthetic_map();
  const CleanedFreeSpace c = clean_free_space(s.cells == kFree, s.cells, kRes);
  const cv::Mat picture = render_cleaned_map(s.cells, c);
  ASSERT_EQ(picture.type(), CV_8UC3);
  EXPECT_EQ(picture.at<cv::Vec3b>(s.room_a.y + 5, s.room_a.x + 5), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(picture.at<cv::Vec3b>(s.ray_cells.back()), cv::Vec3b(40, 40, 220));
  EXPECT_EQ(picture.at<cv::Vec3b>(s.gap.y + 5, s.gap.x), cv::Vec3b(40, 160, 250));
  EXPECT_EQ(picture.at<cv::Vec3b>(s.speck.y, s.speck.x), cv::Vec3b(235, 200, 120));
}

}  // namespace
}  // namespace topocut
