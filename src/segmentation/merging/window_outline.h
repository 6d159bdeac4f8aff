#pragma once
// What the leave-out rows share with open rooms (open_rooms.cpp defines them): a labelled room's outline
// read in a window around its cells, as the open-rooms rule reads it, and the checks on a labelling
// they take. Private to the segmentation module.
#include <optional>

#include <opencv2/core.hpp>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/map/room_outline.h"
#include "topocut/segmentation/open_rooms.h"

namespace topocut {

// The window of a grid of size cells around box (cells), wide enough that every cell a room's outline
// reads (a cell beyond its floor, band cells on) lies inside, with the occupied cells within wall_reach
// of it; inside the grid.
cv::Rect outline_window(const cv::Rect& box, const cv::Size& size, double resolution, const OpenRoomOptions& options);

// The outline of label id of labels (CV_32SC1, the grid's cells in a window; cells: the grid's cells
// there) with the open-rooms rule's wall reach and band (room_outline()); nothing when id has no cell.
std::optional<RoomOutline> window_outline(const cv::Mat& labels, int id, const cv::Mat& cells, double resolution,
                                          const OpenRoomOptions& options);

// The end of the run of cells equal to row[begin] from begin (< cols): the first column after it, or
// cols. Four cells at a compare where SSE2 is there: the leave-out rows pass over every cell of the
// labels, most of them in long runs (of 0 beyond the rooms), and a cell at a time cost them more than
// their windows (office_i_s1: 17 instructions a cell).
inline int run_end(const int* row, int begin, int cols) {
  const int id = row[begin];
  int end = begin + 1;
#if defined(__SSE2__)
  const __m128i wanted = _mm_set1_epi32(id);
  while (end + 4 <= cols &&
         _mm_movemask_epi8(_mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + end)), wanted)) == 0xFFFF)
    end += 4;
#endif
  while (end < cols && row[end] == id) ++end;
  return end;
}

// Throws Error, named after caller, unless segmentation's labels are CV_32SC1 and floor CV_8UC1, both of
// grid's size, and its rooms are numbered 1..N in order.
void check_labelled(const Segmentation& segmentation, const OccupancyGrid& grid, const cv::Mat& floor, const char* caller);

}  // namespace topocut
