#pragma once
// Batch room segmentation (pipeline A): grid → free space → polygons → decomposition → rooms.
// The stages are separate functions so that the incremental segmenter can run them on the parts
// of a map that changed and reuse the rest.
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/segmentation.h"
#include "topocut/decomposition/decompose.h"
#include "topocut/map/binarize.h"
#include "topocut/map/free_space_cleaning.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/door_cuts.h"
#include "topocut/segmentation/open_rooms.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/room_merging.h"
#include "topocut/segmentation/rooms_from_pieces.h"
#include "topocut/segmentation/segment_times.h"

namespace topocut {

struct SegmentOptions {
  double concavity = 2.5;  // tau, maximum concavity in metres (Fermin-Leon et al.: 2.5 m for all maps)
  bool decompose = true;   // false: the trivial baseline, each free-space component is one room
  BinarizeOptions binarize;  // defaults: raw free space (no inflation, no filtering)
  // The real-map front end (free_space_cleaning.h); false: the binarized free space is decomposed.
  bool clean = true;
  FreeSpaceCleaningOptions cleaning;
  // Smallest component and hole, m²: below 1 m² no room (DESIGN.md), as merging's min_room_area.
  ContourOptions contours = [] {
    ContourOptions c;
    c.min_component_area = 1.0;
    return c;
  }();
  // Douglas-Peucker tolerance of the traced outlines, cells (>= 0; 0 keeps the pixel edges): removes
  // the stair steps of slanted walls (0.71 cells at 45 degrees). Rings it would make touch stay exact.
  double simplify = 1.0;
  DoorOptions doors;  // door cuts split each component before the decomposition (door_cuts.h)
  // With merging on, DuDe cuts at this fraction (0..1] of tau: merging removes the cuts that are not
  // room boundaries, so finer pieces only add candidates.
  double oversegment = 0.5;
  // Passed to decompose(); its tau is replaced by concavity / resolution (the polygons are in cells).
  DecompositionOptions decomposition;
  RoomMergeOptions merge;  // pieces -> rooms (room_merging.h)
  OpenRoomOptions open_rooms;  // rooms bounded mostly by never-seen space join their neighbour (open_rooms.h)
  RoomLabelOptions labels; // rooms -> label image (rooms_from_pieces.h)
  RoomKindOptions kinds;   // corridor or room, measured on the final rooms (room_kinds.h)
};

// The reference behaviour (dude-algorithm.md): the options under which topocut does what the
// authors' DuDe does, so that every improvement can be measured against it.
SegmentOptions parity_segment_options(double concavity = 2.5);

// Segments the free space of grid into rooms; every free cell gets a room label. Rooms are
// numbered by their first cell in raster order. Throws Error on an invalid grid or options, or a
// map without free space. If input is given, it receives what was decomposed and labelled
// (segmentation_input()), for pictures of the cleaning; if times is given, each stage's time is
// added to it (segment_times.h).
struct SegmentationInput;
Segmentation segment(const OccupancyGrid& grid, const SegmentOptions& options = {}, SegmentationInput* input = nullptr,
                     SegmentTimes* times = nullptr);

// Stage 0: the part of grid that segment() works on (crop()): the box of its known cells with a margin
// wider than any stage looks, clipped to the grid (all of it without known cells). The same rooms as
// the whole grid, and SLAM maps are mostly unknown around the building (gmapping: 4000 x 4000 cells).
cv::Rect segmentation_box(const OccupancyGrid& grid, const SegmentOptions& options);

// Stage 1: the binarized free-space mask (options.binarize applied); throws Error if it is empty.
cv::Mat segmentation_free_space(const OccupancyGrid& grid, const SegmentOptions& options);

// Stage 2: what segment() decomposes (floor: CV_8UC1, 255 = free, cleaned when options.clean) and
// labels (labelled: the grid as cells_after_cleaning() leaves it); cleaned is empty unless
// options.clean. A cleaning that would leave no floor (a map smaller than a room) is not applied.
struct SegmentationInput {
  cv::Mat floor;
  OccupancyGrid labelled;
  CleanedFreeSpace cleaned;
  // Windowed front end only: the box (the grid's frame) of the thin parts the cleaning judged as a
  // whole (ray or not) that reach into the window but run out of the context it was given, so that only
  // a cleaning seeing all of them judges them as segment() does; empty when there are none. A window
  // grown to hold this box is given a context reaching farther along them.
  cv::Rect thin_parts_cut;
};
SegmentationInput segmentation_input(const OccupancyGrid& grid, const SegmentOptions& options);

// Stage 2 over a window of grid (a crop of it, its cells in the window's own frame): what
// segmentation_input() gives the whole grid there, computed from the window grown by
// front_end_context() cells (the reach of the binarization and the cleaning; what lies farther keeps
// no influence). No error for a window without free space: its floor is then empty of free cells.
// The windowed incremental update's front end.
SegmentationInput segmentation_input(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options);
// The same from the window grown by context cells (at least front_end_local_reach(), for a window
// without removed cells: the floor there is then segmentation_input()'s, thin parts cut aside).
SegmentationInput segmentation_input(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options,
                                     int context);

// How far (cells) a changed cell can change the front end's output (the binarization's and the
// cleaning's reach), and how much around a window the front end reads to compute it there.
int front_end_reach(const SegmentOptions& options, double resolution);
int front_end_context(const SegmentOptions& options, double resolution);
// The reach of the cleaning's floor tests alone (thin parts, obstacle specks), without the inside
// closing's: how far a change moves the front end's output when the cleaning removes no free cell
// within front_end_reach() of it, before or after (no inside or outside to judge). -1 when that does
// not apply: no cleaning, no inside closing, or a binarization that moves free cells (the removed
// cells are then not the grid's free cells off the floor).
int front_end_local_reach(const SegmentOptions& options, double resolution);

// Stages 3 to 5 over what the front end left, on any window of a map: the free-space polygons of
// input.floor, decompose_component() on each, the rule list's rows on all rooms (open rooms), the
// rooms and their labels, the passages with their doors, in input.labelled's frame (its size and
// origin). Only free cells of input.labelled where to_label is non-zero get a room (empty: every free
// cell), so that a window may hold cells of rooms it leaves alone; the rooms' kinds are then left to the
// caller (kRoom: the rooms they open onto lie partly beyond the window). segment() is this function
// over the known cells' box. Stage times are added to times, if given. options must be valid (validate()).
Segmentation segment_input(const SegmentationInput& input, const SegmentOptions& options, const cv::Mat& to_label = cv::Mat(),
                           SegmentTimes* times = nullptr);

// segment()'s stages over window of grid (its front end on the window alone): the segmentation of the
// crop, in its frame. segment() is this over segmentation_box(), placed back into the whole grid.
// Stage times are added to times, if given. options must be valid (validate()).
Segmentation segment_window(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options,
                            SegmentationInput* input = nullptr, SegmentTimes* times = nullptr);

// Stage 3a, first step: the polygon simplified ring by ring (simplify_polygon(), tolerance in
// cells), except that every ring whose simplification crosses or touches itself or another ring (a
// narrow pinch, rings a cell apart) keeps its exact outline; the exact polygon if that does not
// settle it in a few rounds. Valid input gives a valid polygon (intersecting_rings() finds none).
PolygonWithHoles simplified_where_valid(const PolygonWithHoles& exact, double tolerance);

// Stage 3a: the pieces of one free-space component (grid coordinates) and the cuts between them: the
// polygon simplified, split along its door cuts (listed in the result's doors) and each part decomposed
// at tau = concavity / resolution (times oversegment with merging), the exact polygon if the simplified
// one fails; the component itself unless options.decompose. Errors name the component's first cell.
// The simplification, cut search and decomposition times are added to times, if given.
PieceSet decompose_pieces(const FreeSpaceComponent& component, double resolution, const SegmentOptions& options,
                          SegmentTimes* times = nullptr);

// Stage 3: the rooms of one free-space component (grid coordinates of grid, the labelled grid it was
// traced from) and the cuts between them: decompose_pieces() followed by merge_rooms() with the rule
// list. Errors name the component's first cell. Stage times are added to times, if given. options must
// be valid (validate(); checked once by segment() and the incremental segmenter, not per component).
PieceSet decompose_component(const FreeSpaceComponent& component, const OccupancyGrid& grid, const SegmentOptions& options,
                             SegmentTimes* times = nullptr);

// Throws Error naming the first option outside its range (each part's table and
// segment_number_option_rows(): a range is written once).
void validate(const SegmentOptions& options);

// SegmentOptions' own numbers as options (concavity, simplify, oversegment): name, unit, range, help
// (option_table.h). Its parts have tables of their own; segment_option_rows() lists them all.
const std::vector<OptionRow<SegmentOptions>>& segment_number_option_rows();

}  // namespace topocut
