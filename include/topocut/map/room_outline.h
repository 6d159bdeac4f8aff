#pragma once
// A room's outline against walls, never-seen space and other rooms, counted in cell edges: what tells a
// room people draw (walled, with doors) from a ray fan or a scrap bounded by space the sensor never saw.
// The open-rooms rule (segmentation) and the open-room defect count (evaluation) both read it.
#include <map>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/map/label_runs.h"

namespace topocut {

// The extent of each room of a label image (label_runs.h): its bounding box and cell count.
struct RoomExtent {
  cv::Rect box;
  long long cells = 0;
};
std::map<int, RoomExtent> room_extents(const LabelRuns& labels);

// Cells that count as wall for an outline (CV_8UC1, 255): occupied, or unknown within reach cells of an
// occupied cell (SLAM maps leave a rim of never-seen cells along their walls). cells: kFree / kOccupied /
// kUnknown.
cv::Mat wall_cells(const cv::Mat& cells, double reach);

struct RoomOutline {
  long long unknown = 0;                // edges to never-seen cells or off the grid
  long long ragged = 0;                 // of those, edges where the outline turns (a cell on either side is no room cell facing the same way)
  long long wall = 0;                   // edges to wall cells (wall_cells())
  std::map<int, long long> neighbours;  // edges to each other room
  // More than share of the edges against walls or never-seen space run into never-seen space, and more
  // at least ragged_share of those turn: laser rays end at ragged frontiers, drawn walls run straight.
  bool open(double share, double ragged_share) const {
    return static_cast<double>(unknown) > share * static_cast<double>(unknown + wall) &&
           static_cast<double>(ragged) >= ragged_share * static_cast<double>(unknown);
  }
};

// The 4-neighbour edges between room id (box: its extent), holes filled, and the cells around it; edges
// to free cells of no room count as none. An unknown cell with a wall or another room's cell straight on
// within band cells counts as wall (walls drawn in the unknown grey). floor, if given (CV_8UC1, nonzero:
// the free space the rooms were made of), limits other rooms' cells to it, so that rays given to a room
// make no walls.
RoomOutline room_outline(const LabelRuns& labels, int id, const cv::Rect& box, const cv::Mat& cells, const cv::Mat& walls,
                         int band, const cv::Mat& floor = cv::Mat());

}  // namespace topocut
