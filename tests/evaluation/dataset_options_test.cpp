#include "topocut/evaluation/dataset_options.h"

#include <gtest/gtest.h>

#include "topocut/core/error.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/segmentation/segment_switches.h"

namespace topocut {
namespace {

TEST(DatasetOptions, DefaultsRunEverythingWithTheDefaultSegmenter) {
  const DatasetArguments arguments = parse_dataset_arguments({});
  EXPECT_EQ(arguments.dataset, "../shared/datasets/bormann");
  EXPECT_TRUE(arguments.csv.empty());
  ASSERT_EQ(arguments.run.variants.size(), 2u);
  EXPECT_EQ(arguments.run.variants[0], Variant::kPlain);
  EXPECT_EQ(arguments.run.variants[1], Variant::kFurnished);
  EXPECT_TRUE(arguments.run.maps.empty());
  EXPECT_EQ(arguments.run.segment.concavity, SegmentOptions{}.concavity);
  EXPECT_EQ(arguments.run.segment.decompose, SegmentOptions{}.decompose);
}

TEST(DatasetOptions, ParsesEveryOption) {
  const DatasetArguments arguments =
      parse_dataset_arguments({"--dataset", "/data/b", "--variant=furnished", "--map", "lab_ipa", "NLB", "--csv",
                               "out.csv", "--concavity", "1.75", "--trivial", "--map=office_a"});
  EXPECT_EQ(arguments.dataset, "/data/b");
  ASSERT_EQ(arguments.run.variants.size(), 1u);
  EXPECT_EQ(arguments.run.variants[0], Variant::kFurnished);
  EXPECT_EQ(arguments.run.maps, (std::vector<std::string>{"lab_ipa", "NLB", "office_a"}));
  EXPECT_EQ(arguments.csv, "out.csv");
  EXPECT_DOUBLE_EQ(arguments.run.segment.concavity, 1.75);
  EXPECT_FALSE(arguments.run.segment.decompose);
}

TEST(DatasetOptions, VariantAllSelectsBoth) {
  DatasetArguments arguments;
  apply_dataset_option(arguments, "variant", "plain");
  ASSERT_EQ(arguments.run.variants.size(), 1u);
  apply_dataset_option(arguments, "variant", "all");
  EXPECT_EQ(arguments.run.variants.size(), 2u);
}

TEST(DatasetOptions, BadInputIsAnError) {
  EXPECT_THROW(parse_dataset_arguments({"--variant", "furnitures"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--concavity", "0"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--concavity", "-1"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--concavity", "2.5m"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--concavity", "nan"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--concavity"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--dataset", "--trivial"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--trivial=yes"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"--frobnicate"}), Error);
  EXPECT_THROW(parse_dataset_arguments({"stray"}), Error);
  DatasetArguments arguments;
  EXPECT_THROW(apply_dataset_option(arguments, "nonsense", "1"), Error);
}

TEST(DatasetOptions, EveryOptionIsInTheHelpAndAccepted) {
  const std::string help = dataset_options_help();
  // The dataset's own options, then every segmentation and map-loading flag (the library's tables).
  // name, the value given ("" for a switch): the dataset's own a text, a table's number its default.
  std::vector<std::pair<std::string, std::string>> names;
  for (const DatasetOption& option : dataset_options())
    names.emplace_back(option.name, option.value_name.empty() ? "" : option.name == "variant" ? "plain" : "x");
  const DatasetArguments defaults;
  for (const auto& row : segment_option_rows())
    names.emplace_back(row.name, row.is_switch() ? "" : shortest_number(row.get(defaults.segment)));
  for (const auto& row : map_load_option_rows())
    names.emplace_back(row.name, row.is_switch() ? "" : shortest_number(row.get(defaults.run.load)));
  EXPECT_EQ(names.size(), 4u + segment_option_rows().size() + map_load_option_rows().size());
  for (const auto& [name, value] : names) {
    EXPECT_NE(help.find("--" + name), std::string::npos) << name;
    DatasetArguments arguments;
    EXPECT_NO_THROW(apply_dataset_option(arguments, name, value)) << name;
  }
  // Defaults are printed in their shortest form.
  EXPECT_NE(help.find("(default 0.05)"), std::string::npos) << help;
  EXPECT_EQ(help.find("0.050000"), std::string::npos) << help;
}

TEST(DatasetOptions, MethodNameTellsTheBaselineApart) {
  SegmentOptions options;
  const std::string decomposing = method_name(options);
  options.decompose = false;
  EXPECT_NE(method_name(options), decomposing);
  EXPECT_NE(method_name(options).find("trivial"), std::string::npos);
}

TEST(DatasetOptions, SegmenterSwitchesReachTheOptionsAndTheMethodName) {
  DatasetArguments arguments;
  apply_dataset_option(arguments, "concavity", "3");
  apply_dataset_option(arguments, "parity", "");
  EXPECT_EQ(arguments.run.segment.concavity, 3.0);
  EXPECT_FALSE(arguments.run.segment.doors.passages);
  EXPECT_FALSE(arguments.run.segment.merge.enabled);
  EXPECT_NE(method_name(arguments.run.segment).find("parity"), std::string::npos);
  DatasetArguments other;
  apply_dataset_option(other, "no-merge", "");
  apply_dataset_option(other, "cover-obstacles", "");
  EXPECT_FALSE(other.run.segment.merge.enabled);
  EXPECT_TRUE(other.run.segment.doors.passages);
  EXPECT_TRUE(other.run.segment.labels.cover_absorbed_obstacles);
  const std::string name = method_name(other.run.segment);
  EXPECT_NE(name.find("no merge"), std::string::npos);
  EXPECT_EQ(name.find("parity"), std::string::npos);
  EXPECT_EQ(method_name(SegmentOptions{}), "topocut (tau 2.5 m)");
  apply_dataset_option(other, "oversegment", "1");
  EXPECT_EQ(other.run.segment.oversegment, 1.0);
  EXPECT_THROW(apply_dataset_option(other, "oversegment", "2"), Error);
}

}  // namespace
}  // namespace topocut

namespace topocut {
namespace {

TEST(DatasetOptions, RealMapSwitchesAndResolution) {
  const DatasetArguments a = parse_dataset_arguments(
      {"--no-clean", "--fixed-thresholds", "--no-width-steps", "--no-furniture-rule", "--resolution", "0.1"});
  EXPECT_FALSE(a.run.segment.clean);
  EXPECT_FALSE(a.run.load.detect_palette);
  EXPECT_EQ(a.run.segment.merge.step_ratio, 0.0);
  EXPECT_EQ(a.run.segment.merge.furniture_size, 0.0);
  EXPECT_DOUBLE_EQ(a.run.load.resolution, 0.1);
  EXPECT_FALSE(a.variant_given);
  EXPECT_TRUE(parse_dataset_arguments({"--variant", "plain"}).variant_given);
  EXPECT_THROW(parse_dataset_arguments({"--resolution", "0"}), Error);
  // The method name tells each switch apart from the defaults.
  EXPECT_NE(method_name(a.run.segment).find("no clean"), std::string::npos);
  EXPECT_NE(method_name(a.run.segment).find("no width-steps"), std::string::npos);
  const DatasetArguments lines = parse_dataset_arguments({"--no-wall-lines"});
  EXPECT_FALSE(lines.run.segment.doors.wall_lines);
  EXPECT_NE(method_name(lines.run.segment).find("no wall-lines"), std::string::npos);
}

}  // namespace
}  // namespace topocut
