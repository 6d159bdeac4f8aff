// Occupancy evidence settles cells: noise that flips a cell back and forth publishes nothing, while
// evidence that keeps coming does flip it, after the counts the options promise.
#include "topocut/walls/occupancy_evidence.h"

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/core/occupancy_grid.h"

namespace topocut {
namespace {

// One cell (2, 1) of a 5 x 4 grid, observed scan by scan.
struct OneCell {
  OccupancyEvidenceOptions options;
  OccupancyEvidence evidence{cv::Size(5, 4), options};
  cv::Mat published, hits, misses;
  const cv::Point cell{2, 1};

  OneCell() {
    published = cv::Mat(cv::Size(5, 4), CV_8UC1, cv::Scalar(kUnknown));
    hits = cv::Mat::zeros(cv::Size(5, 4), CV_8UC1);
    misses = cv::Mat::zeros(cv::Size(5, 4), CV_8UC1);
  }

  // A scan that hits (or misses) the cell; returns the box of the published changes.
  cv::Rect observe(bool hit) {
    hits.setTo(cv::Scalar(0));
    misses.setTo(cv::Scalar(0));
    (hit ? hits : misses).at<unsigned char>(cell) = 255;
    return evidence.add(cv::Rect(0, 0, 5, 4), hits, misses, published);
  }
  unsigned char state() const { return published.at<unsigned char>(cell); }
};

TEST(OccupancyEvidence, TheFirstObservationPublishesTheCell) {
  OneCell free_cell, wall_cell;
  EXPECT_EQ(free_cell.observe(false), cv::Rect(2, 1, 1, 1));
  EXPECT_EQ(free_cell.state(), kFree);
  EXPECT_EQ(wall_cell.observe(true), cv::Rect(2, 1, 1, 1));
  EXPECT_EQ(wall_cell.state(), kOccupied);
  // Nothing else was touched.
  EXPECT_EQ(cv::countNonZero(free_cell.published != kUnknown), 1);
}

TEST(OccupancyEvidence, ACellFlippingUnderNoisePublishesNoChange) {
  // A free cell seen well, hit by every fourth scan (a wall's edge measured a few cm short).
  OneCell c;
  for (int i = 0; i < 10; ++i) c.observe(false);  // clamped
  for (int i = 0; i < 50; ++i) {
    EXPECT_TRUE(c.observe(i % 4 == 0).empty()) << "scan " << i;
    EXPECT_EQ(c.state(), kFree);
  }
  // A wall missed by every third scan.
  OneCell wall;
  for (int i = 0; i < 10; ++i) wall.observe(true);
  for (int i = 0; i < 50; ++i) {
    EXPECT_TRUE(wall.observe(i % 3 != 0).empty()) << "scan " << i;
    EXPECT_EQ(wall.state(), kOccupied);
  }
}

TEST(OccupancyEvidence, EvidenceThatKeepsComingFlipsTheCellAfterTheDocumentedCounts) {
  // A free cell seen well becomes occupied on the fourth hit in a row (an obstacle that stays).
  OneCell c;
  for (int i = 0; i < 10; ++i) c.observe(false);
  for (int i = 1; i <= 3; ++i) {
    EXPECT_TRUE(c.observe(true).empty()) << "hit " << i;
    EXPECT_EQ(c.state(), kFree);
  }
  EXPECT_EQ(c.observe(true), cv::Rect(2, 1, 1, 1));
  EXPECT_EQ(c.state(), kOccupied);
  // A wall seen well fades on the tenth miss in a row (a person who walked away).
  OneCell wall;
  for (int i = 0; i < 10; ++i) wall.observe(true);
  for (int i = 1; i <= 9; ++i) EXPECT_TRUE(wall.observe(false).empty()) << "miss " << i;
  EXPECT_EQ(wall.state(), kOccupied);
  EXPECT_FALSE(wall.observe(false).empty());
  EXPECT_EQ(wall.state(), kFree);
}

TEST(OccupancyEvidence, BadOptionsAreRefused) {
  auto refused = [](auto change) {
    OccupancyEvidenceOptions o;
    change(o);
    EXPECT_THROW(validate(o), Error);
    EXPECT_THROW(OccupancyEvidence(cv::Size(2, 2), o), Error);
  };
  refused([](OccupancyEvidenceOptions& o) { o.hit_probability = 0.4; });
  refused([](OccupancyEvidenceOptions& o) { o.miss_probability = 0.6; });
  refused([](OccupancyEvidenceOptions& o) { o.clamp_max = 1.0; });
  refused([](OccupancyEvidenceOptions& o) { o.free_at = 0.7; });
  refused([](OccupancyEvidenceOptions& o) { o.occupied_at = 0.99; });
  refused([](OccupancyEvidenceOptions& o) { o.miss_margin = -0.1; });
  EXPECT_NO_THROW(validate(OccupancyEvidenceOptions{}));
}

}  // namespace
}  // namespace topocut
