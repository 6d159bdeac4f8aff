// `topocut rules` prints the library's rule list: its lines are the list's rows, in the list's order,
// as rule_list_text() writes them, so the pipeline's description cannot drift from what runs.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "io/temp_dir.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace {

using topocut::testing::run_cli;
using topocut::testing::TempDir;

std::vector<std::string> first_words(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) words.push_back(line.substr(0, line.find(' ')));
  return words;
}

TEST(RulesCli, PrintsTheLibrarysListInOrder) {
  TempDir dir;
  const auto r = run_cli(dir, "rules", {});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  std::vector<std::string> names;
  for (const topocut::SegmentationRule& rule : topocut::segmentation_rules()) names.push_back(rule.name);
  EXPECT_EQ(first_words(r.out), names);
  EXPECT_EQ(r.out, topocut::rule_list_text(topocut::segmentation_rules()));
  EXPECT_NE(r.out.find("--no-learned-merge"), std::string::npos) << r.out;
}

TEST(RulesCli, RefusesOperandsAndUnknownOptions) {
  TempDir dir;
  for (const std::vector<std::string>& args : {std::vector<std::string>{"map.yaml"}, std::vector<std::string>{"--no-merge"}}) {
    const auto r = run_cli(dir, "rules", args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_EQ(r.err.rfind("topocut rules: error: ", 0), 0u) << r.err;
  }
}

}  // namespace
