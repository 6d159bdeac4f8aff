// The cut rules' shared choice of compatible cuts: narrowest_compatible() tests each candidate against
// the accepted cuts near it only (a grid of their boxes); it must keep exactly the cuts its definition,
// every candidate against every accepted cut, keeps.
#include "segmentation/cuts/cut_search.h"

#include <tuple>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

namespace topocut::cut_search {
namespace {

// The definition: narrowest first, each candidate against every cut accepted before it.
std::vector<Candidate> every_pair(std::vector<Candidate> doors, double resolution) {
  std::sort(doors.begin(), doors.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(x.width, x.segment.a.x, x.segment.a.y, x.segment.b.x, x.segment.b.y) <
           std::tie(y.width, y.segment.a.x, y.segment.a.y, y.segment.b.x, y.segment.b.y);
  });
  const double duplicate = 0.3 / resolution;
  std::vector<Candidate> accepted;
  for (const Candidate& c : doors) {
    bool ok = true;
    for (const Candidate& taken : accepted) {
      const Segment2& s = taken.segment;
      if (segments_conflict(c.segment, s) ||
          (distance_to_segment(c.segment.a, s) < duplicate && distance_to_segment(c.segment.b, s) < duplicate) ||
          (distance_to_segment(s.a, c.segment) < duplicate && distance_to_segment(s.b, c.segment) < duplicate)) {
        ok = false;
        break;
      }
    }
    if (ok) accepted.push_back(c);
  }
  return accepted;
}

TEST(CutSearch, NarrowestCompatibleKeepsWhatTestingEveryPairKeeps) {
  cv::RNG rng(10);
  int kept = 0, dropped = 0;
  for (int round = 0; round < 40; ++round) {
    const double extent = rng.uniform(20.0, 400.0);
    std::vector<Candidate> candidates;
    for (int k = 0; k < rng.uniform(1, 150); ++k) {
      // Door-sized cuts, long wall-line cuts, repeated cuts a little apart and cuts through a shared end.
      const Point2 a{rng.uniform(-extent, extent), rng.uniform(-extent, extent)};
      const double length = rng.uniform(0, 4) == 0 ? rng.uniform(20.0, 300.0) : rng.uniform(0.5, 20.0);
      // Half of them along the axes, as most doors are: their boxes are lines.
      const double angle = rng.uniform(0, 2) == 0 ? rng.uniform(0, 2) * CV_PI / 2 : rng.uniform(0.0, CV_PI);
      Segment2 s{a, {a.x + length * std::cos(angle), a.y + length * std::sin(angle)}};
      if (!candidates.empty() && rng.uniform(0, 3) == 0) {
        const Segment2& near = candidates[static_cast<std::size_t>(rng.uniform(0, static_cast<int>(candidates.size())))].segment;
        const double dx = rng.uniform(-8.0, 8.0), dy = rng.uniform(-8.0, 8.0);
        s = rng.uniform(0, 2) == 0 ? Segment2{{near.a.x + dx, near.a.y + dy}, {near.b.x + dx, near.b.y + dy}} : Segment2{near.b, s.b};
      }
      candidates.push_back({s, rng.uniform(0, 10) == 0 ? -1.0 : distance(s.a, s.b), 0});
    }
    const std::vector<Candidate> mine = narrowest_compatible(candidates, 0.05), expected = every_pair(candidates, 0.05);
    ASSERT_EQ(mine.size(), expected.size()) << "round " << round;
    for (std::size_t i = 0; i < mine.size(); ++i) EXPECT_EQ(mine[i].segment, expected[i].segment) << "round " << round;
    kept += static_cast<int>(expected.size());
    dropped += static_cast<int>(candidates.size() - expected.size());
  }
  // Both outcomes occur often.
  EXPECT_GT(kept, 200);
  EXPECT_GT(dropped, 50);
}

}  // namespace
}  // namespace topocut::cut_search
