#include "topocut/evaluation/matched_rooms.h"

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/evaluation/annotated_space.h"
#include "topocut/evaluation/segmentation_scores.h"

namespace topocut {
namespace {

cv::Mat labels(int rows, int cols) { return cv::Mat(rows, cols, CV_32SC1, cv::Scalar(0)); }

// Thirteen rooms of 12 x 10 px in a row, each followed by a one-pixel separator column, as drawn into
// a Bormann ground truth; the map sees no separators, so the whole strip is free.
constexpr int kRooms = 13;
cv::Rect strip_room(int k) { return {1 + 13 * k, 1, 12, 10}; }

TEST(MatchedRooms, ThreeSegmentsOverThirteenRoomsMatchOnlyTheRoomGivenAlone) {
  cv::Mat rooms = labels(12, 2 + 13 * kRooms);
  for (int k = 0; k < kRooms; ++k) rooms(strip_room(k)).setTo(k + 1);
  const cv::Mat free = cv::Mat(rooms.size(), CV_8UC1, cv::Scalar(0));
  free(cv::Rect(1, 1, 13 * kRooms - 1, 10)).setTo(255);
  cv::Mat segments = labels(rooms.rows, rooms.cols);
  segments(strip_room(0)).setTo(1);                           // room 1 exactly: IoU 1
  segments(strip_room(1) | strip_room(6)).setTo(2);           // rooms 2..7 and five separators: 770 px
  segments(strip_room(7) | strip_room(kRooms - 1)).setTo(3);  // rooms 8..13: 770 px
  const MatchedRooms m = matched_rooms(segments, rooms, free);
  EXPECT_EQ(m.segments, 3);
  EXPECT_EQ(m.rooms, 13);
  EXPECT_EQ(m.matches, 1);  // 120 / 770 is far below one half for every room of the big segments
  EXPECT_EQ(m.false_positives, 2);
  EXPECT_EQ(m.false_negatives, 12);
  EXPECT_DOUBLE_EQ(m.f1, 1.0 / (1.0 + 14.0 / 2.0));
  EXPECT_DOUBLE_EQ(m.pq, 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(m.segments_per_room, 3.0 / 13.0);
  // Bormann's precision still calls two of the three segments 120 / 770 precise and the recall perfect.
  const PrecisionRecall pr = precision_recall(segments, rooms);
  EXPECT_DOUBLE_EQ(pr.recall, 1.0);
  EXPECT_DOUBLE_EQ(pr.precision, (1.0 + 2.0 * 120.0 / 770.0) / 3.0);
}

// One room of 30 x 10 = 300 px in a 20 x 80 px free map.
const cv::Rect kRoom(5, 5, 30, 10);

cv::Mat one_room() {
  cv::Mat rooms = labels(20, 80);
  rooms(kRoom).setTo(1);
  return rooms;
}

TEST(MatchedRooms, IouOfExactlyOneHalfIsNoMatchAndJustAboveIs) {
  cv::Mat segments = labels(20, 80);
  segments(cv::Rect(5, 5, 15, 10)).setTo(4);  // 150 of the room's 300 px: IoU 150 / 300
  MatchedRooms m = matched_rooms(segments, one_room());
  EXPECT_EQ(m.matches, 0);
  EXPECT_DOUBLE_EQ(m.f1, 0.0);  // TP 0, FP 1, FN 1
  EXPECT_DOUBLE_EQ(m.pq, 0.0);

  segments.at<int>(5, 20) = 4;  // 151 px: IoU 151 / 300
  m = matched_rooms(segments, one_room());
  EXPECT_EQ(m.matches, 1);
  EXPECT_DOUBLE_EQ(m.f1, 1.0);
  EXPECT_DOUBLE_EQ(m.pq, 151.0 / 300.0);

  // The whole room and 300 px beside it: IoU 300 / 600, no match; 299 beside it: 300 / 599, a match.
  segments = labels(20, 80);
  segments(cv::Rect(5, 5, 60, 10)).setTo(9);
  EXPECT_EQ(matched_rooms(segments, one_room()).matches, 0);
  segments.at<int>(14, 64) = 0;
  m = matched_rooms(segments, one_room());
  EXPECT_EQ(m.matches, 1);
  EXPECT_DOUBLE_EQ(m.pq, 300.0 / 599.0);
}

TEST(MatchedRooms, RegionsOfAtMostOneHundredFreePixelsAreIgnored) {
  cv::Mat rooms = one_room();
  rooms(cv::Rect(40, 5, 15, 10)).setTo(2);  // room 2: 150 px, 50 of them under furniture in the map
  cv::Mat free(rooms.size(), CV_8UC1, cv::Scalar(255));
  free(cv::Rect(40, 5, 5, 10)).setTo(0);
  cv::Mat segments = labels(20, 80);
  segments(kRoom).setTo(1);
  segments(cv::Rect(60, 0, 10, 10)).setTo(2);   // 100 px in no room: ignored, not a false positive
  segments(cv::Rect(70, 0, 10, 10)).setTo(3);   // 100 px ...
  segments.at<int>(10, 70) = 3;                 // ... and one more: counted, a false positive
  const MatchedRooms with_free = matched_rooms(segments, rooms, free);
  EXPECT_EQ(with_free.rooms, 1);  // room 2 keeps 100 free pixels
  EXPECT_EQ(with_free.segments, 2);
  EXPECT_EQ(with_free.matches, 1);
  EXPECT_EQ(with_free.false_positives, 1);
  EXPECT_EQ(with_free.false_negatives, 0);
  EXPECT_DOUBLE_EQ(with_free.f1, 1.0 / 1.5);
  const MatchedRooms everywhere = matched_rooms(segments, rooms);  // no mask: room 2 has 150 px
  EXPECT_EQ(everywhere.rooms, 2);
  EXPECT_EQ(everywhere.false_negatives, 1);
}

TEST(MatchedRooms, OnlyTheMapsFreePixelsCount) {
  // The segment spills over 400 px of wall: IoU 300 / 700 over all pixels, 1 over the free ones.
  cv::Mat segments = labels(20, 80);
  segments(cv::Rect(5, 5, 30, 10)).setTo(1);
  segments(cv::Rect(5, 15, 40, 5)).setTo(1);
  segments(cv::Rect(35, 5, 10, 10)).setTo(1);
  cv::Mat free(20, 80, CV_8UC1, cv::Scalar(0));
  free(kRoom).setTo(255);
  EXPECT_EQ(matched_rooms(segments, one_room()).matches, 0);
  const MatchedRooms m = matched_rooms(segments, one_room(), free);
  EXPECT_EQ(m.matches, 1);
  EXPECT_DOUBLE_EQ(m.pq, 1.0);
  EXPECT_EQ(segments.at<int>(15, 5), 1);  // the input is left alone
}

TEST(MatchedRooms, LabelTypesDoNotMatter) {
  cv::Mat segments = labels(20, 80);
  segments(kRoom).setTo(1);
  cv::Mat as_16bit;
  segments.convertTo(as_16bit, CV_16UC1, 300.0);
  cv::Mat rooms_8bit;
  one_room().convertTo(rooms_8bit, CV_8UC1);
  const MatchedRooms m = matched_rooms(as_16bit, rooms_8bit);
  EXPECT_EQ(m.matches, 1);
  EXPECT_DOUBLE_EQ(m.f1, 1.0);
}

TEST(MatchedRooms, RejectsBadInput) {
  const cv::Mat segments = labels(20, 80);
  EXPECT_THROW(matched_rooms(segments, labels(20, 80)), Error);  // no room
  EXPECT_THROW(matched_rooms(labels(10, 80), one_room()), Error);
  EXPECT_THROW(matched_rooms(segments, one_room(), cv::Mat(10, 10, CV_8UC1, cv::Scalar(255))), Error);
  EXPECT_THROW(matched_rooms(segments, one_room(), cv::Mat(20, 80, CV_32SC1, cv::Scalar(1))), Error);
  EvaluationOptions loose;
  loose.match_iou = 0.4;  // no longer one-to-one
  EXPECT_THROW(matched_rooms(segments, one_room(), {}, loose), Error);
}

// Room A: columns 0..19, rows 0..9. Segment 1 covers A and the 10 columns beside it (in no room,
// 1 to 10 px from A); segment 2 is 100 px at columns 40..49, 21 to 30 px from A.
struct AnnotatedCase {
  cv::Mat rooms = labels(10, 60), segments = labels(10, 60);
  AnnotatedCase() {
    rooms(cv::Rect(0, 0, 20, 10)).setTo(1);
    segments(cv::Rect(0, 0, 30, 10)).setTo(1);
    segments(cv::Rect(40, 0, 10, 10)).setTo(2);
  }
};

TEST(AnnotatedSpace, PrecisionInsideClipsSegmentsToTheRooms) {
  const AnnotatedCase c;
  EXPECT_DOUBLE_EQ(precision_recall(c.segments, c.rooms).precision, 200.0 / 300.0);  // segment 2 ignored
  EXPECT_DOUBLE_EQ(precision_inside_annotated(c.segments, c.rooms), 1.0);
}

TEST(AnnotatedSpace, FarShareCountsLabelledCellsBeyondHalfAMetre) {
  const AnnotatedCase c;
  // 0.05 m/px: more than 10 px away, only segment 2 (100 of 400 labelled px; 10 px exactly is not far).
  EXPECT_DOUBLE_EQ(far_from_rooms_share(c.segments, c.rooms, 0.05), 0.25);
  // 0.1 m/px: more than 5 px, also columns 25..29 of segment 1.
  EXPECT_DOUBLE_EQ(far_from_rooms_share(c.segments, c.rooms, 0.1), 150.0 / 400.0);
  EXPECT_DOUBLE_EQ(far_from_rooms_share(labels(10, 60), c.rooms, 0.05), 0.0);  // nothing labelled
  EXPECT_THROW(far_from_rooms_share(c.segments, c.rooms, 0.0), Error);
  EXPECT_THROW(far_from_rooms_share(c.segments, labels(5, 60), 0.05), Error);
}

TEST(SegmentationScores, CarryEveryScoreOfTheSameLabels) {
  const AnnotatedCase c;
  const SegmentationScores s = score_segmentation(c.segments, c.rooms, {}, 0.05);
  EXPECT_DOUBLE_EQ(s.overlap.precision, 200.0 / 300.0);
  EXPECT_DOUBLE_EQ(s.overlap.recall, 1.0);
  EXPECT_EQ(s.matched.matches, 1);  // IoU 200 / 300
  EXPECT_DOUBLE_EQ(s.matched.pq, 200.0 / 300.0);
  EXPECT_DOUBLE_EQ(s.precision_inside, 1.0);
  EXPECT_DOUBLE_EQ(s.far_share, 0.25);
}

// Rooms 1, 2, 3 are 20 x 20 px blocks side by side, room 4 a 20 x 20 block below room 1. Segment 1
// takes rooms 1 and 2 (a merge), segment 2 is room 3 exactly, segments 3 and 4 split room 4 in two
// halves, segment 5 is 60 px of nothing (ignored).
TEST(RoomOutcomes, MissesMergesAndMatchesRegionByRegion) {
  cv::Mat rooms = labels(40, 80), segments = labels(40, 80);
  rooms(cv::Rect(0, 0, 20, 20)).setTo(1);
  rooms(cv::Rect(20, 0, 20, 20)).setTo(2);
  rooms(cv::Rect(40, 0, 20, 20)).setTo(3);
  rooms(cv::Rect(0, 20, 20, 20)).setTo(4);
  segments(cv::Rect(0, 0, 40, 20)).setTo(1);
  segments(cv::Rect(40, 0, 20, 20)).setTo(2);
  segments(cv::Rect(0, 20, 10, 20)).setTo(3);
  segments(cv::Rect(10, 20, 10, 20)).setTo(4);
  segments(cv::Rect(60, 30, 10, 6)).setTo(5);
  const RoomOutcomes o = room_outcomes(segments, rooms);
  EXPECT_EQ(o.room_match, (std::map<int, int>{{1, 0}, {2, 0}, {3, 2}, {4, 0}}));
  EXPECT_EQ(o.segment_match, (std::map<int, int>{{1, 0}, {2, 3}, {3, 0}, {4, 0}}));
  EXPECT_EQ(o.merges, std::set<int>{1});
  // The counts are matched_rooms()' own.
  const MatchedRooms m = matched_rooms(segments, rooms);
  EXPECT_EQ(m.matches, 1);
  EXPECT_EQ(m.false_negatives, 3);
  EXPECT_EQ(m.false_positives, 3);
  // Half of a room is not more than half: the split room's halves merge nothing.
  cv::Mat halves = labels(40, 80);
  halves(cv::Rect(0, 20, 10, 20)).setTo(1);
  halves(cv::Rect(0, 0, 10, 20)).setTo(1);
  EXPECT_TRUE(room_outcomes(halves, rooms).merges.empty());
  // Only free pixels count: with room 2 off the map, segment 1 matches room 1.
  cv::Mat free(40, 80, CV_8UC1, cv::Scalar(255));
  free(cv::Rect(20, 0, 20, 20)).setTo(0);
  const RoomOutcomes clipped = room_outcomes(segments, rooms, free);
  EXPECT_EQ(clipped.room_match.at(1), 1);
  EXPECT_EQ(clipped.room_match.count(2), 0u);
  EXPECT_TRUE(clipped.merges.empty());
}

}  // namespace
}  // namespace topocut
