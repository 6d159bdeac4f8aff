#pragma once
// Incremental room segmentation for a growing map (pipeline B; Fermin-Leon et al., Algorithms 3-4):
// the batch segmenter's stages (segment(): the real-map cleaning, the cut rules, DuDe, merging, open
// rooms, labelling) on two schedules. A whole-map update runs segment() itself and carries the room
// ids over by overlap; a windowed update compares the new grid with the previous one, runs segment()'s
// front end again around the change (segmentation_input() over a window), and runs segment()'s other
// stages (segment_input()) on the rooms the change touches together with the changed free space,
// every other room kept as it is, with its id, polygon and passages. Both schedules name rooms with
// one IdLedger (id_ledger.h). Work stays near the change, so an update costs what the change costs,
// not what the map does.
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/core/option_table.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

struct IncrementalOptions {
  // The batch options (segment()'s defaults), applied unchanged to every update. Not supported:
  // labels.cover_absorbed_obstacles (only cells free after the cleaning are labelled).
  SegmentOptions segment;
  // false: every update that changes a cell segments the whole map with segment() and carries the ids
  // by overlap (batch's own schedule, the reference for how calm the windowed schedule's ids are).
  bool windowed = true;
  // Newly free blobs that touch exactly one room join that room without a new decomposition, as
  // long as everything the room has taken in since its last decomposition stays within its
  // allowance: absorb_area (m²) or absorb_fraction of the room's own area, whichever is larger.
  // A blob that does not fit is decomposed together with the room. Small blobs are sensor noise
  // and wall gaps filled in (the seed ignores difference blobs below (0.5 m)²; we label them, so
  // that no free cell is ever left without a room); the fraction keeps a large room from being
  // decomposed again for every scan that adds a strip to it, while bounding how far its cells can
  // drift from what batch would do.
  double absorb_area = 0.25;
  double absorb_fraction = 0.1;
  // A newly free blob (the floor only grew) of at most absorb_area that touches several rooms where
  // they already meet is absorbed too, its cells taking the nearest of them, charged to every one's
  // allowance: a few cells seen at the cut between two rooms, which a long-range laser adds with
  // most scans, cannot join rooms that were apart (a door seen open: those do not meet there and
  // are decomposed). false: such a blob is always decomposed with every room it touches.
  bool absorb_across_rooms = true;
  // The same for obstacle specks: a blob of changed cells (free cells lost and the binarized cells
  // around them) within one room whose bounding box fits in speck_size × speck_size metres, and
  // around which the room's cells stay one piece (so it cannot split the room), leaves the room
  // without a decomposition and is charged to the same allowance. Real laser maps get such specks
  // with most scans (a chair, a person, a wall's edge a few centimetres off); 0 decomposes every
  // one again.
  double speck_size = 0.5;
  // A room is split only when split_after decompositions in a row cut the same room: a cut found
  // one scan and dropped the next (the room merging stage deciding by a hair) would otherwise hand
  // out a new id and take it back with every other scan. Until then the cut-off piece keeps the
  // room's id, and the room's polygon is its larger part. Pieces mostly of newly seen cells, and
  // parts no longer connected, are new rooms at once (a piece cut off beyond a held one counts as
  // next to the room). 1: split as soon as batch would. 5 (default): far fewer ids used and far less
  // churn at the same final rooms (benchmarks/README.md, "Calm ids by default"; a map at rest is
  // segmented whole: resegment(), the node's ~settle_after); the real-log replay uses 3
  // (wall_map_incremental_options()).
  int split_after = 5;
  // The same for merges: an old room whose cells the decomposition puts into a piece that keeps
  // another old room's id keeps its own id and cells until merge_after decompositions in a row
  // have merged it (the merging stage deciding by a hair as a room grows); until then the two are
  // decomposed together and the passage between them, if any, stays. While held, the room keeps its
  // polygon and its partner's is traced from the partner's own cells. 1: merge as soon as batch
  // would; 5 (default), with split_after (benchmarks/README.md, "Calm ids by default"); the
  // real-log replay uses 3.
  int merge_after = 5;
  // Rooms sharing a passage with a room that is decomposed again go with it (one ring), so that
  // door finding and room merging see both sides of the cut, as in batch. With false only rooms
  // joined by cuts that were not found as doors do: less work for a little recall
  // (benchmarks/README.md, "Incremental (exploration)").
  bool neighbours_across_doors = true;
  // The same for rooms sharing a passage that was not found as a door (a cut the merging stage
  // left between two rooms). With both false only the rooms the change touches are decomposed
  // again (and the partners of rooms holding back a merge): the cuts on their border stay where
  // they are, which on the real laser logs makes the slow updates faster and the ids calmer
  // (benchmarks/HISTORY.md, "Merges held back, only the touched rooms decomposed").
  bool neighbours_across_cuts = true;
  // A touched room larger than partial_area (m²; 0 = off, the default) is decomposed again only
  // within partial_margin (m) of the change: pieces touching the rest of the room keep its id
  // and cuts; only pieces wholly inside that window may become rooms. The whole room is decomposed
  // when the window would leave it in parts or merge another room into it, when it has grown by
  // partial_area since it was last decomposed whole, or while it holds back a split (else a room
  // that grows from the first scans is never cut: the pieces at its edge always join it). The real-log replay
  // uses 50 m² (wall_map_incremental_options()); on the explorations it costs some images
  // precision, so it is off by default (benchmarks/README.md, "Partial decomposition of large rooms").
  double partial_area = 0.0;
  double partial_margin = 3.0;
  // When more cells change than this fraction of the free cells (a loop closure moving the whole
  // map), every room is decomposed again: the batch result, with ids kept where rooms overlap.
  double batch_fraction = 0.5;
};

// The fields of IncrementalOptions as options (its own fields; segment: segment_option_rows()): name, unit, range, help (option_table.h).
const std::vector<OptionRow<IncrementalOptions>>& incremental_option_rows();

// What the last update did (diagnostics for tests, benchmarks and logs).
struct IncrementalUpdateReport {
  enum class Kind {
    kUnchanged,    // no cell changed: the previous result is returned as it is
    kIncremental,  // only the touched rooms were decomposed again
    kBatch,        // everything was decomposed again (first update, wholesale change, new frame)
  };
  Kind kind = Kind::kUnchanged;
  std::string reason;         // why the update was a batch one
  cv::Rect changed;           // bounding box of the changed cells, in the new grid's frame
  int changed_cells = 0;      // cells whose free / not-free state (or binarized state) changed
  int absorbed_blobs = 0;     // small newly free blobs given to an adjacent room
  int redecomposed_rooms = 0; // rooms of the previous result decomposed again
  cv::Rect region;            // window in which the decomposition ran (empty if none)
  int region_cells = 0;       // free cells decomposed again
  int partial_rooms = 0;      // rooms of the region decomposed only near the change (partial_area)
  int new_rooms = 0;          // ids handed out by this update
  int removed_rooms = 0;      // ids that disappeared
  // Whose cells may differ from the previous result's moved into this frame: every room's
  // (every_room_relabelled: a whole-map update, a new frame, a failed update before), else only
  // the rooms listed (sorted ids: rooms that appeared, disappeared, gained or lost a cell); every
  // other room keeps exactly its cells, moved by shift. So that a caller redoes per-room work
  // (placements, drawings) only for the rooms an update changed.
  bool every_room_relabelled = true;
  std::vector<int> relabelled_rooms;
  cv::Rect relabelled_box;    // holds every cell of the listed rooms still in the result (empty: none)
  cv::Point shift;            // where the previous result's cell (0, 0) lies in this one's frame
};

// Keeps the previous grid, its cleaned free space (what is decomposed), the cells the cleaning leaves
// free (what is labelled), the labels and where rooms that disappeared last lay, between updates
// (eleven bytes per cell plus the rooms and passages), and hands out stable room ids.
//
// A whole-map update (the first, a changed resolution, a frame that no longer holds the previous one,
// more than batch_fraction of the free cells changed, resegment(), every update when windowed is
// false) is segment() on the grid, with each room's id carried by overlap (carried_ids.h): on a fresh
// segmenter its result equals segment()'s, ids included. A windowed update cleans the free space
// again within the cleaning's reach of the change (ray fans, specks; what lies farther keeps its last
// cleaning) and promises: every cell left free by the cleaning carries exactly one room label (if
// any room exists) and no other cell does; every label value is the id of one room in rooms (sorted
// by id); rooms the change did not reach (not next to a changed cell, not sharing a passage with such
// a room as the neighbours_* options say, not holding back a merge with such a room) keep their id,
// cells, polygon and passages (a room that only took in or lost a small blob keeps its polygon);
// a new room takes back the id of a room that disappeared where more than half of it lies, or more
// than half of whose last cells it covers (a merge undone, a cut found again, a room found again
// with newly seen space; revived_ids()), else an id never used before; when rooms are decomposed
// again each old id goes to the piece sharing the most cells with it (largest overlaps first, one id
// per piece), so a room cut in two keeps its id on its larger part (and the other part too while
// split_after holds the split back; a room merged into another keeps its id and cells while
// merge_after holds the merge back).
// A room larger than partial_area is decomposed only near the change: its cells farther than
// partial_margin from the changed box keep its id and its passages there stay. Ids are therefore
// stable but not contiguous (1..N is not promised, unlike segment()).
class IncrementalSegmenter {
 public:
  explicit IncrementalSegmenter(const IncrementalOptions& options = {});
  ~IncrementalSegmenter();
  IncrementalSegmenter(IncrementalSegmenter&&) noexcept;
  IncrementalSegmenter& operator=(IncrementalSegmenter&&) noexcept;

  // Segments grid, reusing the previous result where nothing changed. The grid may have grown or
  // moved (new size and/or origin, same resolution, as ROS maps grow); a changed resolution or a
  // frame that no longer contains the old one restarts from batch (ids kept where rooms overlap).
  // The result stays valid until the next update; copies of it are independent (the label image is
  // copied on write when a copy still shares it). Throws Error like segment() on an invalid grid
  // or options, and when free space exists but none is left after binarization.
  const Segmentation& update(const OccupancyGrid& grid);

  // The same, with a hint from the caller: every cell outside changed (in grid's frame) equals the
  // previous grid's cell (unknown where the previous grid did not reach). The segmenter then looks
  // only inside changed for differences. A wrong hint gives wrong rooms; an empty hint means "no
  // cell changed".
  const Segmentation& update(const OccupancyGrid& grid, const cv::Rect& changed);

  // Segments the latest grid again as a whole, as segment() does, keeping ids where rooms overlap:
  // the rooms then equal segment()'s on that grid. For a map that stopped changing (the end of a
  // log, a robot at rest) or a caller who wants batch's rooms now. Does nothing before the first update.
  const Segmentation& resegment();

  // The latest result (empty before the first update).
  const Segmentation& result() const;

  // What the latest update did.
  const IncrementalUpdateReport& last_update() const;

  // How many results this segmenter has handed out (every update and resegment(), reset() and
  // load_ledger() too, failed or not): whether a caller saw each one (last_update() compares with
  // the one before only).
  std::uint64_t results() const { return results_; }

  // Bytes held between updates: grid copy, cleaned free space, labelled cells, labels, rooms and passages.
  std::size_t state_bytes() const;

  // Writes the id ledger (id_ledger.h) with the latest rooms, so that a segmenter started later (a
  // restarted node) can give the same rooms the same ids. Throws Error before the first update.
  void save_ledger(std::ostream& out) const;

  // Forgets everything, then reads what save_ledger() wrote: the next update segments the whole map
  // and carries the saved rooms' ids by overlap (where the saved map lies on whole cells of the new
  // one), never reusing an id handed out before the save. Throws Error on a damaged ledger, leaving
  // the segmenter unchanged.
  void load_ledger(std::istream& in);

  // Forgets everything; the next update is a batch one with fresh ids.
  void reset();

  const IncrementalOptions& options() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::uint64_t results_ = 0;
};

}  // namespace topocut
