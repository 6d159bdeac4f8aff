// Stability figures on hand-made label sequences whose answers are counted by hand in the comments.
#include "topocut/exploration/room_stability.h"

#include <gtest/gtest.h>

#include "topocut/core/error.h"

namespace topocut {
namespace {

cv::Mat labels(std::initializer_list<std::initializer_list<int>> rows) {
  cv::Mat out(static_cast<int>(rows.size()), static_cast<int>(rows.begin()->size()), CV_32SC1);
  int r = 0;
  for (const auto& row : rows) {
    int c = 0;
    for (const int v : row) out.at<int>(r, c++) = v;
    ++r;
  }
  return out;
}

TEST(RoomStability, UnchangedLabelsHaveNoChurn) {
  StabilityTracker tracker;
  const cv::Mat a = labels({{1, 1, 2}, {1, 0, 2}});
  tracker.add(a, {0, 0}, 1.0);
  tracker.add(a, {0, 0}, 1.0);
  const StabilityReport r = tracker.report();
  ASSERT_EQ(r.churn.size(), 1u);
  EXPECT_EQ(r.churn[0], 0.0);
  EXPECT_EQ(r.rooms_changed, 0);
  EXPECT_EQ(r.distinct_ids, 2);
  EXPECT_EQ(r.final_rooms, 2);
  EXPECT_EQ(r.rooms.at(1).updates, 1);
}

TEST(RoomStability, CountsCellsThatChangedRoom) {
  // Cells labelled in both: 5 (the centre of the bottom row was unlabelled); one went from 1 to 2.
  // Room 1: 3 surviving cells, 1 lost -> 1/3 > 10 %. Room 2: 2 surviving, 1 gained -> 1/2 > 10 %.
  StabilityTracker tracker;
  tracker.add(labels({{1, 1, 2}, {1, 0, 2}}), {0, 0}, 1.0);
  tracker.add(labels({{1, 2, 2}, {1, 1, 2}}), {0, 0}, 1.0);
  const StabilityReport r = tracker.report();
  ASSERT_EQ(r.churn.size(), 1u);
  EXPECT_DOUBLE_EQ(r.churn[0], 0.2);
  EXPECT_EQ(r.rooms.at(1).cell_changes, 1);
  EXPECT_EQ(r.rooms.at(2).cell_changes, 1);
  EXPECT_EQ(r.rooms.at(1).id_changes, 0);
  EXPECT_EQ(r.rooms_changed, 2);
  EXPECT_EQ(r.room_changes, 2);
  EXPECT_EQ(r.updates_with_churn, 1);
}

TEST(RoomStability, RenamedRoomIsAnIdChange) {
  StabilityTracker tracker;
  tracker.add(labels({{1, 1}, {1, 1}}), {0, 0}, 1.0);
  tracker.add(labels({{3, 3}, {3, 3}}), {0, 0}, 1.0);
  const StabilityReport r = tracker.report();
  EXPECT_DOUBLE_EQ(r.churn[0], 1.0);
  EXPECT_EQ(r.rooms.at(1).id_changes, 1);
  EXPECT_EQ(r.rooms.at(1).cell_changes, 0);
  EXPECT_EQ(r.distinct_ids, 2);  // 1 and 3
  EXPECT_EQ(r.final_rooms, 1);
}

TEST(RoomStability, TenPercentIsTheBorder) {
  // A 20-cell room 1 beside room 2: moving 2 cells (10 %) is no change, moving 3 more (15 %) is one.
  cv::Mat a(1, 25, CV_32SC1, cv::Scalar(1));
  a.colRange(20, 25).setTo(2);
  cv::Mat b = a.clone();
  b.colRange(18, 20).setTo(2);
  cv::Mat c = b.clone();
  c.colRange(15, 18).setTo(2);
  StabilityTracker tracker;
  tracker.add(a, {0, 0}, 0.5);
  tracker.add(b, {0, 0}, 0.5);
  EXPECT_EQ(tracker.report().rooms.at(1).cell_changes, 0);
  tracker.add(c, {0, 0}, 0.5);
  const StabilityReport r = tracker.report();
  // b -> c: room 1 had 18 surviving cells, lost 3 (3/18 > 10 %); room 2 had 7, gained 3.
  EXPECT_EQ(r.rooms.at(1).cell_changes, 1);
  EXPECT_EQ(r.rooms.at(2).cell_changes, 2);  // gained 2 of 5 (40 %), then 3 of 7
  ASSERT_EQ(r.churn.size(), 2u);
  EXPECT_DOUBLE_EQ(r.churn[0], 2.0 / 25.0);
  EXPECT_DOUBLE_EQ(r.churn[1], 3.0 / 25.0);
}

TEST(RoomStability, GrowingFrameIsMatchedThroughTheOrigin) {
  // The map grows by one column on the left (origin x - 1) and one row on top (same origin y,
  // one more row): the old cells sit one row down and one column right in the new image.
  StabilityTracker tracker;
  tracker.add(labels({{1, 2}, {1, 2}}), {0, 0}, 1.0);
  tracker.add(labels({{5, 5, 5}, {0, 1, 2}, {0, 1, 2}}), {-1, 0}, 1.0);
  StabilityReport r = tracker.report();
  EXPECT_EQ(r.churn[0], 0.0);
  EXPECT_EQ(r.rooms_changed, 0);
  EXPECT_EQ(r.distinct_ids, 3);
  EXPECT_EQ(r.final_rooms, 3);
  // Swapping the two old rooms' cells is churn: 7 cells labelled twice (5 5 5 and four), 4 swapped.
  tracker.add(labels({{5, 5, 5}, {0, 2, 1}, {0, 2, 1}}), {-1, 0}, 1.0);
  r = tracker.report();
  EXPECT_DOUBLE_EQ(r.churn[1], 4.0 / 7.0);
}

TEST(RoomStability, OrderStatisticsOverUpdates) {
  // Churn 0, 0, 0.5: median 0, nearest-rank p95 the largest of three, max 0.5.
  StabilityTracker tracker;
  const cv::Mat a = labels({{1, 2}}), b = labels({{1, 1}});
  tracker.add(a, {0, 0}, 1.0);
  tracker.add(a, {0, 0}, 1.0);
  tracker.add(a, {0, 0}, 1.0);
  tracker.add(b, {0, 0}, 1.0);
  const StabilityReport r = tracker.report();
  EXPECT_EQ(r.churn_median, 0.0);
  EXPECT_DOUBLE_EQ(r.churn_p95, 0.5);
  EXPECT_DOUBLE_EQ(r.churn_max, 0.5);
  EXPECT_EQ(r.rooms.at(2).id_changes, 1);
  EXPECT_EQ(r.final_rooms, 1);
}

TEST(RoomStability, RejectsWrongInput) {
  StabilityTracker tracker;
  EXPECT_THROW(tracker.add(cv::Mat::zeros(2, 2, CV_8UC1), {0, 0}, 1.0), Error);
  EXPECT_THROW(tracker.add(labels({{1}}), {0, 0}, 0.0), Error);
  EXPECT_THROW(tracker.add(labels({{-1}}), {0, 0}, 1.0), Error);
  EXPECT_THROW(StabilityTracker(StabilityOptions{1.5}), Error);
}

}  // namespace
}  // namespace topocut
