#include "topocut/segmentation/outside_parts.h"

#include <functional>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/map/building_inside.h"
#include "topocut/map/free_space_polygons.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;

// A 10 m x 10 m grid, never seen but for: a walled 5 m x 4 m room (columns 50-149, rows 110-189) with
// a 1 m window in its top wall (columns 90-109), a fan of floor seen through it widening upwards into
// the never-seen space (rows 30-108), one-cell rays going on beyond the fan to row 5 (free cells of no
// piece, as the cleaning leaves them), and a walled 1.5 m x 1.5 m closet far off (columns 5-34, rows
// 150-179). As the labelling leaves them: room 1 the room, window and fan, rays and all, its polygon
// its floor's squares; room 2 the closet. Passages from the room to the closet: one across the room,
// one across the fan.
struct Fan {
  Segmentation segmentation;
  OccupancyGrid grid{cv::Mat(200, 200, CV_8UC1, cv::Scalar(kUnknown)), kRes, {0.0, 0.0}};
  cv::Mat floor;
  cv::Mat fan_floor;  // the floor above the window

  // ragged_room: the room's floor ends in teeth of laser rays 0.2-0.4 m short of its side and bottom
  // walls, the cells between never seen.
  explicit Fan(bool rays = true, bool ragged_room = false) {
    cv::rectangle(grid.cells, cv::Rect(49, 109, 102, 82), cv::Scalar(kOccupied), cv::FILLED);
    grid.cells(cv::Rect(50, 110, 100, 80)).setTo(kFree);
    if (ragged_room) ragged_walls();
    grid.cells(cv::Rect(90, 109, 20, 1)).setTo(kFree);
    fan_floor = cv::Mat(grid.cells.size(), CV_8UC1, cv::Scalar(0));
    for (int row = 30; row <= 108; ++row) {
      const int half = 10 + (108 - row) / 2;  // the window's half width, growing upwards
      fan_floor(cv::Rect(100 - half, row, 2 * half, 1)).setTo(255);
    }
    grid.cells.setTo(kFree, fan_floor);
    cv::rectangle(grid.cells, cv::Rect(4, 149, 32, 32), cv::Scalar(kOccupied), cv::FILLED);
    grid.cells(cv::Rect(5, 150, 30, 30)).setTo(kFree);
    floor = grid.cells == kFree;
    segmentation.labels = cv::Mat(grid.cells.size(), CV_32SC1, cv::Scalar(0));
    segmentation.labels.setTo(1, floor);
    segmentation.labels(cv::Rect(5, 150, 30, 30)).setTo(2);
    for (int col = 62; rays && col < 138; col += 3) {
      grid.cells(cv::Rect(col, 5, 1, 25)).setTo(kFree);
      segmentation.labels(cv::Rect(col, 5, 1, 25)).setTo(1);
    }
    segmentation.resolution = kRes;
    for (int id = 1; id <= 2; ++id) segmentation.rooms.push_back(room(id));
    segmentation.passages.push_back(Passage{1, 2, Segment2{{3.0, 2.0}, {3.0, 3.0}}, 1.0, true, CutRule::kDoor});
    segmentation.passages.push_back(Passage{1, 2, Segment2{{4.5, 6.0}, {5.5, 6.0}}, 1.0, true, CutRule::kDoor});
  }

  void ragged_walls() {
    grid.cells(cv::Rect(50, 110, 100, 80)).setTo(kUnknown);
    grid.cells(cv::Rect(58, 110, 84, 72)).setTo(kFree);
    for (int k = 0; k < 84; k += 2) {  // teeth of 1-4 cells below the floor
      grid.cells(cv::Rect(58 + k, 182, 1, 1 + k % 4)).setTo(kFree);
      if (k < 72) {  // and beside it
        grid.cells(cv::Rect(58 - 1 - k % 3, 110 + k, 1 + k % 3, 1)).setTo(kFree);
        grid.cells(cv::Rect(142, 110 + k, 1 + k % 3, 1)).setTo(kFree);
      }
    }
  }

  // Room id as the labelling describes it: its polygon its floor's squares, its cells' area and centre.
  Room room(int id) const {
    Room result;
    result.id = id;
    const cv::Mat own = (segmentation.labels == id) & floor;
    const std::vector<FreeSpaceComponent> parts = trace_components(remove_diagonal_pinches(own));
    for (const Point2& v : parts.at(0).polygon.outer) result.polygon.outer.push_back(grid_to_world(grid, v));
    result.area = area(result.polygon);
    describe_cells(result);
    return result;
  }

  void describe_cells(Room& room) const {
    const cv::Mat cells = segmentation.labels == room.id;
    room.labelled_area = cv::countNonZero(cells) * kRes * kRes;
    const cv::Moments m = cv::moments(cells, true);
    room.centroid = cell_center_world(grid, 0, 0) + Point2{m.m10 / m.m00 * kRes, -m.m01 / m.m00 * kRes};
  }
};

// The room keeps what lies inside the building: its cells outside (the fan and its rays) get 0, its
// polygon loses their squares (the room's floor cells inside, to the cell), its area and centre are
// its cells'. The closet stays as it was; the passage across the fan goes, the other stays.
TEST(OutsideParts, AWalledRoomLosesTheFanSeenThroughItsWindow) {
  Fan fan;
  const Room& before = fan.segmentation.rooms[0];
  ASSERT_TRUE(holds_rays(before, OpenRoomOptions{}));
  const cv::Mat inside = building_inside(fan.grid.cells, OpenRoomOptions{}.fan_closing / kRes);
  const cv::Mat room_inside = (fan.segmentation.labels == 1) & inside;
  const cv::Mat closet = fan.segmentation.labels == 2;
  const Room closet_before = fan.segmentation.rooms[1];
  ASSERT_GT(cv::countNonZero(fan.fan_floor & (inside == 0)), 3000);  // most of the fan is outside
  leave_out_outside_parts(fan.segmentation, fan.grid, fan.floor);
  const cv::Mat& labels = fan.segmentation.labels;
  EXPECT_EQ(cv::countNonZero((labels == 1) != room_inside), 0);
  EXPECT_EQ(cv::countNonZero((labels == 2) != closet), 0);
  EXPECT_EQ(labels.at<int>(60, 100), 0);   // the fan
  EXPECT_EQ(labels.at<int>(10, 62), 0);    // a ray
  EXPECT_EQ(labels.at<int>(150, 100), 1);  // the room
  const Room& after = fan.segmentation.rooms[0];
  EXPECT_NEAR(after.area, cv::countNonZero(room_inside & fan.floor) * kRes * kRes, 1e-9);
  EXPECT_NEAR(area(after.polygon), after.area, 1e-12);
  EXPECT_NEAR(bounding_box(after.polygon.outer).y1, (200 - 109) * kRes, 1e-9);  // the top of the window's row 109
  Room expected = after;
  fan.describe_cells(expected);
  EXPECT_DOUBLE_EQ(after.labelled_area, expected.labelled_area);
  EXPECT_NEAR(after.centroid.x, expected.centroid.x, 1e-9);
  EXPECT_NEAR(after.centroid.y, expected.centroid.y, 1e-9);
  EXPECT_EQ(fan.segmentation.rooms[1].polygon, closet_before.polygon);
  ASSERT_EQ(fan.segmentation.passages.size(), 1u);
  EXPECT_EQ(fan.segmentation.passages[0].cut.a, (Point2{3.0, 2.0}));
}

// Nothing changes: without rays (a drawn plan's room), with the row off, for a room with no more than
// fan_inside_share of its floor inside (the open-fans row's), with no walls, or when a room without
// rays lies mostly outside (walls the map does not draw as walls, and outside tells nothing).
TEST(OutsideParts, RoomsWithoutRaysMostlyOutsideOrOnMapsWithoutWallsStay) {
  const auto kept = [](Fan fan, const OpenRoomOptions& options = {}) {
    const cv::Mat before = fan.segmentation.labels.clone();
    const std::vector<Room> rooms = fan.segmentation.rooms;
    leave_out_outside_parts(fan.segmentation, fan.grid, fan.floor, options);
    return cv::countNonZero(fan.segmentation.labels != before) == 0 && fan.segmentation.passages.size() == 2u &&
           fan.segmentation.rooms[0].polygon == rooms[0].polygon && fan.segmentation.rooms[0].area == rooms[0].area;
  };
  // The fan with options changed by set.
  const auto kept_with = [&](const std::function<void(OpenRoomOptions&)>& set) {
    OpenRoomOptions options;
    set(options);
    return kept(Fan(), options);
  };
  EXPECT_FALSE(kept(Fan()));
  EXPECT_TRUE(kept(Fan(false)));
  EXPECT_TRUE(kept_with([](OpenRoomOptions& o) { o.cut_outside_parts = false; }));
  EXPECT_TRUE(kept_with([](OpenRoomOptions& o) { o.fan_ray_share = 0.0; }));
  EXPECT_TRUE(kept_with([](OpenRoomOptions& o) { o.enabled = false; }));
  // The room's floor is about two thirds inside.
  EXPECT_FALSE(kept_with([](OpenRoomOptions& o) { o.fan_inside_share = 0.6; }));
  EXPECT_TRUE(kept_with([](OpenRoomOptions& o) { o.fan_inside_share = 0.7; }));
  // A room whose floor inside is itself open (rays end raggedly where its walls were never seen) is no
  // walled room: the closing may have enclosed the end of a fan instead (its own part inside).
  const Fan ragged(true, true);
  const cv::Mat ragged_inside = building_inside(ragged.grid.cells, OpenRoomOptions{}.fan_closing / kRes);
  const cv::Mat ragged_floor = (ragged.segmentation.labels == 1) & ragged.floor;
  ASSERT_GT(cv::countNonZero(ragged_floor & ragged_inside), 0.5 * cv::countNonZero(ragged_floor));
  ASSERT_GT(cv::countNonZero(ragged.fan_floor & (ragged_inside == 0)), 3000);
  EXPECT_TRUE(kept(ragged));
  Fan no_walls;
  no_walls.grid.cells.setTo(kUnknown, no_walls.grid.cells == kOccupied);
  EXPECT_TRUE(kept(no_walls));
  Fan open_closet;  // the closet's walls gone: its floor reaches the grid's edge through never-seen cells
  open_closet.grid.cells(cv::Rect(4, 149, 32, 32)).setTo(kUnknown);
  open_closet.grid.cells(cv::Rect(5, 150, 30, 30)).setTo(kFree);
  EXPECT_TRUE(kept(open_closet));
}

TEST(OutsideParts, BadLabelsSizesAndNumbersAreErrors) {
  Fan label;
  label.segmentation.labels.at<int>(0, 0) = 3;
  EXPECT_THROW(leave_out_outside_parts(label.segmentation, label.grid, label.floor), Error);
  Fan size;
  EXPECT_THROW(leave_out_outside_parts(size.segmentation, size.grid, size.floor(cv::Rect(0, 0, 10, 10)).clone()), Error);
  Fan numbers;
  numbers.segmentation.rooms[1].id = 5;
  EXPECT_THROW(leave_out_outside_parts(numbers.segmentation, numbers.grid, numbers.floor), Error);
  Fan options;
  OpenRoomOptions bad;
  bad.fan_inside_share = 2.0;
  EXPECT_THROW(leave_out_outside_parts(options.segmentation, options.grid, options.floor, bad), Error);
}

}  // namespace
}  // namespace topocut
