#pragma once
// Pieces -> rooms: rasterize the pieces of the free space, give every free cell a room, number the
// rooms, and turn the cuts between pieces into passages of the room graph.
#include <vector>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"
#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/core/segmentation.h"
#include "topocut/map/rasterize.h"

namespace topocut {

// Pieces of free space and the cuts that separate them, in grid coordinates (x = column,
// y = height-1-row, one unit per cell).
struct PieceSet {
  std::vector<PolygonWithHoles> pieces;
  std::vector<Segment2> cuts;  // a cut between two pieces becomes a passage; others are ignored
  std::vector<CutRule> rules;  // the rule that made each cut (parallel to cuts)

  // Adds a cut made by rule.
  void add_cut(const Segment2& cut, CutRule rule);
  // Appends other's pieces and cuts (pieces from several components, or reused ones).
  void append(const PieceSet& other);
  // The rule of a cut equal to cut, kDecomposition if there is none.
  CutRule rule_of(const Segment2& cut) const;
};

struct RoomLabelOptions {
  // Obstacles a piece covers (holes the decomposition absorbed as too small to matter: furniture,
  // pillars, sensor noise) belong to that room: their cells get its label. The floor under a
  // table is part of the room; false gives every non-free cell 0, as the reference wrapper's
  // evaluation of free cells only.
  bool cover_absorbed_obstacles = false;
};

// The fields of RoomLabelOptions as options: name, unit, range, help (option_table.h).
const std::vector<OptionRow<RoomLabelOptions>>& room_label_option_rows();

// The segmentation of grid from pieces: a piece labels the cells whose centres it contains, other free
// cells the nearest piece along free space, non-free cells 0 (covered ones too unless
// cover_absorbed_obstacles). Rooms: the pieces labelling a cell, numbered 1..N in raster order, polygon
// in metres. A cut between two rooms is a passage (metres), sorted by room ids, then by cut.
Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& pieces, const RoomLabelOptions& options = {});

// rooms_from_pieces() given the pieces' spans (polygon_spans(pieces.pieces, grid.cells.size())), for a
// caller that has rasterized them already (the open rooms' stage, when it joined none).
Segmentation rooms_from_pieces(const OccupancyGrid& grid, const PieceSet& pieces, const std::vector<CellSpan>& spans,
                               const RoomLabelOptions& options = {});

// Index of the piece containing point p (grid coordinates, even-odd over all rings), or -1.
int piece_containing(const std::vector<PolygonWithHoles>& pieces, const Point2& p);

// The points just left and right of cut a-b's midpoint (1e-3 cells off it, far below any feature of
// a pixel polygon): the two pieces a cut separates contain one each. False for a zero-length or
// non-finite cut.
bool cut_sides(const Point2& a, const Point2& b, Point2& left, Point2& right);

}  // namespace topocut
