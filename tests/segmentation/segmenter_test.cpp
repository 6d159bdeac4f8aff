#include "topocut/segmentation/segmenter.h"

#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <opencv2/imgcodecs.hpp>

#include "topocut/core/error.h"
#include "topocut/decomposition/ring_intersections.h"
#include "topocut/map/simplify.h"

namespace topocut {
namespace {

// The segmentation module does not depend on io, so maps are read here with OpenCV directly:
// grey > 250 free, < 50 occupied, otherwise unknown (the bundled maps use 254 / 0 / 205).
OccupancyGrid read_map(const std::string& path) {
  const cv::Mat grey = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (grey.empty()) throw Error("test map missing: " + path);
  OccupancyGrid grid{cv::Mat(grey.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  grid.cells.setTo(kFree, grey > 250);
  grid.cells.setTo(kOccupied, grey < 50);
  return grid;
}

std::string bundled(const std::string& name) { return std::string(TOPOCUT_SOURCE_DIR "/maps/") + name + ".png"; }

// Invariants every segmentation must satisfy, whatever the decomposition did.
void expect_consistent(const OccupancyGrid& grid, const Segmentation& s) {
  ASSERT_EQ(s.labels.type(), CV_32SC1);
  ASSERT_EQ(s.labels.size(), grid.cells.size());
  EXPECT_EQ(s.resolution, grid.resolution);
  EXPECT_EQ(s.origin, grid.origin);
  // Every free cell has a room; nothing else has one.
  EXPECT_EQ(cv::countNonZero((s.labels > 0) != (grid.cells == kFree)), 0);
  double low = 0, high = 0;
  cv::minMaxLoc(s.labels, &low, &high);
  EXPECT_EQ(low, 0.0);
  ASSERT_EQ(static_cast<std::size_t>(high), s.rooms.size());
  double total = 0.0;
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    const Room& room = s.rooms[i];
    EXPECT_EQ(room.id, static_cast<int>(i) + 1);
    const int cells = cv::countNonZero(s.labels == room.id);
    EXPECT_GT(cells, 0);
    EXPECT_NEAR(room.labelled_area, cells * grid.resolution * grid.resolution, 1e-9);
    EXPECT_GE(room.polygon.outer.size(), 3u);
    EXPECT_NEAR(room.area, area(room.polygon), 1e-9);  // every output's "area" is the polygon's
    total += room.labelled_area;
  }
  EXPECT_NEAR(total, cv::countNonZero(grid.cells == kFree) * grid.resolution * grid.resolution, 1e-6);
  // Ids follow the raster order of each room's first cell.
  int next = 1;
  for (int r = 0; r < s.labels.rows; ++r)
    for (int c = 0; c < s.labels.cols; ++c) {
      const int l = s.labels.at<int>(r, c);
      if (l >= next) {
        EXPECT_EQ(l, next);
        next = l + 1;
      }
    }
  for (const Passage& p : s.passages) {
    EXPECT_LT(p.room_a, p.room_b);
    EXPECT_GE(p.room_a, 1);
    EXPECT_LE(p.room_b, static_cast<int>(s.rooms.size()));
    EXPECT_NEAR(p.width, distance(p.cut.a, p.cut.b), 1e-9);
  }
}

// The baseline on the raw free space: one room per component, no cleaning either.
SegmentOptions trivial() {
  SegmentOptions options;
  options.decompose = false;
  options.clean = false;
  return options;
}

TEST(Segment, TrivialModeOneRoomPerComponentNumberedByFirstCell) {
  OccupancyGrid grid{cv::Mat(60, 80, CV_8UC1, cv::Scalar(kOccupied)), 0.1, {-2.0, 1.0}};
  grid.cells(cv::Rect(40, 5, 30, 20)).setTo(kFree);   // first cell (40, 5): room 1
  grid.cells(cv::Rect(5, 10, 20, 40)).setTo(kFree);   // first cell (5, 10): room 2
  grid.cells(cv::Rect(45, 40, 10, 10)).setTo(kFree);  // 1 m²: room 3
  grid.cells(cv::Rect(30, 20, 2, 2)).setTo(kFree);    // 0.04 m² speck: joins the nearest room
  grid.cells(cv::Rect(60, 45, 5, 5)).setTo(kUnknown);
  const Segmentation s = segment(grid, trivial());
  expect_consistent(grid, s);
  ASSERT_EQ(s.rooms.size(), 3u);
  EXPECT_EQ(s.labels.at<int>(5, 40), 1);
  EXPECT_EQ(s.labels.at<int>(10, 5), 2);
  EXPECT_EQ(s.labels.at<int>(40, 45), 3);
  EXPECT_EQ(s.labels.at<int>(20, 30), 2);  // the speck is 6 cells from room 2, 9 from room 1
  EXPECT_EQ(s.labels.at<int>(47, 62), 0);  // unknown
  EXPECT_TRUE(s.passages.empty());
  // Room 3: cells 45..54 x 40..49; centroid at the middle of the block in world metres.
  EXPECT_NEAR(s.rooms[2].labelled_area, 1.0, 1e-9);
  EXPECT_NEAR(s.rooms[2].area, 1.0, 1e-9);
  EXPECT_NEAR(s.rooms[2].centroid.x, -2.0 + 50 * 0.1, 1e-9);
  EXPECT_NEAR(s.rooms[2].centroid.y, 1.0 + (60 - 45) * 0.1, 1e-9);
  // Its polygon is the block's outline in metres: x -2 + 4.5 .. -2 + 5.5, y 1 + 1.0 .. 1 + 2.0.
  EXPECT_NEAR(area(s.rooms[2].polygon), 1.0, 1e-9);
  for (const Point2& v : s.rooms[2].polygon.outer) {
    EXPECT_TRUE(std::abs(v.x - 2.5) < 1e-9 || std::abs(v.x - 3.5) < 1e-9) << v.x;
    EXPECT_TRUE(std::abs(v.y - 2.0) < 1e-9 || std::abs(v.y - 3.0) < 1e-9) << v.y;
  }
}

// Free cells of the rectangles (x, y, width, height in cells) on an occupied 0.05 m grid.
OccupancyGrid plan(cv::Size size, std::initializer_list<cv::Rect> free) {
  OccupancyGrid grid{cv::Mat(size, CV_8UC1, cv::Scalar(kOccupied)), 0.05, {0.0, 0.0}};
  for (const cv::Rect& r : free) grid.cells(r).setTo(kFree);
  return grid;
}

TEST(Segment, WallLinesSeparateARoomOpenAcrossItsWidthAndSplitNoRoomOfEvenWidth) {
  SegmentOptions options;
  options.doors.wall_lines = true;
  // A 3.5 m x 4 m room on top of an 8 m x 6 m room, flush with its right wall, joined across the
  // narrow room's whole width: two rooms, each rectangle one of them.
  const OccupancyGrid two = plan({180, 220}, {cv::Rect(10, 10, 160, 120), cv::Rect(100, 130, 70, 80)});
  const Segmentation s = segment(two, options);
  expect_consistent(two, s);
  ASSERT_EQ(s.rooms.size(), 2u);
  const int wide = s.labels.at<int>(60, 50), narrow = s.labels.at<int>(180, 130);
  EXPECT_NE(wide, narrow);
  EXPECT_EQ(cv::countNonZero(s.labels(cv::Rect(10, 10, 160, 120)) == wide), 160 * 120);
  EXPECT_EQ(cv::countNonZero(s.labels(cv::Rect(100, 130, 70, 80)) == narrow), 70 * 80);
  // An L-shaped corridor 2 m wide, 10 m a leg, and a straight 20 m one: one room each; the wall
  // lines at the inner corner cross the corridor at its own width and are merged away.
  const OccupancyGrid bent = plan({240, 240}, {cv::Rect(10, 10, 200, 40), cv::Rect(10, 50, 40, 160)});
  EXPECT_EQ(segment(bent, options).rooms.size(), 1u);
  const OccupancyGrid straight = plan({420, 60}, {cv::Rect(10, 10, 400, 40)});
  EXPECT_EQ(segment(straight, options).rooms.size(), 1u);
}

TEST(Segment, DefaultModeKeepsTheInvariants) {
  const OccupancyGrid grid = read_map(bundled("floorplan"));
  const Segmentation s = segment(grid);
  expect_consistent(grid, s);
  EXPECT_GE(s.rooms.size(), 1u);
}

TEST(Segment, UnknownAroundTheMapChangesNoRoom) {
  // The same map with 300 / 200 / 150 / 250 more unknown cells on its four sides (origin moved so
  // that it stays in place): segment() works on the known cells' box, so rooms, labels and
  // passages are the same, and the labels outside are 0.
  const OccupancyGrid grid = read_map(bundled("furnished"));
  const int left = 300, top = 200, right = 150, bottom = 250;
  OccupancyGrid wide;
  cv::copyMakeBorder(grid.cells, wide.cells, top, bottom, left, right, cv::BORDER_CONSTANT, cv::Scalar(kUnknown));
  wide.resolution = grid.resolution;
  wide.origin = {grid.origin.x - left * grid.resolution, grid.origin.y - bottom * grid.resolution};
  const Segmentation s = segment(grid), w = segment(wide);
  expect_consistent(wide, w);
  const cv::Rect inner(left, top, grid.width(), grid.height());
  EXPECT_EQ(cv::countNonZero(w.labels(inner) != s.labels), 0);
  EXPECT_EQ(cv::countNonZero(w.labels), cv::countNonZero(s.labels));
  ASSERT_EQ(w.rooms.size(), s.rooms.size());
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    EXPECT_NEAR(w.rooms[i].area, s.rooms[i].area, 1e-9);
    EXPECT_NEAR(w.rooms[i].centroid.x, s.rooms[i].centroid.x, 1e-6);
    EXPECT_NEAR(w.rooms[i].centroid.y, s.rooms[i].centroid.y, 1e-6);
  }
  ASSERT_EQ(w.passages.size(), s.passages.size());
  for (std::size_t i = 0; i < s.passages.size(); ++i) {
    EXPECT_EQ(w.passages[i].room_a, s.passages[i].room_a);
    EXPECT_EQ(w.passages[i].room_b, s.passages[i].room_b);
    EXPECT_NEAR(w.passages[i].width, s.passages[i].width, 1e-6);
  }
  // What the cleaning saw comes back at the whole map's size, for --out-clean.
  SegmentationInput input;
  segment(wide, {}, &input);
  EXPECT_EQ(input.cleaned.removed.size(), wide.cells.size());
  EXPECT_EQ(input.labelled.cells.size(), wide.cells.size());
  const cv::Rect box = segmentation_box(wide, {});
  EXPECT_LT(box.area(), wide.cells.total() / 2);
  EXPECT_TRUE((box & inner) == inner);
}

TEST(Segment, ARingWhoseSimplificationCrossesStaysExactAndTheRestIsSimplified) {
  // The outer ring has a 0.9-cell bump that a 1-cell simplification straightens away, and hole 0
  // sits in the bump across the straightened edge; hole 1 is a staircase far from both. Before,
  // the whole component fell back to its exact polygon; now only the crossing pair does.
  PolygonWithHoles exact{{{0, 0}, {100, 0}, {100, 100}, {51, 100}, {51, 100.9}, {50, 100.9}, {50, 100}, {0, 100}}, {}};
  exact.holes.push_back({{50.2, 99.5}, {50.2, 100.5}, {50.8, 100.5}, {50.8, 99.5}});
  Ring stairs{{20, 20}};
  for (int k = 1; k <= 20; ++k) {
    stairs.push_back({20.0 + k, 20.0 + k - 1});
    stairs.push_back({20.0 + k, 20.0 + k});
  }
  stairs.push_back({20, 40});
  std::reverse(stairs.begin(), stairs.end());  // holes run clockwise
  exact.holes.push_back(stairs);
  ASSERT_TRUE(intersecting_rings(exact).empty());
  ASSERT_FALSE(intersecting_rings(simplify_polygon(exact, 1.0)).empty());  // the case this is about
  const PolygonWithHoles p = simplified_where_valid(exact, 1.0);
  EXPECT_TRUE(intersecting_rings(p).empty());
  EXPECT_EQ(p.outer, exact.outer);
  EXPECT_EQ(p.holes[0], exact.holes[0]);
  EXPECT_LT(p.holes[1].size(), 6u);  // the staircase is a triangle again
  EXPECT_EQ(simplified_where_valid(exact, 0.0).holes[1], exact.holes[1]);
}

TEST(Segment, RobotRadiusShrinksPiecesButStillLabelsEveryFreeCell) {
  const OccupancyGrid grid = read_map(bundled("furnished"));
  SegmentOptions options = trivial();
  options.binarize.robot_radius = 0.5;  // closes the 0.9 m door: the offices come apart
  const Segmentation s = segment(grid, options);
  expect_consistent(grid, s);
  EXPECT_EQ(s.rooms.size(), 2u);
  EXPECT_EQ(segment(grid, trivial()).rooms.size(), 1u);
}

TEST(Segment, BundledMapsTrivialModeHasOneRoomPerComponent) {
  for (const char* name : {"floorplan", "corridor_l", "furnished"}) {
    SCOPED_TRACE(name);
    const OccupancyGrid grid = read_map(bundled(name));
    const Segmentation s = segment(grid, trivial());
    expect_consistent(grid, s);
    cv::Mat components;
    const int count = cv::connectedComponents(grid.cells == kFree, components, 8) - 1;
    EXPECT_EQ(static_cast<int>(s.rooms.size()), count);
  }
}

TEST(Segment, BormannMapTrivialMode) {
  const std::string path = std::string(TOPOCUT_SHARED_DIR "/datasets/bormann/lab_ipa_furnitures.png");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared Bormann dataset not found at " << path;
  const OccupancyGrid grid = read_map(path);
  const Segmentation s = segment(grid, trivial());
  expect_consistent(grid, s);
  // Components of at least the minimum component area once diagonal pinches are broken, counted
  // with OpenCV.
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(remove_diagonal_pinches(grid.cells == kFree), labels, stats, centroids, 4);
  const double min_cells = trivial().contours.min_component_area / (grid.resolution * grid.resolution);
  int big = 0;
  for (int i = 1; i < n; ++i) big += stats.at<int>(i, cv::CC_STAT_AREA) >= min_cells - 1e-9;
  EXPECT_EQ(static_cast<int>(s.rooms.size()), big);
}

TEST(Segment, SameInputSameOutput) {
  const OccupancyGrid grid = read_map(bundled("floorplan"));
  const Segmentation a = segment(grid);
  const Segmentation b = segment(grid);
  EXPECT_EQ(cv::countNonZero(a.labels != b.labels), 0);
  ASSERT_EQ(a.rooms.size(), b.rooms.size());
  for (std::size_t i = 0; i < a.rooms.size(); ++i) EXPECT_EQ(a.rooms[i].polygon, b.rooms[i].polygon);
  ASSERT_EQ(a.passages.size(), b.passages.size());
  for (std::size_t i = 0; i < a.passages.size(); ++i) EXPECT_EQ(a.passages[i].cut, b.passages[i].cut);
}

TEST(Segment, StagesComposeToSegment) {
  // The stages an incremental segmenter reuses give exactly what segment() gives.
  const OccupancyGrid grid = read_map(bundled("furnished"));
  const SegmentOptions options;
  const cv::Mat free = segmentation_free_space(grid, options);
  const FreeSpacePolygons polygons = free_space_polygons(free, grid.resolution, options.contours);
  PieceSet pieces;
  for (const FreeSpaceComponent& c : polygons.components) pieces.append(decompose_component(c, grid, options));
  const Segmentation staged = rooms_from_pieces(grid, pieces);
  EXPECT_EQ(cv::countNonZero(staged.labels != segment(grid, options).labels), 0);
  // Trivial mode hands back the component itself.
  SegmentOptions plain = options;
  plain.decompose = false;
  const PieceSet one = decompose_component(polygons.components[0], grid, plain);
  ASSERT_EQ(one.pieces.size(), 1u);
  EXPECT_EQ(one.pieces[0], polygons.components[0].polygon);
  EXPECT_TRUE(one.cuts.empty());
}

// A clock that advances by one at every reading: stage times count readings, so that overlapping
// stages (a stage timed inside another) would add up to more than the call took.
double ticks_read = 0.0;
double tick() { return ticks_read += 1.0; }

TEST(Segment, StageTimesCoverEveryStageOnceAndChangeNothing) {
  OccupancyGrid grid = read_map(bundled("furnished"));
  cv::copyMakeBorder(grid.cells, grid.cells, 30, 30, 30, 30, cv::BORDER_CONSTANT, cv::Scalar(kUnknown));  // the box path too
  SegmentTimes times;
  times.clock = tick;
  const double before = tick();
  const Segmentation timed = segment(grid, SegmentOptions{}, nullptr, &times);
  const double after = tick();
  EXPECT_EQ(cv::countNonZero(timed.labels != segment(grid).labels), 0);
  for (std::size_t k = 0; k < kSegmentStages; ++k) EXPECT_GT(times.ms[k], 0.0) << stage_name(static_cast<SegmentStage>(k));
  EXPECT_LE(times.total(), after - before);
  // Times add up over calls.
  const double once = times.total();
  segment(grid, SegmentOptions{}, nullptr, &times);
  EXPECT_GT(times.total(), once);
}

// A 10 m x 10 m L of 2 m wide corridor, walls one cell thick around it.
OccupancyGrid l_corridor() {
  OccupancyGrid grid{cv::Mat(202, 202, CV_8UC1, cv::Scalar(kOccupied)), 0.05, {}};
  grid.cells(cv::Rect(1, 161, 200, 40)).setTo(kFree);  // bottom arm
  grid.cells(cv::Rect(1, 1, 40, 200)).setTo(kFree);    // left arm
  return grid;
}

// Two 3 m x 3 m rooms side by side, 0.2 m wall, a 0.9 m door in it.
OccupancyGrid two_rooms_with_a_door() {
  OccupancyGrid grid{cv::Mat(62, 126, CV_8UC1, cv::Scalar(kOccupied)), 0.05, {}};
  grid.cells(cv::Rect(1, 1, 60, 60)).setTo(kFree);
  grid.cells(cv::Rect(65, 1, 60, 60)).setTo(kFree);
  grid.cells(cv::Rect(61, 21, 4, 18)).setTo(kFree);
  return grid;
}

TEST(Segment, AnLShapedCorridorIsOneRoomWhereDuDeAloneCutsIt) {
  const OccupancyGrid grid = l_corridor();
  const Segmentation s = segment(grid);
  expect_consistent(grid, s);
  ASSERT_EQ(s.rooms.size(), 1u);
  EXPECT_TRUE(s.passages.empty());
  // The merged room's polygon is the union of DuDe's pieces: the whole L (its cells' area, up to
  // the one-cell simplification of the outline), without holes.
  EXPECT_TRUE(s.rooms[0].polygon.holes.empty());
  EXPECT_NEAR(s.rooms[0].area, s.rooms[0].labelled_area, 0.02 * s.rooms[0].labelled_area);
  const Segmentation parity = segment(grid, parity_segment_options());
  expect_consistent(grid, parity);
  EXPECT_GE(parity.rooms.size(), 2u);
}

TEST(Segment, TwoRoomsJoinedByADoorAreTwoRoomsWithOnePassage) {
  const OccupancyGrid grid = two_rooms_with_a_door();
  const Segmentation s = segment(grid);
  expect_consistent(grid, s);
  ASSERT_EQ(s.rooms.size(), 2u);
  ASSERT_EQ(s.passages.size(), 1u);
  EXPECT_NEAR(s.passages[0].width, 0.9, 1e-9);
  // Each room holds one of the 3 m x 3 m squares (and a share of the door's frame).
  EXPECT_NE(s.labels.at<int>(30, 30), s.labels.at<int>(30, 95));
  for (const Room& room : s.rooms) {
    EXPECT_GE(room.labelled_area, 9.0 - 1e-9);
    EXPECT_LE(room.labelled_area, 9.0 + 4 * 18 * 0.0025 + 1e-9);
  }
  // The trivial baseline sees one component.
  EXPECT_EQ(segment(grid, trivial()).rooms.size(), 1u);
}

TEST(Segment, TwoRoomsBehindAFreeStandingWallAreRoomsOfTheirOwn) {
  // A 10 m x 6 m floor: a corridor (rows 5-44), two rooms (rows 49-124) split by a partition; the
  // partition misses the far wall by 0.2 m and the wall along the corridor misses both side walls by 1 m, so
  // the two are one free-standing T of wall and every door of the rooms leads round it.
  OccupancyGrid grid = plan({210, 130}, {cv::Rect(5, 5, 200, 120)});
  grid.cells(cv::Rect(25, 45, 160, 4)).setTo(kOccupied);
  grid.cells(cv::Rect(103, 49, 4, 72)).setTo(kOccupied);
  const Segmentation s = segment(grid);
  expect_consistent(grid, s);
  ASSERT_EQ(s.rooms.size(), 3u);
  const int corridor = s.labels.at<int>(25, 100), left = s.labels.at<int>(90, 50), right = s.labels.at<int>(90, 150);
  EXPECT_NE(corridor, left);
  EXPECT_NE(corridor, right);
  EXPECT_NE(left, right);
  EXPECT_EQ(s.passages.size(), 3u);
  // The doors round the island are island cuts; without them the learned merging still finds the three
  // rooms here from the pieces' shapes, the hand rules do not.
  EXPECT_TRUE(std::any_of(s.passages.begin(), s.passages.end(), [](const Passage& p) { return p.rule == CutRule::kIslandCut; }));
  SegmentOptions off;
  off.doors.island_cuts = false;
  const Segmentation without = segment(grid, off);
  EXPECT_TRUE(std::none_of(without.passages.begin(), without.passages.end(), [](const Passage& p) { return p.rule == CutRule::kIslandCut; }));
  off.merge.learned = false;
  EXPECT_LT(segment(grid, off).rooms.size(), 3u);
}

TEST(Segment, ParityOptionsSwitchEveryImprovementOff) {
  const SegmentOptions parity = parity_segment_options(3.0);
  EXPECT_EQ(parity.concavity, 3.0);
  EXPECT_FALSE(parity.merge.enabled);
  EXPECT_FALSE(parity.doors.passages);
  EXPECT_FALSE(parity.doors.extend_walls);
  EXPECT_FALSE(parity.doors.wall_lines);
  EXPECT_FALSE(parity.doors.island_cuts);
  EXPECT_EQ(parity.simplify, 0.0);
  EXPECT_FALSE(parity.labels.cover_absorbed_obstacles);
  // Parity pieces are exactly DuDe's pieces of each component, at tau itself (no oversegmentation
  // without merging).
  const OccupancyGrid grid = read_map(bundled("floorplan"));
  const cv::Mat free = segmentation_free_space(grid, parity);
  const FreeSpacePolygons polygons = free_space_polygons(free, grid.resolution, parity.contours);
  std::size_t pieces = 0;
  for (const FreeSpaceComponent& c : polygons.components) {
    DecompositionOptions dude = parity.decomposition;
    dude.tau = parity.concavity / grid.resolution;
    pieces += decompose(c.polygon, dude).pieces.size();
  }
  EXPECT_EQ(segment(grid, parity).rooms.size(), pieces);
}

TEST(Segment, BadInput) {
  OccupancyGrid none{cv::Mat(10, 10, CV_8UC1, cv::Scalar(kOccupied)), 0.05, {}};
  try {
    segment(none);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no free space"), std::string::npos);
  }
  OccupancyGrid grid{cv::Mat(10, 10, CV_8UC1, cv::Scalar(kFree)), 0.05, {}};
  SegmentOptions options;
  options.concavity = 0.0;
  EXPECT_THROW(segment(grid, options), Error);
  options.concavity = std::nan("");
  EXPECT_THROW(segment(grid, options), Error);
  options = SegmentOptions{};
  options.oversegment = 0.0;
  EXPECT_THROW(segment(grid, options), Error);
  options.oversegment = 1.5;
  EXPECT_THROW(segment(grid, options), Error);
  options = SegmentOptions{};
  options.merge.door_like.ratio = -1.0;
  EXPECT_THROW(segment(grid, options), Error);
  options = SegmentOptions{};
  options.doors.max_width = 0.0;
  EXPECT_THROW(segment(grid, options), Error);
  options = SegmentOptions{};
  options.simplify = -1.0;
  EXPECT_THROW(segment(grid, options), Error);
  grid.resolution = -1.0;
  EXPECT_THROW(segment(grid), Error);
  grid.resolution = 0.05;
  options = SegmentOptions{};
  options.binarize.robot_radius = 1.0;  // swallows the whole 0.5 m room
  grid.cells.row(0).setTo(kOccupied);
  EXPECT_THROW(segment(grid, options), Error);
  EXPECT_THROW(segment(OccupancyGrid{}), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

TEST(Segment, RaysOutsideTheBuildingAreNoRoomAndSpecksAreNoRooms) {
  // A walled 5 m x 5 m room with a window in its top wall and one-cell laser rays fanning out of
  // it into the unknown, plus a 3 x 3 obstacle speck and a 2 x 2 speck never observed (unknown),
  // and in the unknown far away a scrap of free space thinner than a person and a 0.8 m x 0.8 m
  // free speck.
  OccupancyGrid grid{cv::Mat(200, 200, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  cv::rectangle(grid.cells, cv::Rect(49, 79, 102, 102), cv::Scalar(kOccupied), cv::FILLED);
  grid.cells(cv::Rect(50, 80, 100, 100)).setTo(kFree);
  grid.cells(cv::Rect(90, 79, 20, 1)).setTo(kFree);
  std::vector<cv::Point> far_rays;
  for (int k = -2; k <= 2; ++k) {
    for (int t = 1; t <= 60; ++t) {
      const cv::Point p(100 + k * t / 4, 79 - t);
      grid.cells.at<unsigned char>(p) = kFree;
      if (t > 6) far_rays.push_back(p);
    }
  }
  grid.cells(cv::Rect(80, 120, 3, 3)).setTo(kOccupied);
  grid.cells(cv::Rect(60, 140, 2, 2)).setTo(kUnknown);
  grid.cells(cv::Rect(5, 190, 4, 4)).setTo(kFree);
  grid.cells(cv::Rect(5, 20, 16, 16)).setTo(kFree);
  const Segmentation s = segment(grid);
  ASSERT_EQ(s.rooms.size(), 1u);
  for (const cv::Point& p : far_rays) EXPECT_EQ(s.labels.at<int>(p), 0) << p;
  EXPECT_EQ(s.labels.at<int>(120, 80), 0);  // the obstacle speck stays unlabelled
  EXPECT_EQ(cv::countNonZero(s.labels(cv::Rect(60, 140, 2, 2)) == 1), 4);  // unobserved floor: the room's
  EXPECT_EQ(s.labels.at<int>(100, 100), 1);
  EXPECT_EQ(s.labels.at<int>(190, 5), 0);  // thin and in the unknown: outside the building
  EXPECT_EQ(s.labels.at<int>(25, 10), 1);  // below 1 m²: no room, joins the nearest (DESIGN.md)
  // Without the cleaning the fan is free space of the room's component: labelled.
  SegmentOptions raw;
  raw.clean = false;
  const Segmentation r = segment(grid, raw);
  EXPECT_NE(r.labels.at<int>(far_rays.back()), 0);
  EXPECT_EQ(r.labels.at<int>(140, 60), 0);  // without the cleaning unknown is never labelled
}

TEST(Segment, AWindowWithoutRemovedCellsNeedsOnlyTheFloorTestsReach) {
  // A walled 15 m x 5 m room with a window in its top wall at the left end and one-cell laser rays
  // fanning out of it into the unknown (cells the cleaning removes), a table near the right end.
  OccupancyGrid grid{cv::Mat(200, 400, CV_8UC1, cv::Scalar(kUnknown)), 0.05, {0.0, 0.0}};
  cv::rectangle(grid.cells, cv::Rect(19, 79, 302, 102), cv::Scalar(kOccupied), cv::FILLED);
  grid.cells(cv::Rect(20, 80, 300, 100)).setTo(kFree);
  grid.cells(cv::Rect(40, 79, 20, 1)).setTo(kFree);
  for (int k = -2; k <= 2; ++k)
    for (int t = 1; t <= 60; ++t) grid.cells.at<unsigned char>(cv::Point(50 + k * t / 4, 79 - t)) = kFree;
  grid.cells(cv::Rect(270, 120, 20, 10)).setTo(kOccupied);
  const SegmentOptions options;
  const int local = front_end_local_reach(options, grid.resolution);
  EXPECT_EQ(local, 23);  // (1.25 x 0.6 m + 0.3 m) / 0.05 m + 2: no inside closing
  EXPECT_LT(local, front_end_reach(options, grid.resolution));
  // Far from the rays the floor tests' reach as context gives the full context's front end.
  const cv::Rect window(250, 100, 40, 40);
  const SegmentationInput full = segmentation_input(grid, window, options);
  const SegmentationInput near = segmentation_input(grid, window, options, local);
  EXPECT_EQ(cv::countNonZero(full.floor != near.floor), 0);
  EXPECT_EQ(cv::countNonZero(full.labelled.cells != near.labelled.cells), 0);
  EXPECT_GT(cv::countNonZero(near.floor), 0);
  // Beside the rays the cleaning removes free cells: there the inside closing's reach is needed.
  const SegmentationInput rays = segmentation_input(grid, cv::Rect(30, 10, 40, 70), options, local);
  EXPECT_GT(cv::countNonZero((grid.cells(cv::Rect(30, 10, 40, 70)) == kFree) & (rays.floor == 0)), 0);
  // It does not apply where removed cells are not the free cells off the floor, nor without a cleaning.
  SegmentOptions inflated;
  inflated.binarize.robot_radius = 0.2;
  EXPECT_EQ(front_end_local_reach(inflated, grid.resolution), -1);
  SegmentOptions raw;
  raw.clean = false;
  EXPECT_EQ(front_end_local_reach(raw, grid.resolution), -1);
}

}  // namespace
}  // namespace topocut
