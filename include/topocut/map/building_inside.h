#pragma once
// The inside of a building on a grid: what the grid's edge does not reach through the open cells once
// the walls are closed across gaps (windows, doors, unseen stretches of wall). The cleaning tells rays
// into a room from rays into the open by it (its own structure: floor and walls); the open-fans rule
// tells a walled room holding a fan from a fan outside (walls only).
#include <opencv2/core.hpp>

namespace topocut {

// The cells of cells (CV_8UC1: kFree / kOccupied / kUnknown) inside the building (255, else 0): not
// reached by a 4-connected flood from beyond the grid's edge through the cells that are not occupied
// once the occupied cells are closed by a square of 2n+1 cells, n = max(1, round(closing / 2)) (closing
// in cells: gaps up to about that wide close). Nothing is inside when closing <= 0 (as the cleaning).
// The walls themselves count as inside. Costs the walls' runs, not the cells.
cv::Mat building_inside(const cv::Mat& cells, double closing);

// building_inside() of one grid, computed when first asked for and kept for the next caller with the
// same closing: the two leave-out rows (open-fans, outside-parts) read the same inside in turn. Holds a
// reference to cells, which must outlive it and stay unchanged.
class BuildingInside {
 public:
  explicit BuildingInside(const cv::Mat& cells) : cells_(cells) {}
  // building_inside(cells, closing); computed again only for another closing.
  const cv::Mat& at(double closing);

 private:
  const cv::Mat& cells_;
  double closing_ = 0.0;
  cv::Mat inside_;
};

// Whether any of cells (CV_8UC1) is kOccupied, stopping at the first: without, walls cannot be told
// from never-seen space (walls drawn in the unknown grey), and nothing is inside.
bool has_occupied_cell(const cv::Mat& cells);

}  // namespace topocut
