#include "topocut/map/room_outline.h"

#include <opencv2/imgproc.hpp>

#include "topocut/core/occupancy_grid.h"

namespace topocut {

std::map<int, RoomExtent> room_extents(const cv::Mat& labels) {
  std::map<int, RoomExtent> rooms;
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) {
      if (row[c] <= 0) continue;
      RoomExtent& room = rooms[row[c]];
      room.box = room.cells == 0 ? cv::Rect(c, r, 1, 1) : (room.box | cv::Rect(c, r, 1, 1));
      ++room.cells;
    }
  }
  return rooms;
}

cv::Mat wall_cells(const cv::Mat& cells, double reach) {
  cv::Mat distance;  // to the nearest occupied cell
  cv::distanceTransform(cells != kOccupied, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance <= reach;
}

RoomOutline room_outline(const cv::Mat& labels, int id, const cv::Rect& box, const cv::Mat& cells, const cv::Mat& walls,
                         int band, const cv::Mat& floor) {
  const cv::Rect window = cv::Rect(box.x - 1, box.y - 1, box.width + 2, box.height + 2);
  cv::Mat outside(window.size(), CV_8UC1, cv::Scalar(255));  // 255 outside the room, 0 in it
  const cv::Rect inner = window & cv::Rect(0, 0, labels.cols, labels.rows);
  outside(inner - window.tl()).setTo(0, labels(inner) == id);
  // The window's frame lies outside the room: what the fill from its corner does not reach is enclosed.
  cv::floodFill(outside, cv::Point(0, 0), cv::Scalar(128), nullptr, cv::Scalar(0), cv::Scalar(0), 4);
  RoomOutline outline;
  const auto inside_grid = [&](int r, int c) { return r >= 0 && c >= 0 && r < labels.rows && c < labels.cols; };
  // Straight on behind the unknown cell (r, c), within band cells, the first cell that is not unknown is
  // a wall or another room's: the unknown cells are a wall drawn in grey. Free cells of no room (rays the
  // cleaning removed) or of this room do not count.
  const auto drawn_wall = [&](int r, int c, int dr, int dc) {
    for (int k = 1; k <= band && inside_grid(r + k * dr, c + k * dc); ++k) {
      const int rr = r + k * dr, cc = c + k * dc;
      if (walls.at<unsigned char>(rr, cc)) return true;
      if (cells.at<unsigned char>(rr, cc) == kUnknown) continue;
      const int owner = labels.at<int>(rr, cc);
      return owner > 0 && owner != id && (floor.empty() || floor.at<unsigned char>(rr, cc) != 0);
    }
    return false;
  };
  // The room cell (wr, wc) facing out along (dr, dc): the outline turns there unless both cells beside it
  // (across the direction) are room cells facing out the same way.
  const auto ragged = [&](int wr, int wc, int dr, int dc) {
    for (const int side : {-1, 1}) {
      const int sr = wr + side * dc, sc = wc + side * dr;
      if (outside.at<unsigned char>(sr, sc) == 128 || outside.at<unsigned char>(sr + dr, sc + dc) != 128) return true;
    }
    return false;
  };
  const auto edge = [&](int wr, int wc, int dr, int dc) {
    if (outside.at<unsigned char>(wr, wc) != 128) return;  // inside the filled room
    const int r = window.y + wr, c = window.x + wc;
    if (!inside_grid(r, c)) {
      ++outline.unknown;
      return;
    }
    const int other = labels.at<int>(r, c);
    if (other > 0) {
      ++outline.neighbours[other];
    } else if (cells.at<unsigned char>(r, c) != kFree) {
      const bool wall = walls.at<unsigned char>(r, c) || (cells.at<unsigned char>(r, c) == kUnknown && drawn_wall(r, c, dr, dc));
      ++(wall ? outline.wall : outline.unknown);
      if (!wall && ragged(wr - dr, wc - dc, dr, dc)) ++outline.ragged;
    }
  };
  for (int wr = 1; wr + 1 < window.height; ++wr) {
    for (int wc = 1; wc + 1 < window.width; ++wc) {
      if (outside.at<unsigned char>(wr, wc) == 128) continue;
      edge(wr - 1, wc, -1, 0);
      edge(wr + 1, wc, 1, 0);
      edge(wr, wc - 1, 0, -1);
      edge(wr, wc + 1, 0, 1);
    }
  }
  return outline;
}

}  // namespace topocut
