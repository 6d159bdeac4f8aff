#pragma once
// The result of segmenting a map into rooms: what every pipeline produces and every writer reads.
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/cut_rule.h"
#include "topocut/core/geometry.h"

namespace topocut {

// What a room is for, as far as its shape tells (segmentation/room_kinds.h measures it once the rooms
// are final): a corridor is long, narrow and opens onto several rooms; every other room is a room.
enum class RoomKind { kRoom, kCorridor };

// "room" or "corridor": a room's kind as every output names it.
inline const char* room_kind_name(RoomKind kind) { return kind == RoomKind::kCorridor ? "corridor" : "room"; }

struct Room {
  int id = 0;                // label value in Segmentation::labels, 1..N
  PolygonWithHoles polygon;  // world metres, outer CCW, holes CW
  double area = 0.0;         // m², of the polygon (what every output's "area" is)
  Point2 centroid;           // world metres, of the room's labelled cells
  // m², of the room's labelled cells: differs from area where the polygon covers cells that are no
  // room's (absorbed obstacles) or cells outside the polygon joined the room (cleaning, specks).
  double labelled_area = 0.0;
  RoomKind kind = RoomKind::kRoom;  // from the room's labelled cells (room_kinds.h)
};

// Where a room is, beyond its polygon (map frame, metres).
struct RoomPlacement {
  Point2 inside;  // centre of the room's labelled cell farthest from the room's edge (always in the room)
  Point2 min;     // lower-left corner of the polygon's bounding box
  Point2 max;     // upper-right corner
};

// A passage (door, opening) between two rooms: the cut that separates them.
struct Passage {
  int room_a = 0;
  int room_b = 0;
  Segment2 cut;         // world metres
  double width = 0.0;   // metres, length of the cut
  bool door = false;    // a door (a cut at most the door width, DoorOptions::max_width), not a wider opening
  CutRule rule = CutRule::kDecomposition;  // the pipeline rule that made the cut
};

// "door" or "opening": a passage's kind as every output names it.
inline const char* passage_kind(const Passage& passage) { return passage.door ? "door" : "opening"; }

struct Segmentation {
  cv::Mat labels;                // CV_32SC1, grid size; 0 = not a room (obstacle, unknown, rays or a fan outside the building), rooms 1..N
  std::vector<Room> rooms;       // sorted by id
  std::vector<Passage> passages; // the room graph's edges
  double resolution = 0.05;      // metres per cell of labels
  Point2 origin;                 // as OccupancyGrid::origin
};

}  // namespace topocut
