// The JSON of a labelled scan: two walls far apart and one invalid beam make two segments; with
// fuzzy c-means each segment lists its centres, which lie on its wall.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "topocut/labeling/labeling_json.h"
#include "topocut/labeling/segment_centres.h"

namespace topocut {
namespace {

// Beams 0..9 hit the wall x = 2 (y from -0.45 to 0.45), beam 10 is invalid, beams 11..20 hit the
// wall x = -2: two segments, far apart.
Scan two_walls() {
  Scan scan;
  for (int side = 0; side < 2; ++side) {
    const double x = side == 0 ? 2.0 : -2.0;
    for (int i = 0; i < 10; ++i) {
      const double y = -0.45 + 0.1 * i;
      scan.angles.push_back(std::atan2(y, x));
      scan.ranges.push_back(std::hypot(x, y));
    }
    if (side == 0) {
      scan.angles.push_back(M_PI / 2);
      scan.ranges.push_back(std::numeric_limits<double>::quiet_NaN());
    }
  }
  return scan;
}

TEST(LabelingJson, ListsSegmentsInvalidBeamsAndTheOptions) {
  const Scan scan = two_walls();
  LabelingOptions options;
  options.element = StructuringElement::kSquare;
  const Labeling labeling = label_scan(scan, options);
  const nlohmann::json json = nlohmann::json::parse(labeling_to_json("walls.csv", scan, options, labeling));
  EXPECT_EQ(json["scan"], "walls.csv");
  EXPECT_EQ(json["beams"], 21);
  EXPECT_EQ(json["element"], "square");
  EXPECT_EQ(json["invalid_beams"], nlohmann::json::array({10}));
  ASSERT_EQ(json["segments"].size(), 2u);
  EXPECT_EQ(json["segments"][0]["beams"].size(), 10u);
  EXPECT_EQ(json["segments"][1]["beams"][0], 11);
  EXPECT_FALSE(json["segments"][0].contains("centres"));
}

TEST(LabelingJson, CentresOfEachSegmentLieOnItsWall) {
  const Scan scan = two_walls();
  const Labeling labeling = label_scan(scan);
  FuzzyCMeansOptions fcm;
  fcm.clusters = 3;
  const auto centres = segment_centres(scan, labeling, fcm);
  ASSERT_EQ(centres.size(), 2u);
  const nlohmann::json json = nlohmann::json::parse(labeling_to_json("s", scan, {}, labeling, centres));
  for (int s = 0; s < 2; ++s) {
    const auto& list = json["segments"][s]["centres"];
    ASSERT_EQ(list.size(), 3u);
    for (const auto& c : list) EXPECT_NEAR(std::abs(c[0].get<double>()), 2.0, 1e-9);
  }
}

}  // namespace
}  // namespace topocut
