// A merge rule added as a row of the rule list, to show what adding one takes. In the library a new
// merge criterion touches three files:
//   1. its file, src/segmentation/merging/NAME.cpp: the function MergeVerdict NAME(MergeCandidate&) with its
//      contract comment (merge_criteria.h says what a verdict is and what a candidate measures);
//   2. its test, tests/segmentation/merging/NAME_test.cpp, reaching it through its row
//      (find_segmentation_rule("NAME")->judge, or merge_rooms() and segment() as shipped);
//   3. its row in make_rules() (src/segmentation/segmentation_rules.cpp): name, stage, what it does (the
//      line `topocut rules` prints), is_on, judge, and with a switch turn_off and its help; beside a
//      declaration of the function, placed where it is to be asked: before learned-merge to overrule the model, after it
//      to decide with the hand rules only. A row with a turn_off gets its switch (--no-NAME in every
//      front end, --parity, the ablation) from the list; a switch of its own needs a field in
//      RoomMergeOptions to read and clear (a fourth file), a rule on with the merging (is_on: merge) none.
// Here the criterion, its row and the list it joins live in this test alone, and merge_rooms() runs
// that list.
#include <algorithm>

#include <gtest/gtest.h>

#include "topocut/segmentation/merge_criteria.h"
#include "topocut/segmentation/room_merging.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {
namespace {

constexpr double kRes = 0.05;  // m per cell: 20 cells are a metre

// The new criterion: a cut no wider than a door keeps its rooms apart, whatever comes after it.
MergeVerdict door_wide_cuts_stay(MergeCandidate& c) {
  return c.cut_length() <= 1.0 ? MergeVerdict::keep() : MergeVerdict::abstain();
}

// Its row; on while *on is.
SegmentationRule door_wide_row(const bool* on) {
  SegmentationRule row;
  row.name = "door-wide-cuts";
  row.stage = RuleStage::kMerge;
  row.does = "criterion: a cut no wider than a door keeps its rooms apart";
  row.is_on = [on](const SegmentOptions&) { return *on; };
  row.judge = door_wide_cuts_stay;
  return row;
}

// The shipped list with row inserted before the row named before.
std::vector<SegmentationRule> with_row(SegmentationRule row, const std::string& before) {
  std::vector<SegmentationRule> rules = segmentation_rules();
  const auto at = std::find_if(rules.begin(), rules.end(), [&](const SegmentationRule& r) { return r.name == before; });
  rules.insert(at, std::move(row));
  return rules;
}

// Two rooms (3 m x 3 m and 1 m x 0.9 m) joined by a 0.9 m cut, and a model that merges everything.
struct TwoRooms {
  PieceSet set;
  SegmentOptions options;
  TwoRooms() {
    set.pieces = {{{{0, 0}, {60, 0}, {60, 20}, {60, 38}, {60, 60}, {0, 60}}, {}},
                  {{{60, 20}, {80, 20}, {80, 38}, {60, 38}}, {}}};
    set.cuts = {{{60, 20}, {60, 38}}};
    options.merge.model = parse_merge_model("topocut-merge-model 1\nthreshold 0.5\nbias 5\n");
  }
  std::size_t rooms(const std::vector<SegmentationRule>& rules) const {
    return merge_rooms({}, set, cv::Mat(), kRes, options, rules).pieces.size();
  }
};

TEST(MergeRuleRow, ANewCriterionRowTakesEffectWhereTheListPutsIt) {
  const TwoRooms two;
  bool on = true;
  EXPECT_EQ(two.rooms(segmentation_rules()), 1u);  // the model merges them
  EXPECT_EQ(two.rooms(with_row(door_wide_row(&on), "learned-merge")), 2u);
  on = false;  // its switch
  EXPECT_EQ(two.rooms(with_row(door_wide_row(&on), "learned-merge")), 1u);
  // After the model it is never asked: the model answers every candidate.
  on = true;
  EXPECT_EQ(two.rooms(with_row(door_wide_row(&on), "door-cuts")), 1u);
}

TEST(MergeRuleRow, TheHandRulesAfterTheModelDecideWithoutIt) {
  TwoRooms two;
  two.options.merge.learned = false;
  two.options.merge.door_like.ratio = 0.5;     // 0.9 m over the 0.9 m side: the hand rules merge
  two.options.merge.min_room_thickness = 0.0;  // and the thin room is not folded
  EXPECT_EQ(two.rooms(segmentation_rules()), 1u);
  bool on = true;
  EXPECT_EQ(two.rooms(with_row(door_wide_row(&on), "door-ratio")), 2u);
}

// The rule list describes itself: the new row is listed where it runs, with what it does, and no
// table kept by hand needs a line for it.
TEST(MergeRuleRow, ANewRowIsListedWhereItRuns) {
  bool on = true;
  const std::vector<SegmentationRule> rules = with_row(door_wide_row(&on), "learned-merge");
  const std::vector<RuleListing> listing = rule_listing(rules);
  ASSERT_EQ(listing.size(), segmentation_rules().size() + 1);
  const auto at = std::find_if(listing.begin(), listing.end(), [](const RuleListing& r) { return r.name == "door-wide-cuts"; });
  ASSERT_NE(at, listing.end());
  EXPECT_EQ(std::next(at)->name, "learned-merge");
  EXPECT_EQ(at->stage, "merge");
  EXPECT_EQ(at->switch_name, "");  // no turn_off: no switch
  EXPECT_EQ(at->does, "criterion: a cut no wider than a door keeps its rooms apart");
  const std::string text = rule_list_text(rules);
  const std::size_t line = text.find("door-wide-cuts ");
  ASSERT_NE(line, std::string::npos) << text;
  EXPECT_LT(line, text.find("learned-merge "));
  const std::string row = text.substr(line, text.find('\n', line) - line);
  EXPECT_NE(row.find(" merge "), std::string::npos) << row;
  EXPECT_NE(row.find(" no switch "), std::string::npos) << row;
  EXPECT_TRUE(row.ends_with(" criterion: a cut no wider than a door keeps its rooms apart")) << row;
}

}  // namespace
}  // namespace topocut
