#include "topocut/io/overlay.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

namespace {

constexpr int kShift = 4;  // sub-pixel bits for cv drawing functions
constexpr double kSubpixel = 1 << kShift;

// World metres to (scaled) image pixel coordinates, in cv's fixed-point form.
struct Projector {
  double res;
  Point2 origin;
  int height;
  double scale;
  cv::Point2d to_image(const Point2& w) const {
    const double u = (w.x - origin.x) / res;
    const double v = height - (w.y - origin.y) / res;
    return {u * scale - 0.5, v * scale - 0.5};
  }
  cv::Point fixed(const Point2& w) const {
    const cv::Point2d p = to_image(w);
    return {static_cast<int>(std::lround(p.x * kSubpixel)), static_cast<int>(std::lround(p.y * kSubpixel))};
  }
};

void check_sizes(const OccupancyGrid& grid, const Segmentation& s) {
  validate(grid);
  if (s.labels.type() != CV_32SC1) throw Error("the segmentation labels must be CV_32SC1");
  if (s.labels.size() != grid.cells.size())
    throw Error("the segmentation (" + std::to_string(s.labels.cols) + " x " + std::to_string(s.labels.rows) +
                ") and the map (" + std::to_string(grid.width()) + " x " + std::to_string(grid.height()) +
                ") differ in size");
}

// Which rules made the cuts (colour swatch and name per rule present), in the top-left corner: a
// reader of the overlay sees why each room boundary is there.
void draw_rule_legend(cv::Mat& image, const std::vector<Passage>& passages) {
  std::vector<CutRule> present;
  for (const Passage& p : passages)
    if (std::find(present.begin(), present.end(), p.rule) == present.end()) present.push_back(p.rule);
  std::sort(present.begin(), present.end());
  const int line = 16;
  int y = 6;
  for (const CutRule rule : present) {
    const cv::Vec3b c = cut_rule_colour(rule);
    const cv::Rect box(6, y, 130, line);
    cv::Mat patch = image(box & cv::Rect(0, 0, image.cols, image.rows));
    patch = 0.25 * patch + 0.75 * cv::Scalar(255, 255, 255);
    cv::line(image, {10, y + line / 2}, {30, y + line / 2}, cv::Scalar(c[0], c[1], c[2]), 3, cv::LINE_AA);
    cv::putText(image, to_string(rule), {36, y + line - 4}, cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
    y += line;
  }
}

}  // namespace

cv::Vec3b cut_rule_colour(CutRule rule) {
  switch (rule) {
    case CutRule::kDoor: return {30, 30, 210};
    case CutRule::kWallOpening: return {0, 140, 255};
    case CutRule::kIslandCut: return {200, 0, 200};
    case CutRule::kWallLine: return {210, 110, 0};
    case CutRule::kDecomposition: break;
  }
  return {40, 150, 40};
}

cv::Vec3b room_colour(int id) {
  // Golden-ratio hue steps keep consecutive ids (often neighbours, as ids follow the raster order)
  // far apart on the colour wheel; alternating saturation separates ids whose hues come close.
  const double golden = 0.6180339887498949;
  const double hue = std::fmod(0.11 + id * golden, 1.0);
  const unsigned char saturation = (id % 3 == 0) ? 150 : (id % 3 == 1 ? 210 : 255);
  const unsigned char value = (id % 2 == 0) ? 235 : 205;
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(static_cast<int>(hue * 180.0), saturation, value));
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr.at<cv::Vec3b>(0, 0);
}

std::vector<Point2> room_anchor_points(const Segmentation& s) {
  std::vector<Point2> anchors;
  anchors.reserve(s.rooms.size());
  if (s.labels.empty()) {
    for (const Room& room : s.rooms) anchors.push_back(room.centroid);
    return anchors;
  }
  const cv::Mat& labels = s.labels;
  const int h = labels.rows, w = labels.cols;
  auto to_world = [&](int c, int r) {
    return Point2{s.origin.x + (c + 0.5) * s.resolution, s.origin.y + (h - r - 0.5) * s.resolution};
  };
  // Distance of every room cell to the nearest cell outside its room (computed once for all rooms).
  cv::Mat interior(labels.size(), CV_8UC1, cv::Scalar(0));
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const int l = labels.at<int>(r, c);
      if (l == 0) continue;
      const bool inside = r > 0 && r < h - 1 && c > 0 && c < w - 1 && labels.at<int>(r - 1, c) == l &&
                          labels.at<int>(r + 1, c) == l && labels.at<int>(r, c - 1) == l && labels.at<int>(r, c + 1) == l;
      interior.at<unsigned char>(r, c) = inside ? 255 : 0;
    }
  }
  cv::Mat depth;
  cv::distanceTransform(interior, depth, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  int max_id = 0;
  for (const Room& room : s.rooms) max_id = std::max(max_id, room.id);
  std::vector<float> best_depth(static_cast<std::size_t>(max_id) + 1, -1.0f);
  std::vector<cv::Point> best_cell(static_cast<std::size_t>(max_id) + 1, cv::Point(-1, -1));
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const int l = labels.at<int>(r, c);
      if (l <= 0 || l > max_id) continue;
      const float d = depth.at<float>(r, c);
      if (d > best_depth[l]) {
        best_depth[l] = d;
        best_cell[l] = {c, r};
      }
    }
  }
  for (const Room& room : s.rooms) {
    const int c = static_cast<int>(std::floor((room.centroid.x - s.origin.x) / s.resolution));
    const int r = h - 1 - static_cast<int>(std::floor((room.centroid.y - s.origin.y) / s.resolution));
    const bool centroid_inside = c >= 0 && c < w && r >= 0 && r < h && labels.at<int>(r, c) == room.id &&
                                 depth.at<float>(r, c) >= 2.0f;
    if (centroid_inside || room.id <= 0 || room.id > max_id || best_cell[room.id].x < 0) {
      anchors.push_back(room.centroid);
    } else {
      anchors.push_back(to_world(best_cell[room.id].x, best_cell[room.id].y));
    }
  }
  return anchors;
}

cv::Vec3b room_kind_colour(RoomKind kind) {
  return kind == RoomKind::kCorridor ? cv::Vec3b(0, 140, 255) : cv::Vec3b(215, 150, 60);
}

cv::Mat render_overlay(const OccupancyGrid& grid, const Segmentation& s, const OverlayOptions& options) {
  check_sizes(grid, s);
  if (options.scale < 0 || options.scale > 16) throw Error("the overlay scale must lie in 0..16");
  const int w = grid.width(), h = grid.height();
  int scale = options.scale;
  if (scale == 0) scale = std::clamp((800 + std::max(w, h) - 1) / std::max(w, h), 1, 4);

  std::map<int, RoomKind> kind_of;
  for (const Room& room : s.rooms) kind_of[room.id] = room.kind;
  auto tint = [&](int l) {
    if (!options.colour_by_kind) return room_colour(l);
    const auto it = kind_of.find(l);
    return room_kind_colour(it == kind_of.end() ? RoomKind::kRoom : it->second);
  };
  cv::Mat base(grid.cells.size(), CV_8UC3);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const unsigned char cell = grid.cells.at<unsigned char>(r, c);
      const int l = s.labels.at<int>(r, c);
      cv::Vec3b colour = cell == kFree ? cv::Vec3b(255, 255, 255)
                                       : (cell == kOccupied ? cv::Vec3b(45, 45, 45) : cv::Vec3b(200, 200, 200));
      if (l > 0) {
        const cv::Vec3b room = tint(l);
        // Cells on a border between two rooms are drawn darker, so the partition reads at a glance.
        bool border = false;
        const int dr[4] = {-1, 1, 0, 0}, dc[4] = {0, 0, -1, 1};
        for (int k = 0; k < 4 && !border; ++k) {
          const int rr = r + dr[k], cc = c + dc[k];
          if (rr < 0 || rr >= h || cc < 0 || cc >= w) continue;
          const int other = s.labels.at<int>(rr, cc);
          border = other > 0 && other != l;
        }
        for (int k = 0; k < 3; ++k) {
          colour[k] = border ? static_cast<unsigned char>(room[k] * 0.55)
                             : static_cast<unsigned char>(0.55 * room[k] + 0.45 * 255.0);
        }
      }
      base.at<cv::Vec3b>(r, c) = colour;
    }
  }
  cv::Mat image;
  cv::resize(base, image, cv::Size(w * scale, h * scale), 0, 0, cv::INTER_NEAREST);

  const Projector project{s.resolution, s.origin, h, static_cast<double>(scale)};
  const std::vector<Point2> anchors = room_anchor_points(s);
  auto anchor_of = [&](int id) -> const Point2* {
    for (std::size_t i = 0; i < s.rooms.size(); ++i)
      if (s.rooms[i].id == id) return &anchors[i];
    return nullptr;
  };
  const int thin = std::max(1, scale / 2);
  if (options.draw_passages) {
    for (const Passage& p : s.passages) {
      const cv::Vec3b c = cut_rule_colour(p.rule);
      cv::line(image, project.fixed(p.cut.a), project.fixed(p.cut.b), cv::Scalar(c[0], c[1], c[2]), std::max(2, scale),
               cv::LINE_AA, kShift);
    }
    for (const Passage& p : s.passages) {
      const Point2* a = anchor_of(p.room_a);
      const Point2* b = anchor_of(p.room_b);
      if (!a || !b) continue;
      const Point2 mid = (p.cut.a + p.cut.b) / 2.0;
      const cv::Scalar ink(110, 50, 20);
      cv::line(image, project.fixed(*a), project.fixed(mid), ink, thin, cv::LINE_AA, kShift);
      cv::line(image, project.fixed(mid), project.fixed(*b), ink, thin, cv::LINE_AA, kShift);
      cv::circle(image, project.fixed(mid), static_cast<int>(kSubpixel * (1.5 + scale)), ink, cv::FILLED, cv::LINE_AA, kShift);
    }
  }
  if (options.draw_ids) {
    const double font_scale = std::clamp(0.3 * scale, 0.4, 0.9);
    const int thickness = scale >= 3 ? 2 : 1;
    for (std::size_t i = 0; i < s.rooms.size(); ++i) {
      const std::string text = std::to_string(s.rooms[i].id);
      int baseline = 0;
      const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font_scale, thickness, &baseline);
      const cv::Point2d at = project.to_image(anchors[i]);
      const cv::Point origin(static_cast<int>(std::lround(at.x - size.width / 2.0)),
                             static_cast<int>(std::lround(at.y + size.height / 2.0)));
      cv::putText(image, text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale, cv::Scalar(255, 255, 255), thickness + 3,
                  cv::LINE_AA);
      cv::putText(image, text, origin, cv::FONT_HERSHEY_SIMPLEX, font_scale, cv::Scalar(0, 0, 0), thickness, cv::LINE_AA);
    }
  }
  if (options.draw_passages && image.cols >= 300 && !s.passages.empty()) draw_rule_legend(image, s.passages);
  return image;
}

void write_overlay(const std::string& path, const OccupancyGrid& grid, const Segmentation& segmentation,
                   const OverlayOptions& options) {
  write_image_atomically(path, render_overlay(grid, segmentation, options));
}

}  // namespace topocut
