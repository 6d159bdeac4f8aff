#include "topocut/evaluation/precision_recall.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "topocut/core/error.h"
#include "io/test_images.h"

namespace topocut {
namespace {

// The ground truth used by most tests (50 x 20 pixels, all obstacle but for):
//   room A: columns 1..30, rows 1..10  -> 300 px, value 255
//   a one-pixel separator line at column 31, rows 1..10 (value 0, as drawn into Bormann's GT)
//   room B: columns 32..46, rows 1..10 -> 150 px, value 255
const cv::Rect kRoomA(1, 1, 30, 10);
const cv::Rect kSeparator(31, 1, 1, 10);
const cv::Rect kRoomB(32, 1, 15, 10);

cv::Mat two_room_ground_truth() {
  cv::Mat gt(20, 50, CV_8UC1, cv::Scalar(0));
  gt(kRoomA).setTo(255);
  gt(kRoomB).setTo(255);
  return gt;
}

cv::Mat empty_labels() { return cv::Mat(20, 50, CV_32SC1, cv::Scalar(0)); }

TEST(PrecisionRecall, PerfectSegmentationScoresOne) {
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(7);
  labels(kRoomB).setTo(3);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  EXPECT_DOUBLE_EQ(result.precision, 1.0);
  EXPECT_DOUBLE_EQ(result.recall, 1.0);
  EXPECT_EQ(result.segments, 2);
  EXPECT_EQ(result.rooms, 2);
}

TEST(PrecisionRecall, MergingTwoRoomsCostsPrecisionOnly) {
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(1);
  labels(kRoomB).setTo(1);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  // One segment of 300 + 150 px whose best room is A: 300 / 450.
  EXPECT_EQ(result.segments, 1);
  EXPECT_DOUBLE_EQ(result.precision, 300.0 / 450.0);
  EXPECT_DOUBLE_EQ(result.recall, 1.0);
}

TEST(PrecisionRecall, SegmentPixelsOnAGroundTruthSeparatorCountInTheSegment) {
  // The segmenter does not see the drawn separator, so its segment covers it: |S| = 300 + 10 + 150.
  cv::Mat labels = empty_labels();
  labels(cv::Rect(1, 1, 46, 10)).setTo(1);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  EXPECT_DOUBLE_EQ(result.precision, 300.0 / 460.0);
  EXPECT_DOUBLE_EQ(result.recall, 1.0);
}

TEST(PrecisionRecall, SplittingARoomCostsRecallOnly) {
  cv::Mat labels = empty_labels();
  labels(cv::Rect(1, 1, 18, 10)).setTo(1);   // 180 px of A
  labels(cv::Rect(19, 1, 12, 10)).setTo(2);  // 120 px of A
  labels(kRoomB).setTo(3);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  EXPECT_EQ(result.segments, 3);
  EXPECT_DOUBLE_EQ(result.precision, 1.0);
  // recall_A = 180 / 300, recall_B = 1.
  EXPECT_DOUBLE_EQ(result.recall, (0.6 + 1.0) / 2.0);
  ASSERT_EQ(result.room_recall.size(), 2u);
}

TEST(PrecisionRecall, UnlabelledPixelsAreNotRecalled) {
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(1);
  labels(cv::Rect(1, 1, 5, 10)).setTo(0);  // 50 px of A left without a room
  labels(kRoomB).setTo(2);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  EXPECT_DOUBLE_EQ(result.precision, 1.0);
  EXPECT_DOUBLE_EQ(result.recall, (250.0 / 300.0 + 1.0) / 2.0);
}

TEST(PrecisionRecall, RoomsOfAtMostOneHundredPixelsAreIgnored) {
  cv::Mat gt = two_room_ground_truth();
  gt(cv::Rect(1, 13, 10, 5)).setTo(255);   // 50 px: ignored
  gt(cv::Rect(13, 13, 10, 7)).setTo(255);   // 70 px, touching the bottom border: ignored
  gt(cv::Rect(25, 12, 20, 5)).setTo(255);  // 100 px: ignored (the rule is "<= 100")
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(1);
  labels(kRoomB).setTo(2);
  const PrecisionRecall ignored = evaluate_against_ground_truth(labels, gt);
  EXPECT_EQ(ignored.rooms, 2);
  EXPECT_DOUBLE_EQ(ignored.recall, 1.0);
  EXPECT_DOUBLE_EQ(ignored.precision, 1.0);

  gt.at<unsigned char>(17, 25) = 255;  // the 100 px room grows to 101 px and now counts, unrecalled
  const PrecisionRecall counted = evaluate_against_ground_truth(labels, gt);
  EXPECT_EQ(counted.rooms, 3);
  EXPECT_DOUBLE_EQ(counted.recall, 2.0 / 3.0);
}

TEST(PrecisionRecall, SegmentsOfAtMostOneHundredPixelsAreIgnored) {
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(1);
  labels(cv::Rect(1, 1, 10, 10)).setTo(5);  // a 100 px segment inside A: ignored entirely
  labels(kRoomB).setTo(2);
  labels(cv::Rect(40, 12, 5, 5)).setTo(9);  // a 25 px speck on obstacle: ignored
  const PrecisionRecall result = evaluate_against_ground_truth(labels, two_room_ground_truth());
  EXPECT_EQ(result.segments, 2);
  EXPECT_DOUBLE_EQ(result.precision, 1.0);
  // The ignored segment's pixels are not recalled: recall_A = 200 / 300.
  EXPECT_DOUBLE_EQ(result.recall, (200.0 / 300.0 + 1.0) / 2.0);
}

TEST(PrecisionRecall, SegmentPixelsInAnIgnoredGroundTruthRoomLowerPrecision) {
  cv::Mat gt = two_room_ground_truth();
  gt(cv::Rect(1, 12, 10, 5)).setTo(255);  // a 50 px GT "room", ignored
  cv::Mat labels = empty_labels();
  labels(kRoomA).setTo(1);
  labels(cv::Rect(1, 12, 10, 5)).setTo(1);  // same label, not connected: still one segment
  labels(kRoomB).setTo(2);
  const PrecisionRecall result = evaluate_against_ground_truth(labels, gt);
  EXPECT_DOUBLE_EQ(result.precision, (300.0 / 350.0 + 1.0) / 2.0);
  EXPECT_DOUBLE_EQ(result.recall, 1.0);
}

TEST(PrecisionRecall, FreeMeansBrighterThan250) {
  cv::Mat gt(20, 50, CV_8UC1, cv::Scalar(0));
  gt(cv::Rect(1, 1, 15, 10)).setTo(254);
  gt(cv::Rect(16, 1, 1, 10)).setTo(250);  // not free: separates the two rooms
  gt(cv::Rect(17, 1, 15, 10)).setTo(251);
  gt(cv::Rect(33, 1, 15, 10)).setTo(128);  // unknown grey: not a room
  const cv::Mat rooms = ground_truth_rooms(gt);
  ASSERT_EQ(rooms.type(), CV_32SC1);
  double max_label = 0;
  cv::minMaxLoc(rooms, nullptr, &max_label);
  EXPECT_EQ(max_label, 2);
  EXPECT_NE(rooms.at<int>(1, 1), 0);
  EXPECT_NE(rooms.at<int>(1, 17), 0);
  EXPECT_NE(rooms.at<int>(1, 1), rooms.at<int>(1, 17));
  EXPECT_EQ(rooms.at<int>(1, 16), 0);
  EXPECT_EQ(rooms.at<int>(1, 33), 0);
  EXPECT_EQ(rooms.at<int>(0, 0), 0);

  cv::Mat labels = empty_labels();
  labels(cv::Rect(1, 1, 31, 10)).setTo(1);  // covers both rooms and the 250 line
  const PrecisionRecall result = evaluate_against_ground_truth(labels, gt);
  EXPECT_EQ(result.rooms, 2);
  EXPECT_DOUBLE_EQ(result.precision, 150.0 / 310.0);
  EXPECT_DOUBLE_EQ(result.recall, 1.0);
}

TEST(PrecisionRecall, GroundTruthRoomsAreEightConnected) {
  // Two 11 x 11 squares that touch only at a corner form one room.
  cv::Mat gt(30, 30, CV_8UC1, cv::Scalar(0));
  gt(cv::Rect(0, 0, 11, 11)).setTo(255);
  gt(cv::Rect(11, 11, 11, 11)).setTo(255);
  const cv::Mat rooms = ground_truth_rooms(gt);
  EXPECT_EQ(rooms.at<int>(0, 0), rooms.at<int>(21, 21));
  EXPECT_NE(rooms.at<int>(0, 0), 0);

  cv::Mat labels(30, 30, CV_32SC1, cv::Scalar(0));
  labels(cv::Rect(0, 0, 11, 11)).setTo(1);
  labels(cv::Rect(11, 11, 11, 11)).setTo(2);
  const PrecisionRecall result = precision_recall(labels, rooms);
  EXPECT_EQ(result.rooms, 1);
  EXPECT_DOUBLE_EQ(result.recall, 0.5);
  EXPECT_DOUBLE_EQ(result.precision, 1.0);
}

TEST(PrecisionRecall, LabelValuesAndTypesDoNotMatter) {
  cv::Mat labels = empty_labels();
  labels(cv::Rect(1, 1, 18, 10)).setTo(1);
  labels(cv::Rect(19, 1, 28, 10)).setTo(2);
  const PrecisionRecall reference = evaluate_against_ground_truth(labels, two_room_ground_truth());

  cv::Mat relabelled = empty_labels();
  relabelled.setTo(60000, labels == 1);
  relabelled.setTo(17, labels == 2);
  cv::Mat sixteen_bit;
  relabelled.convertTo(sixteen_bit, CV_16U);
  const PrecisionRecall other = evaluate_against_ground_truth(sixteen_bit, two_room_ground_truth());
  EXPECT_DOUBLE_EQ(other.precision, reference.precision);
  EXPECT_DOUBLE_EQ(other.recall, reference.recall);
  // Hand check: segment 2 = 120 px of A + 10 separator px + 150 px of B -> 150 / 280.
  EXPECT_DOUBLE_EQ(reference.precision, (1.0 + 150.0 / 280.0) / 2.0);
  EXPECT_DOUBLE_EQ(reference.recall, (180.0 / 300.0 + 1.0) / 2.0);
}

TEST(PrecisionRecall, NoSegmentsGivesZeroPrecisionAndRecall) {
  const PrecisionRecall result = evaluate_against_ground_truth(empty_labels(), two_room_ground_truth());
  EXPECT_EQ(result.segments, 0);
  EXPECT_EQ(result.precision, 0.0);
  EXPECT_EQ(result.recall, 0.0);
}

TEST(PrecisionRecall, RejectsBadInput) {
  const cv::Mat gt = two_room_ground_truth();
  EXPECT_THROW(evaluate_against_ground_truth(cv::Mat(10, 10, CV_32SC1, cv::Scalar(0)), gt), Error);
  cv::Mat negative = empty_labels();
  negative.at<int>(3, 3) = -1;
  EXPECT_THROW(evaluate_against_ground_truth(negative, gt), Error);
  EXPECT_THROW(evaluate_against_ground_truth(cv::Mat(20, 50, CV_32FC1, cv::Scalar(1)), gt), Error);
  EXPECT_THROW(evaluate_against_ground_truth(cv::Mat(20, 50, CV_32SC3, cv::Scalar(1)), gt), Error);
  EXPECT_THROW(evaluate_against_ground_truth(empty_labels(), cv::Mat(20, 50, CV_8UC1, cv::Scalar(0))), Error);
  EXPECT_THROW(ground_truth_rooms(cv::Mat()), Error);
  EXPECT_THROW(ground_truth_rooms(cv::Mat(20, 50, CV_8UC3, cv::Scalar(255, 255, 255))), Error);
}

class GroundTruthFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("topocut_gt_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(GroundTruthFile, LoadsColourAsGreyAndTransparentAsObstacle) {
  cv::Mat bgra(4, 4, CV_8UC4, cv::Scalar(255, 255, 255, 255));
  bgra.at<cv::Vec4b>(0, 0) = cv::Vec4b(254, 254, 254, 255);
  bgra.at<cv::Vec4b>(1, 1) = cv::Vec4b(255, 255, 255, 0);  // transparent white
  bgra.at<cv::Vec4b>(2, 2) = cv::Vec4b(0, 0, 0, 255);
  ASSERT_TRUE(topocut::testing::write_test_image(path("rgba.png"), bgra));
  const cv::Mat grey = load_ground_truth(path("rgba.png"));
  ASSERT_EQ(grey.type(), CV_8UC1);
  EXPECT_EQ(grey.at<unsigned char>(0, 0), 254);
  EXPECT_EQ(grey.at<unsigned char>(1, 1), 0);
  EXPECT_EQ(grey.at<unsigned char>(2, 2), 0);
  EXPECT_EQ(grey.at<unsigned char>(3, 3), 255);

  cv::Mat bgr(4, 4, CV_8UC3, cv::Scalar(251, 251, 251));
  ASSERT_TRUE(topocut::testing::write_test_image(path("rgb.png"), bgr));
  EXPECT_EQ(load_ground_truth(path("rgb.png")).at<unsigned char>(2, 3), 251);

  cv::Mat sixteen(4, 4, CV_16UC1, cv::Scalar(65535));
  ASSERT_TRUE(topocut::testing::write_test_image(path("grey16.png"), sixteen));
  EXPECT_EQ(load_ground_truth(path("grey16.png")).at<unsigned char>(0, 0), 255);
}

TEST_F(GroundTruthFile, MissingOrUndecodableFileIsAnError) {
  EXPECT_THROW(load_ground_truth(path("missing.png")), Error);
  {
    std::FILE* f = std::fopen(path("junk.png").c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("not a png", f);
    std::fclose(f);
  }
  EXPECT_THROW(load_ground_truth(path("junk.png")), Error);
}

}  // namespace
}  // namespace topocut
