#pragma once
// Room kinds: corridor or room, measured from each room's labelled cells once the rooms are final, so
// that it works whatever made the rooms (segment(), the live segmenter, people's own rooms). A corridor
// is long for its width, narrow, and opens onto several rooms; an office hallway is wider than a home's
// but far longer. The thresholds were chosen on people's room types of the r2v homes and checked on
// the Bormann offices (benchmarks/room_kinds_benchmark.cpp, benchmarks/README.md "Room kinds").
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/option_table.h"
#include "topocut/core/segmentation.h"

namespace topocut {

struct RoomKindOptions {
  // A corridor: at least openings rooms beside it, elongation at least elongation, and a mean width at
  // most width (a home's corridor) or an elongation at least hallway_elongation (an office's hallway).
  int openings = 3;
  double elongation = 2.8;
  double width = 1.1;                // metres
  double hallway_elongation = 7.0;
  double min_contact = 0.3;          // metres: a room touching another along less is not beside it
  // Metres: shapes are measured on the labels sampled every this many metres (at least every cell):
  // a corridor a metre wide still spans 6 samples, and the pass costs a fraction of sampling every
  // cell; finer sampling costs more for a slightly better corridor score (benchmarks/README.md,
  // "Room kinds").
  double sample = 0.15;
};

// The fields of RoomKindOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<RoomKindOptions>>& room_kind_option_rows();

// Throws Error unless the numbers are finite and non-negative.
void validate(const RoomKindOptions& options);

// What the kind is decided by, for one room.
struct RoomShape {
  double area = 0.0;        // m², of the labelled cells
  double mean_width = 0.0;  // m: 4 x the mean distance of the room's cells to its edge (a strip's width)
  double elongation = 0.0;  // area / mean_width² (a strip's length over its width; about 2 for a square)
  int openings = 0;         // other rooms it touches along at least RoomKindOptions::min_contact
};

// The shape of every room of labels (CV_32SC1, 0 = no room), indexed by label - 1 up to the largest
// label sampled; resolution in metres per cell. Rooms touch where they share a cut; a room's edge is wherever
// its cells end (walls, other rooms, unlabelled cells, the image border). Measured on every k-th cell
// of every k-th row, k the whole number of cells in options.sample (at least 1): a room no sample
// falls in has an empty shape (a room). Throws Error on a wrong type or a resolution that is not positive.
std::vector<RoomShape> room_shapes(const cv::Mat& labels, double resolution, const RoomKindOptions& options = {});

// The cells between two samples room_shapes() takes at resolution (metres per cell): at least 1.
int room_kind_sample_step(const RoomKindOptions& options, double resolution);

// The kind options give a room of this shape.
RoomKind room_kind(const RoomShape& shape, const RoomKindOptions& options = {});

// Sets the kind of every room of segmentation from its labels.
void assign_room_kinds(Segmentation& segmentation, const RoomKindOptions& options = {});

}  // namespace topocut
