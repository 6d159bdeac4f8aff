#include "topocut/evaluation/exploration_frame.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "topocut/io/overlay.h"

namespace topocut {

cv::Mat render_exploration_frame(const OccupancyGrid& grid, const Segmentation& segmentation,
                                 const std::vector<Point2>& path, const Pose2& robot, const FrameOptions& options) {
  OverlayOptions overlay;
  overlay.scale = options.scale;
  overlay.draw_ids = options.draw_ids;
  overlay.draw_passages = options.draw_passages;
  cv::Mat image = render_overlay(grid, segmentation, overlay);
  const double scale = static_cast<double>(image.cols) / grid.width();
  constexpr int kShift = 4;
  constexpr double kSub = 1 << kShift;
  // World metres to fixed-point image coordinates (pixel centres at +0.5, as the overlay draws).
  auto to_image = [&](double x, double y) {
    const double u = (x - grid.origin.x) / grid.resolution * scale - 0.5;
    const double v = (grid.height() - (y - grid.origin.y) / grid.resolution) * scale - 0.5;
    return cv::Point(static_cast<int>(std::lround(u * kSub)), static_cast<int>(std::lround(v * kSub)));
  };
  const int thickness = std::max(1, static_cast<int>(std::lround(scale)));
  if (path.size() >= 2) {
    std::vector<cv::Point> line;
    line.reserve(path.size());
    for (const Point2& p : path) line.push_back(to_image(p.x, p.y));
    // A white halo under a dark line keeps the path readable over every room colour.
    cv::polylines(image, line, false, cv::Scalar(255, 255, 255), thickness + 2, cv::LINE_AA, kShift);
    cv::polylines(image, line, false, cv::Scalar(120, 40, 10), thickness, cv::LINE_AA, kShift);
  }
  const cv::Point centre = to_image(robot.x, robot.y);
  if (options.range > 0.0) {
    const int radius = static_cast<int>(std::lround(options.range / grid.resolution * scale * kSub));
    cv::circle(image, centre, radius, cv::Scalar(40, 40, 200), thickness, cv::LINE_AA, kShift);
  }
  const int body = static_cast<int>(std::lround(std::max(3.0, 0.25 / grid.resolution * scale) * kSub));
  cv::circle(image, centre, body, cv::Scalar(30, 30, 220), cv::FILLED, cv::LINE_AA, kShift);
  const cv::Point nose = to_image(robot.x + 0.4 * std::cos(robot.theta), robot.y + 0.4 * std::sin(robot.theta));
  cv::line(image, centre, nose, cv::Scalar(255, 255, 255), thickness, cv::LINE_AA, kShift);
  if (!options.caption.empty()) {
    const double font = std::max(0.5, image.cols / 1600.0);
    int baseline = 0;
    const cv::Size text = cv::getTextSize(options.caption, cv::FONT_HERSHEY_SIMPLEX, font, 2, &baseline);
    cv::rectangle(image, cv::Rect(4, 4, text.width + 12, text.height + baseline + 12), cv::Scalar(255, 255, 255), cv::FILLED);
    cv::putText(image, options.caption, cv::Point(10, 10 + text.height), cv::FONT_HERSHEY_SIMPLEX, font,
                cv::Scalar(20, 20, 20), 2, cv::LINE_AA);
  }
  return image;
}

}  // namespace topocut
