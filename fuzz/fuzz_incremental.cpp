// libFuzzer target: the incremental segmenter against segment(). Input bytes become a world (a
// wall-less strip, or walled rooms with partitions, doorways and specks of every kind) and a
// sequence of views of it: the seen part grows, shrinks or shifts, the frame grows or moves with
// it. After every update the cells the incremental result labels must be those segment() labels on
// the same grid; a map segment() refuses must be refused by the update too.
#include <algorithm>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmenter.h"

namespace {

using topocut::fuzz::ByteReader;

cv::Mat world_from(ByteReader& in, int h, int w) {
  cv::Mat world(h, w, CV_8UC1, cv::Scalar(topocut::kFree));
  if (in.next() % 3 == 0) return world;  // a strip without walls
  world.setTo(topocut::kOccupied);
  if (h > 2 && w > 2) world(cv::Rect(1, 1, w - 2, h - 2)).setTo(topocut::kFree);
  for (int k = in.next() % 4; k > 0 && w > 4; --k) {
    const int x = 2 + in.next() % (w - 4);
    world.col(x).setTo(topocut::kOccupied);
    const int y = in.next() % h;
    world(cv::Rect(x, y, 1, std::min(1 + in.next() % 8, h - y))).setTo(topocut::kFree);
  }
  const unsigned char states[3] = {topocut::kFree, topocut::kOccupied, topocut::kUnknown};
  for (int k = in.next() % 16; k > 0; --k) world.at<unsigned char>(in.next() % h, (in.next() * 256 + in.next()) % w) = states[in.next() % 3];
  return world;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  ByteReader in(data, size);
  const int h = 1 + in.next() % 48, w = 2 + (in.next() * 256 + in.next()) % 300;
  const cv::Mat world = world_from(in, h, w);
  IncrementalSegmenter segmenter;
  cv::Rect seen(0, 0, 1 + in.next() % w, 1 + in.next() % h);
  for (int step = 0; step < 6 && !in.empty(); ++step) {
    const cv::Rect frame = cv::Rect(std::max(0, seen.x - in.next() % 3), std::max(0, seen.y - in.next() % 3), w, h) &
                           cv::Rect(0, 0, w, h);
    OccupancyGrid grid{cv::Mat(frame.size(), CV_8UC1, cv::Scalar(kUnknown)), 0.05,
                       {frame.x * 0.05, (h - frame.br().y) * 0.05}};
    const cv::Rect inside = seen & frame;
    world(inside).copyTo(grid.cells(inside - frame.tl()));
    Segmentation batch;
    bool refused = false;
    try {
      batch = segment(grid);
    } catch (const Error&) {
      refused = true;
    }
    try {
      const Segmentation& s = segmenter.update(grid);
      if (!refused && cv::countNonZero((s.labels > 0) != (batch.labels > 0)) != 0)
        fuzz::fail("step " + std::to_string(step) + ": the update labels " + std::to_string(cv::countNonZero(s.labels)) +
                   " cells, segment() " + std::to_string(cv::countNonZero(batch.labels)));
    } catch (const Error&) {
      // An update of a map without free space is refused or gives no room; it never throws where
      // segment() succeeds.
      if (!refused) fuzz::fail("the update threw where segment() succeeded");
    }
    const int grow = in.next() % 48, shrink = in.next() % 4 == 0 ? in.next() % 6 : 0;
    seen = cv::Rect(seen.x + shrink, seen.y, seen.width + grow - shrink, seen.height + in.next() % 10) & cv::Rect(0, 0, w, h);
    if (seen.empty()) seen = cv::Rect(0, 0, 1, 1);
  }
  return 0;
}
