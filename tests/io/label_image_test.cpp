#include "topocut/io/label_image.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "io/temp_dir.h"
#include "topocut/core/error.h"

namespace topocut {
namespace {

using testing::TempDir;

TEST(LabelImage, SixteenBitRoundTrip) {
  TempDir dir;
  const cv::Mat labels = (cv::Mat_<int>(2, 3) << 0, 1, 300, 65535, 2, 0);
  write_label_image(dir.file("l.png"), labels);
  const cv::Mat raw = cv::imread(dir.file("l.png"), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(raw.type(), CV_16UC1);
  EXPECT_EQ(raw.at<unsigned short>(0, 2), 300);
  const cv::Mat back = read_label_image(dir.file("l.png"));
  EXPECT_EQ(back.type(), CV_32SC1);
  EXPECT_EQ(cv::countNonZero(back != labels), 0);
}

TEST(LabelImage, RejectsWhatDoesNotFit) {
  TempDir dir;
  EXPECT_THROW(write_label_image(dir.file("l.png"), (cv::Mat_<int>(1, 2) << 0, 65536)), Error);
  EXPECT_THROW(write_label_image(dir.file("l.png"), (cv::Mat_<int>(1, 2) << -1, 2)), Error);
  EXPECT_THROW(write_label_image(dir.file("l.jpg"), (cv::Mat_<int>(1, 2) << 0, 2)), Error);
  EXPECT_THROW(write_label_image(dir.file("l.png"), cv::Mat()), Error);
  EXPECT_THROW(write_label_image(dir.file("missing/l.png"), (cv::Mat_<int>(1, 2) << 0, 2)), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("l.png")));
  EXPECT_THROW(read_label_image(dir.file("none.png")), Error);
  EXPECT_THROW(read_label_image(dir.write("t.png", "text")), Error);
  ASSERT_TRUE(cv::imwrite(dir.file("rgb.png"), cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3))));
  EXPECT_THROW(read_label_image(dir.file("rgb.png")), Error);
}

}  // namespace
}  // namespace topocut
