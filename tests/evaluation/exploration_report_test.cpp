// The text reports of incremental runs: update times and room stability.
#include "topocut/evaluation/exploration_report.h"

#include <string>

#include <gtest/gtest.h>

namespace topocut {
namespace {

UpdateRecord record(double incremental_ms, double batch_ms) {
  UpdateRecord u;
  u.incremental_ms = incremental_ms;
  u.incremental_wall_ms = 2.0 * incremental_ms;
  u.batch_ms = batch_ms;
  return u;
}

TEST(ExplorationReport, UpdateTimesWithoutBatch) {
  const std::string text = format_update_times({record(1.0, -1.0), record(3.0, -1.0), record(2.0, -1.0)});
  EXPECT_EQ(text,
            "incremental per update: median 2.000 ms, p95 3.000 ms, max 3.00 ms (total 6.0 ms; CPU time)\n"
            "  wall clock:           median 4.000 ms, p95 6.000 ms, max 6.00 ms\n");
}

TEST(ExplorationReport, UpdateTimesComparedWithBatchOnTheSameUpdates) {
  // Batch was timed on the second and third update only: the speed-up pairs exactly those.
  const std::string text = format_update_times({record(1.0, -1.0), record(2.0, 40.0), record(4.0, 80.0)});
  EXPECT_NE(text.find("batch per update:       median 60.000 ms, p95 80.000 ms, max 80.00 ms (2 updates compared)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("speed-up on the same updates: 20.0x (medians), 20.0x (totals)\n"), std::string::npos) << text;
}

TEST(ExplorationReport, StabilityLine) {
  StabilityReport r;
  r.churn = {0.0, 0.0, 0.5};
  r.churn_p95 = r.churn_max = 0.5;
  r.updates_with_churn = 1;
  r.rooms[1] = {};
  r.rooms[2] = {3, 1, 0};
  r.rooms_changed = r.room_changes = 1;
  r.distinct_ids = 2;
  r.final_rooms = 1;
  EXPECT_NE(format_stability(r).find("ids used 2, final rooms 1"), std::string::npos);
  EXPECT_EQ(format_stability(r),
            "churn median 0.000 %, p95 50.000 %, max 50.000 % (1 of 3 updates); rooms changed 1 of 2 (1 changes); "
            "ids used 2, final rooms 1");
}

TEST(ExplorationReport, BatchStabilityOnlyWhenCompared) {
  GridReplay run;
  EXPECT_EQ(format_batch_stability(run), "");
  run.stability.churn = {0.0, 0.01, 0.02};
  run.stability.churn_p95 = 0.02;
  run.stability.distinct_ids = 12;
  run.stability.final_rooms = 10;
  run.batch_stability.churn = {0.1, 0.0, 0.2};
  run.batch_stability.churn_median = 0.1;
  run.batch_stability.churn_p95 = run.batch_stability.churn_max = 0.2;
  run.batch_stability.updates_with_churn = 2;
  run.batch_stability.distinct_ids = 15;
  run.batch_stability.final_rooms = 10;
  // The same line as the incremental one, then the ratios: 0.02 / 0.2, 12 / 10 and 15 / 10.
  EXPECT_EQ(format_batch_stability(run),
            "batch stability (ids carried by overlap): churn median 10.000 %, p95 20.000 %, max 20.000 % (2 of 3 "
            "updates); rooms changed 0 of 0 (0 changes); ids used 15, final rooms 10\n"
            "against batch: churn p95 0.10 of batch's; ids used per final room 1.20 (batch 1.50)\n");
}

TEST(ExplorationReport, FinalRoomsSayWhenTheRestChangedThem) {
  GridReplay run;
  run.incremental.rooms.resize(4);
  run.batch.rooms.resize(4);
  run.windowed_rooms = 4;
  EXPECT_EQ(final_rooms_line(run), "final rooms: incremental 4, batch 4\n");
  run.windowed_rooms = 5;
  EXPECT_EQ(final_rooms_line(run),
            "final rooms: incremental 4 (5 before the map at rest was segmented as a whole), batch 4\n");
}

}  // namespace
}  // namespace topocut
