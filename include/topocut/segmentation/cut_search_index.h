#pragma once
// One polygon's edges in the grid the cut rules search (door_cuts.h, wall_openings.h, island_cuts.h,
// wall_lines.h): the rules run in turn on the same polygon with the same options, so the grid is
// built once and shared instead of once per rule.
#include <memory>

#include "topocut/core/geometry.h"

namespace topocut {

struct DoorOptions;
namespace cut_search {
struct PolygonEdges;
}

// The edges of polygon (grid coordinates) in the cut search's grid for options at resolution, and its
// reflex corners, built when a rule first asks for them. polygon must outlive the index.
class CutSearchIndex {
 public:
  CutSearchIndex(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options);
  ~CutSearchIndex();
  CutSearchIndex(const CutSearchIndex&) = delete;
  CutSearchIndex& operator=(const CutSearchIndex&) = delete;

  // The shared edges (internal to the cut rules) if they are those of this polygon at this resolution
  // and these options' grid cell, else null (the rule then builds its own).
  const cut_search::PolygonEdges* edges_for(const PolygonWithHoles& polygon, double resolution, const DoorOptions& options) const;

 private:
  const PolygonWithHoles& polygon_;
  double resolution_;
  double cell_;
  double min_turn_;
  mutable std::unique_ptr<cut_search::PolygonEdges> edges_;
};

}  // namespace topocut
