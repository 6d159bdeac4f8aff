#include "topocut/evaluation/region_labels.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "topocut/core/error.h"
#include "io/test_images.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

TEST(RegionLabels, GreyAndSixteenBitValuesAreTheLabels) {
  cv::Mat grey(2, 3, CV_8UC1, cv::Scalar(0));
  grey.at<unsigned char>(0, 1) = 17;
  grey.at<unsigned char>(1, 2) = 255;
  const cv::Mat labels = region_labels(grey);
  ASSERT_EQ(labels.type(), CV_32SC1);
  EXPECT_EQ(labels.at<int>(0, 0), 0);
  EXPECT_EQ(labels.at<int>(0, 1), 17);
  EXPECT_EQ(labels.at<int>(1, 2), 255);
  cv::Mat wide(2, 3, CV_16UC1, cv::Scalar(0));
  wide.at<unsigned short>(1, 0) = 40000;
  EXPECT_EQ(region_labels(wide).at<int>(1, 0), 40000);
}

TEST(RegionLabels, ColoursAreNumberedByTheirRgbValueAndBlackIsNone) {
  cv::Mat colour(1, 5, CV_8UC3, cv::Scalar(0, 0, 0));  // BGR
  colour.at<cv::Vec3b>(0, 1) = {0, 0, 200};   // red 200: the largest (R, G, B)
  colour.at<cv::Vec3b>(0, 2) = {5, 10, 0};    // (0, 10, 5)
  colour.at<cv::Vec3b>(0, 3) = {0, 0, 200};   // the same red: the same region
  colour.at<cv::Vec3b>(0, 4) = {9, 0, 0};     // (0, 0, 9): the smallest
  const cv::Mat labels = region_labels(colour);
  EXPECT_EQ(labels.at<int>(0, 0), 0);
  EXPECT_EQ(labels.at<int>(0, 4), 1);
  EXPECT_EQ(labels.at<int>(0, 2), 2);
  EXPECT_EQ(labels.at<int>(0, 1), 3);
  EXPECT_EQ(labels.at<int>(0, 3), 3);
}

TEST(RegionLabels, TransparentPixelsAreNone) {
  cv::Mat rgba(1, 2, CV_8UC4, cv::Scalar(10, 20, 30, 255));
  rgba.at<cv::Vec4b>(0, 1)[3] = 100;
  const cv::Mat labels = region_labels(rgba);
  EXPECT_EQ(labels.at<int>(0, 0), 1);
  EXPECT_EQ(labels.at<int>(0, 1), 0);
  cv::Mat grey_alpha(1, 2, CV_8UC2, cv::Scalar(7, 255));
  grey_alpha.at<cv::Vec2b>(0, 0)[1] = 0;
  EXPECT_EQ(region_labels(grey_alpha).at<int>(0, 0), 0);
  EXPECT_EQ(region_labels(grey_alpha).at<int>(0, 1), 7);
}

TEST(RegionLabels, ReadsGreySixteenBitAndRgbFilesAndNamesABadOne) {
  const fs::path dir = fs::temp_directory_path() / ("topocut_region_labels_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  cv::Mat wide(4, 4, CV_16UC1, cv::Scalar(0));
  wide(cv::Rect(0, 0, 2, 4)).setTo(300);
  ASSERT_TRUE(testing::write_test_image((dir / "wide.png").string(), wide));
  cv::Mat colour(4, 4, CV_8UC3, cv::Scalar(0, 0, 0));
  colour(cv::Rect(2, 0, 2, 4)).setTo(cv::Scalar(1, 2, 3));
  ASSERT_TRUE(testing::write_test_image((dir / "colour.png").string(), colour));
  ASSERT_TRUE(testing::write_test_image((dir / "grey.png").string(), cv::Mat(4, 4, CV_8UC1, cv::Scalar(9))));
  EXPECT_EQ(read_region_labels((dir / "wide.png").string()).at<int>(3, 1), 300);
  EXPECT_EQ(read_region_labels((dir / "colour.png").string()).at<int>(3, 3), 1);
  EXPECT_EQ(read_region_labels((dir / "colour.png").string()).at<int>(3, 1), 0);
  EXPECT_EQ(read_region_labels((dir / "grey.png").string()).at<int>(0, 0), 9);
  std::ofstream(dir / "bad.png") << "not an image";
  try {
    read_region_labels((dir / "bad.png").string());
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_region_labels((dir / "absent.png").string()), Error);
  EXPECT_THROW(region_labels(cv::Mat(2, 2, CV_32FC1, cv::Scalar(1))), Error);
  EXPECT_THROW(region_labels(cv::Mat()), Error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace topocut
