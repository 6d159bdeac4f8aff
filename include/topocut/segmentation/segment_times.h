#pragma once
// Where segment()'s time goes: the milliseconds of each of its stages, added up when a caller passes
// a SegmentTimes (benchmarks, profiling); nothing is read from any clock otherwise.
#include <array>
#include <cstddef>
#include <string>

#include "topocut/core/clock.h"

namespace topocut {

// segment()'s stages in pipeline order. Front end: the segmentation box, free space, cleaning,
// polygons and their simplification; cuts: the cut rules (doors, wall openings, wall lines, island
// cuts); decomposition: splitting at those cuts and DuDe on every part; merging: merge_rooms() with
// its features; open rooms: join_open_rooms(); labelling: rooms_from_pieces(); outputs: what segment()
// does with the rooms after that (door flags, labels placed back into the whole map).
enum class SegmentStage { kFrontEnd, kCuts, kDecomposition, kMerging, kOpenRooms, kLabelling, kOutputs };
inline constexpr std::size_t kSegmentStages = 7;

// "front end", "cuts", ...: the stage's name in tables.
std::string stage_name(SegmentStage stage);

struct SegmentTimes {
  ClockMs clock = thread_cpu_ms;     // the clock read between stages (set it before the first use)
  std::array<double, kSegmentStages> ms{};  // per stage, added over every call given this record

  double& operator[](SegmentStage stage) { return ms[static_cast<std::size_t>(stage)]; }
  double operator[](SegmentStage stage) const { return ms[static_cast<std::size_t>(stage)]; }
  double total() const;  // all stages
};

// Adds the time from its start to the next stage's start (or its end) to that stage of times; does
// nothing when times is null.
class StageTimer {
 public:
  StageTimer(SegmentTimes* times, SegmentStage stage);
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;
  ~StageTimer();
  // Closes the current stage and opens stage.
  void next(SegmentStage stage);

 private:
  SegmentTimes* times_;
  SegmentStage stage_;
  double start_ = 0.0;
};

}  // namespace topocut
