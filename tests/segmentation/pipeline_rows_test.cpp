// The pipeline is the rule list (segmentation_rules.h): both schedules, segment() and the
// incremental update, run exactly the rows that are on, in the list's order, and each row has the one
// function its stage calls. A stage run outside the list, skipped or run out of order fails here.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segmentation_rules.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {
namespace {

// A corridor (14.6 m x 1.6 m at 0.05 m) and four rooms above it, each with a 0.9 m door into it.
struct Offices {
  OccupancyGrid grid;
  std::vector<cv::Rect> doors;
  Offices() {
    grid.cells = cv::Mat(160, 300, CV_8UC1, cv::Scalar(kOccupied));
    grid.resolution = 0.05;
    grid.cells(cv::Rect(4, 124, 292, 32)).setTo(kFree);
    const int widths[4] = {70, 60, 80, 66};
    int x = 4;
    for (const int width : widths) {
      grid.cells(cv::Rect(x, 4, width, 116)).setTo(kFree);
      doors.emplace_back(x + width / 2 - 9, 120, 18, 4);
      grid.cells(doors.back()).setTo(kFree);
      x += width + 4;
    }
  }
};

bool per_component(RuleStage stage) {
  return stage == RuleStage::kOutline || stage == RuleStage::kCut || stage == RuleStage::kDecompose || stage == RuleStage::kMerge;
}

// The rows a schedule runs under options, in list order: those that are on and have a step (the
// merge criteria are asked inside merge); whole-map rows only when whole is.
std::vector<std::string> rows_to_run(const SegmentOptions& options, bool whole) {
  std::vector<std::string> names;
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.is_on(options) && !rule.judge && (whole || !rule.whole_map)) names.push_back(rule.name);
  return names;
}

std::size_t position(const std::string& name) {
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  const auto at = std::find_if(rules.begin(), rules.end(), [&](const SegmentationRule& r) { return r.name == name; });
  EXPECT_NE(at, rules.end()) << name << " is no row of the list";
  return static_cast<std::size_t>(at - rules.begin());
}

// The trace runs the list's rows in order, going back only from one component's rows to the next
// component's (or a retry's); its rows, each named once in the order first run, are expected.
void expect_runs_list(const std::vector<std::string>& trace, const std::vector<std::string>& expected) {
  std::vector<std::string> first_runs;
  for (const std::string& name : trace)
    if (std::find(first_runs.begin(), first_runs.end(), name) == first_runs.end()) first_runs.push_back(name);
  EXPECT_EQ(first_runs, expected);
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  for (std::size_t k = 1; k < trace.size(); ++k) {
    const std::size_t before = position(trace[k - 1]), now = position(trace[k]);
    if (now >= before || before >= rules.size() || now >= rules.size()) continue;
    EXPECT_TRUE(per_component(rules[before].stage) && per_component(rules[now].stage))
        << trace[k] << " runs again after " << trace[k - 1];
  }
}

TEST(PipelineRows, EachRowHasTheFunctionOfItsStageAndNoOther) {
  for (const SegmentationRule& rule : segmentation_rules()) {
    SCOPED_TRACE(rule.name);
    ASSERT_TRUE(rule.is_on);
    EXPECT_EQ(rule.stage == RuleStage::kClean, static_cast<bool>(rule.clean));
    EXPECT_EQ(rule.stage == RuleStage::kOutline, static_cast<bool>(rule.outline));
    EXPECT_EQ(rule.stage == RuleStage::kCut, static_cast<bool>(rule.find_cuts));
    EXPECT_EQ(rule.stage == RuleStage::kDecompose, static_cast<bool>(rule.decompose));
    EXPECT_EQ(rule.stage == RuleStage::kMerge, rule.judge || rule.on_component);
    EXPECT_FALSE(rule.judge && rule.on_component);
    EXPECT_EQ(rule.stage == RuleStage::kRooms, static_cast<bool>(rule.on_rooms));
    EXPECT_EQ(rule.stage == RuleStage::kLabel, static_cast<bool>(rule.label));
    EXPECT_EQ(rule.stage == RuleStage::kLeaveOut, static_cast<bool>(rule.leave_out));
    EXPECT_EQ(rule.stage == RuleStage::kDescribe, static_cast<bool>(rule.describe));
    EXPECT_TRUE(!rule.whole_map || rule.stage == RuleStage::kDescribe || rule.stage == RuleStage::kLeaveOut);
  }
}

TEST(PipelineRows, TheStagesComeInPipelineOrder) {
  // Each schedule runs a stage's rows together, so the list reads as it runs only while its stages
  // never go back.
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  for (std::size_t k = 1; k < rules.size(); ++k) EXPECT_LE(rules[k - 1].stage, rules[k].stage) << rules[k].name;
}

TEST(PipelineRows, SegmentRunsTheRowsThatAreOnInListOrder) {
  const Offices offices;
  std::vector<SegmentOptions> runs{SegmentOptions{}, parity_segment_options()};
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!rule.turn_off) continue;
    runs.emplace_back();
    rule.turn_off(runs.back());
  }
  for (const SegmentOptions& options : runs) {
    const std::vector<std::string> expected = rows_to_run(options, true);
    SCOPED_TRACE(::testing::PrintToString(expected));
    const RuleTrace trace;
    const Segmentation s = segment(offices.grid, options);
    EXPECT_GE(s.rooms.size(), 2u);
    expect_runs_list(trace.rows(), expected);
  }
}

TEST(PipelineRows, TheIncrementalUpdateRunsTheRowsThatAreOnInListOrder) {
  // A door opened: the update segments the room behind it and the corridor again in a window (not the
  // corridor's other neighbours: that would be every room, a batch update), through the same rows
  // but the whole-map ones (room kinds, which it measures on the rooms it changed).
  const Offices offices;
  OccupancyGrid closed = offices.grid;
  closed.cells = offices.grid.cells.clone();
  closed.cells(offices.doors[2]).setTo(kOccupied);
  IncrementalOptions options;
  options.neighbours_across_doors = false;
  IncrementalSegmenter segmenter(options);
  segmenter.update(closed);
  const RuleTrace trace;
  segmenter.update(offices.grid);
  ASSERT_EQ(segmenter.last_update().kind, IncrementalUpdateReport::Kind::kIncremental) << segmenter.last_update().reason;
  expect_runs_list(trace.rows(), rows_to_run(IncrementalOptions{}.segment, false));
}

TEST(PipelineRows, ATraceListsOnlyWhatRanWhileItLived) {
  const Offices offices;
  segment(offices.grid);
  const RuleTrace trace;
  EXPECT_TRUE(trace.rows().empty());
  segment(offices.grid);
  const std::vector<std::string> rows = trace.rows();
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows.front(), "clean");
  EXPECT_EQ(rows.back(), "room-kinds");
}

// The list describes each row (`topocut rules` prints it): what it does, its stage, and a switch's help
// for the rows with one; one line each, the list's order and names.
TEST(PipelineRows, TheListingIsTheListDescribed) {
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  const std::vector<RuleListing> listing = rule_listing(rules);
  ASSERT_EQ(listing.size(), rules.size());
  const std::string text = rule_list_text(rules);
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), rules.size());
  std::size_t line = 0;
  for (std::size_t i = 0; i < rules.size(); ++i) {
    const SegmentationRule& rule = rules[i];
    EXPECT_EQ(listing[i].name, rule.name);
    EXPECT_EQ(listing[i].stage, to_string(rule.stage));
    EXPECT_FALSE(rule.does.empty()) << rule.name;
    EXPECT_EQ(rule.does.find('\n'), std::string::npos) << rule.name;
    EXPECT_EQ(rule.help.empty(), !rule.turn_off) << rule.name << ": a switch has help, a row without one none";
    const std::string switch_name = rule.turn_off ? "no-" + rule.name : "";
    EXPECT_EQ(listing[i].switch_name, switch_name) << rule.name;
    // Built piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + a temporary string.
    std::string stage = " ", switch_shown = " ";
    stage += to_string(rule.stage);
    stage += ' ';
    switch_shown += switch_name.empty() ? "no switch" : "--" + switch_name;
    switch_shown += ' ';
    const std::size_t end = text.find('\n', line);
    const std::string row = text.substr(line, end - line);
    EXPECT_EQ(row.rfind(rule.name + " ", 0), 0u) << row;
    EXPECT_NE(row.find(stage), std::string::npos) << row;
    EXPECT_NE(row.find(switch_shown), std::string::npos) << row;
    EXPECT_EQ(row.substr(row.size() - rule.does.size()), rule.does) << row;
    line = end + 1;
  }
}

}  // namespace
}  // namespace topocut
