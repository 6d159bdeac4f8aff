// Ids carried by overlap between two label images, hand-made cases with hand-computed answers.
#include "topocut/segmentation/carried_ids.h"

#include <vector>

#include <gtest/gtest.h>

#include "segmentation/incremental/label_rows.h"

namespace topocut {
namespace {

using testing::labels_of;

TEST(CarriedIds, EachOldIdGoesToTheRoomSharingMostOfItsCells) {
  // Old room 7 (6 cells) is cut into new 1 (4 of its cells) and new 2 (2); old room 5 (3 cells)
  // becomes new 3; new 4 lies where nothing was.
  const cv::Mat previous = labels_of({"777777555", "000000000"});
  const cv::Mat next = labels_of({"111122333", "000000044"});
  int next_id = 9;
  const std::vector<int> ids = carried_ids(previous, next, 4, next_id);
  EXPECT_EQ(ids, (std::vector<int>{0, 7, 9, 5, 10}));
  EXPECT_EQ(next_id, 11);
  // Without a previous image every room gets a new id, in label order.
  next_id = 1;
  EXPECT_EQ(carried_ids(cv::Mat(), next, 4, next_id), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(CarriedIds, ARoomWhereARetiredOneLayTakesItsIdBack) {
  // New room 2 lies 3 of its 4 cells where retired room 8 was: it takes 8; new room 3 has only 1
  // of its 3 cells where retired room 6 was: a new id. Id 7 is carried, so never revived.
  const cv::Mat previous = labels_of({"77770000", "00000000"});
  const cv::Mat retired = labels_of({"00008887", "00060000"});
  const cv::Mat next = labels_of({"11112222", "00033300"});
  int next_id = 9;
  const std::vector<int> ids = carried_ids(previous, next, 3, next_id, retired);
  EXPECT_EQ(ids, (std::vector<int>{0, 7, 8, 9}));
  EXPECT_EQ(next_id, 10);
}

TEST(CarriedIds, TheCarrierFollowsAGrowingMovingFrame) {
  // The second map has one more column on the left (origin 1 cell further west) and one more row at
  // the bottom: the rooms are the same cells in the world, so they keep their ids.
  Segmentation a;
  a.labels = labels_of({"1122", "1122"});
  a.rooms.resize(2);
  a.rooms[0].id = 1;
  a.rooms[1].id = 2;
  a.resolution = 0.5;
  a.origin = {1.0, 1.0};
  Segmentation b = a;
  b.labels = labels_of({"01122", "01122", "03333"});
  b.rooms.resize(3);
  b.rooms[2].id = 3;
  b.origin = {0.5, 0.5};
  IdCarrier carrier;
  EXPECT_EQ(cv::countNonZero(carrier.carry(a).labels != a.labels), 0);
  const Segmentation carried = carrier.carry(b);
  EXPECT_EQ(carried.labels.at<int>(0, 1), 1);
  EXPECT_EQ(carried.labels.at<int>(0, 3), 2);
  EXPECT_EQ(carried.labels.at<int>(2, 2), 3);  // a new room: the next unused id
}

}  // namespace
}  // namespace topocut
