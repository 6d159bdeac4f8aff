#include "topocut/io/rooms_svg.h"

#include <algorithm>
#include <vector>


#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/image_codec.h"
#include "topocut/io/overlay.h"

namespace topocut {

namespace {

std::string fmt(double v) {
  std::string s = fixed(v, 4);
  // Trim trailing zeros: shorter files, same values.
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string hex(const cv::Vec3b& bgr) { return format("#%02x%02x%02x", bgr[2], bgr[1], bgr[0]); }

std::string base64(const std::string& bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (b[i] << 16) | (b[i + 1] << 8) | b[i + 2];
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += table[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned v = b[i] << 16;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned v = (b[i] << 16) | (b[i + 1] << 8);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

}  // namespace

std::string rooms_to_svg(const OccupancyGrid& grid, const Segmentation& s, const SvgOptions& options) {
  validate(grid);
  if (s.labels.size() != grid.cells.size()) throw Error("the segmentation and the map differ in size");
  const double width_m = grid.width() * grid.resolution;
  const double height_m = grid.height() * grid.resolution;
  auto X = [&](const Point2& p) { return fmt(p.x - s.origin.x); };
  auto Y = [&](const Point2& p) { return fmt(height_m - (p.y - s.origin.y)); };
  const int longer = std::max(grid.width(), grid.height());
  const int scale = std::clamp((800 + longer - 1) / longer, 1, 4);
  const double line = std::max(grid.resolution, std::max(width_m, height_m) / 500.0);
  const double font = std::max(width_m, height_m) / 45.0;

  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(grid.width() * scale) + "\" height=\"" +
         std::to_string(grid.height() * scale) + "\" viewBox=\"0 0 " + fmt(width_m) + " " + fmt(height_m) + "\">\n";
  svg += "<!-- topocut rooms; user units are metres, world origin (" + fmt(s.origin.x) + ", " + fmt(s.origin.y) +
         ") at the lower-left corner -->\n";
  if (options.embed_map) {
    cv::Mat picture(grid.cells.size(), CV_8UC1, cv::Scalar(200));
    picture.setTo(255, grid.cells == kFree);
    picture.setTo(45, grid.cells == kOccupied);
    const std::string png = encode_image(picture, ".png");
    svg += "<image x=\"0\" y=\"0\" width=\"" + fmt(width_m) + "\" height=\"" + fmt(height_m) +
           "\" preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\"data:image/png;base64," +
           base64(png) + "\"/>\n";
  } else {
    svg += "<rect x=\"0\" y=\"0\" width=\"" + fmt(width_m) + "\" height=\"" + fmt(height_m) + "\" fill=\"#c8c8c8\"/>\n";
  }
  svg += "<g id=\"rooms\" fill-rule=\"evenodd\" fill-opacity=\"0.6\" stroke-width=\"" + fmt(line) + "\">\n";
  for (const Room& room : s.rooms) {
    std::string d;
    auto add_ring = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) d += (i ? " L" : "M") + X(ring[i]) + " " + Y(ring[i]);
      if (!ring.empty()) d += " Z ";
    };
    add_ring(room.polygon.outer);
    for (const Ring& hole : room.polygon.holes) add_ring(hole);
    const cv::Vec3b colour = room_colour(room.id);
    const cv::Vec3b dark(static_cast<unsigned char>(colour[0] * 0.55), static_cast<unsigned char>(colour[1] * 0.55),
                         static_cast<unsigned char>(colour[2] * 0.55));
    svg += "<path id=\"room" + std::to_string(room.id) + "\" fill=\"" + hex(colour) + "\" stroke=\"" + hex(dark) +
           "\" d=\"" + d + "\"/>\n";
  }
  svg += "</g>\n";

  const std::vector<Point2> anchors = room_anchor_points(s);
  svg += "<g id=\"passages\" stroke-linecap=\"round\">\n";
  for (const Passage& p : s.passages) {
    svg += "<line stroke=\"#d21e1e\" stroke-width=\"" + fmt(2.5 * line) + "\" x1=\"" + X(p.cut.a) + "\" y1=\"" +
           Y(p.cut.a) + "\" x2=\"" + X(p.cut.b) + "\" y2=\"" + Y(p.cut.b) + "\"/>\n";
    const Point2 mid = (p.cut.a + p.cut.b) / 2.0;
    std::string points;
    for (const int id : {p.room_a, p.room_b}) {
      for (std::size_t i = 0; i < s.rooms.size(); ++i) {
        if (s.rooms[i].id != id) continue;
        if (!points.empty()) {
          points += ' ';
          points += X(mid);
          points += ',';
          points += Y(mid);
          points += ' ';
        }
        points += X(anchors[i]);
        points += ',';
        points += Y(anchors[i]);
      }
    }
    svg += "<polyline fill=\"none\" stroke=\"#143270\" stroke-width=\"" + fmt(line) + "\" points=\"" + points + "\"/>\n";
  }
  svg += "</g>\n";
  svg += "<g id=\"ids\" font-family=\"sans-serif\" font-size=\"" + fmt(font) +
         "\" text-anchor=\"middle\" dominant-baseline=\"central\" stroke=\"#ffffff\" stroke-width=\"" + fmt(font / 6.0) +
         "\" paint-order=\"stroke\">\n";
  for (std::size_t i = 0; i < s.rooms.size(); ++i) {
    svg += "<text x=\"" + X(anchors[i]) + "\" y=\"" + Y(anchors[i]) + "\">" + std::to_string(s.rooms[i].id) + "</text>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

void write_rooms_svg(const std::string& path, const OccupancyGrid& grid, const Segmentation& segmentation,
                     const SvgOptions& options) {
  write_file_atomically(path, rooms_to_svg(grid, segmentation, options));
}

}  // namespace topocut
