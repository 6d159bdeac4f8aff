#pragma once
// The room ids of one growing map, kept from one segmentation to the next by both of the incremental
// segmenter's schedules (a whole-map update and a windowed one): an old id goes to the room that
// overlaps it most (carried_ids.h), a room that lies where one disappeared, or covers most of where
// one disappeared, takes that id back (a room that flickers, a merge undone, a cut found again, a
// room found again with newly seen space), every other room takes an id never used.
// The ledger can be saved and loaded with the ids last published, so that ids survive a restart.
#include <algorithm>
#include <iosfwd>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/geometry.h"
#include "topocut/core/segmentation.h"
#include "topocut/segmentation/carried_ids.h"

namespace topocut {

class IdLedger {
 public:
  // A ledger for a map of size cells (none by default) that has no room yet (ids start at 1).
  IdLedger() = default;
  explicit IdLedger(const cv::Size& size);
  // A ledger that has handed out the ids below next_id, rooms that disappeared lying in retired.
  IdLedger(int next_id, cv::Mat retired);

  // Ids (index = label of next, 1..labels; entry 0 unused) for a segmentation of the whole map
  // (next, CV_32SC1, the ledger's size) that follows previous (the ids published last, same size):
  // by overlap, then revived, then new. Every old id that goes to no room is retired where it lay.
  std::vector<int> carry(const cv::Mat& previous, const cv::Mat& next, int labels);

  // For labels of next (window of the map; ids[l] == 0: no id yet, -1: left alone) that lie more than
  // half where a room that disappeared lay, or cover more than half of where it lay in the map (mask:
  // next's cells that count; empty: all): that id back, if available(id); every other label without
  // an id: a new one. Returns how many are new.
  template <class Available>
  int name(const cv::Rect& window, const cv::Mat& next, const cv::Mat& mask, std::vector<int>& ids, const Available& available);

  // Room id lost its cells of row from column begin to end (excluded): a room found there later may
  // take it back.
  void retire(int row, int begin, int end, int id);

  // The map grew or moved by whole cells: the cell at (r, c) is now at (r + shift.y, c + shift.x) of a
  // map of size cells; what falls outside is forgotten.
  void move(const cv::Point& shift, const cv::Size& size);
  // Forgets where rooms lay (a new map), keeping the ids handed out.
  void clear(const cv::Size& size);

  int next_id() const { return next_id_; }  // every id handed out is below
  const cv::Mat& retired() const { return retired_; }
  // Cells of retired() that hold id (0 for an id that never disappeared).
  long long retired_cells(int id) const {
    return id > 0 && static_cast<std::size_t>(id) < retired_cells_.size() ? retired_cells_[static_cast<std::size_t>(id)] : 0;
  }
  std::size_t bytes() const { return retired_.total() * retired_.elemSize() + retired_cells_.size() * sizeof(long long); }

 private:
  void set_retired(int* cell, int id);
  void count_retired();

  int next_id_ = 1;
  cv::Mat retired_;  // CV_32SC1: where each room that disappeared last lay (its id), 0 elsewhere
  std::vector<long long> retired_cells_;  // by id: its cells in retired_ (how large it was where it lay)
};

// What a saved ledger holds: the ledger and the rooms last published (labels, resolution and
// origin; their ids), which the next segmentation of the same map carries its ids from.
struct SavedLedger {
  IdLedger ledger;
  Segmentation published;  // labels, resolution and origin only
};

// Writes ledger and published (its labels, resolution, origin) as text, rows run-length coded.
void write_ledger(std::ostream& out, const IdLedger& ledger, const Segmentation& published);
// Reads what write_ledger wrote; throws Error with one clear sentence on anything else.
SavedLedger read_ledger(std::istream& in);

template <class Available>
int IdLedger::name(const cv::Rect& window, const cv::Mat& next, const cv::Mat& mask, std::vector<int>& ids,
                   const Available& available) {
  std::vector<int> revived(ids.size(), -1);  // -1: has an id or is left alone
  for (std::size_t l = 1; l < ids.size(); ++l)
    if (ids[l] == 0) revived[l] = 0;
  revived_ids(retired_(window), next, mask, revived, [&](int id) { return id < next_id_ && available(id); }, &retired_cells_);
  int fresh = 0;
  for (std::size_t l = 1; l < ids.size(); ++l) {
    if (ids[l] != 0) continue;
    ids[l] = revived[l] > 0 ? revived[l] : next_id_++;
    fresh += revived[l] <= 0;
  }
  return fresh;
}

}  // namespace topocut
