// read_option_file and apply_option_file: the YAML of --config, read once for every front end.
#include "topocut/io/option_file.h"

#include <gtest/gtest.h>

#include "io/temp_dir.h"

namespace {

using topocut::OptionFileEntry;
using topocut::OptionFileError;
using topocut::OptionRange;
using topocut::OptionRow;
using topocut::testing::TempDir;

struct Target {
  double width = 1.0;
  bool quiet = false;
};

const std::vector<OptionRow<Target>>& rows() {
  static const std::vector<OptionRow<Target>> table = {
      {"door-width", "M", "a length", OptionRange::kLength, [](const Target& t) { return t.width; },
       [](Target& t, double v) { t.width = v; }},
      {"quiet", "", "a switch", OptionRange::kSwitch, [](const Target& t) { return t.quiet ? 1.0 : 0.0; },
       [](Target& t, double v) { t.quiet = v != 0.0; }}};
  return table;
}

// The message apply_option_file throws for text, or "" when it applies.
std::string refusal(const TempDir& dir, const std::string& text, Target* target = nullptr) {
  const std::string path = dir.write("options.yaml", text);
  Target scratch;
  try {
    topocut::apply_option_file(topocut::read_option_file(path), rows(), target ? *target : scratch, "an option here");
  } catch (const topocut::Error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionFile, EntriesKeepTheFilesOrderAndSpelling) {
  TempDir dir;
  const std::string path = dir.write("o.yaml", "door_width: 0.9\nquiet: yes\nlist: [1, 2]\n");
  const std::vector<OptionFileEntry> entries = topocut::read_option_file(path);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].key, "door_width");
  EXPECT_EQ(entries[0].name, "door-width");
  EXPECT_DOUBLE_EQ(entries[0].number_value(), 0.9);
  EXPECT_TRUE(entries[1].switch_value());
  EXPECT_TRUE(entries[2].is_list);
  EXPECT_EQ(entries[2].values, (std::vector<std::string>{"1", "2"}));
  EXPECT_TRUE(topocut::read_option_file(dir.write("empty.yaml", "")).empty());
}

TEST(OptionFile, AppliesThroughTheRowsChecks) {
  TempDir dir;
  Target target;
  EXPECT_EQ(refusal(dir, "door-width: 1.5\nquiet: true\n", &target), "");
  EXPECT_DOUBLE_EQ(target.width, 1.5);
  EXPECT_TRUE(target.quiet);
  Target untouched;
  EXPECT_EQ(refusal(dir, "quiet: false\n", &untouched), "");  // as on the command line: off leaves it off
  EXPECT_FALSE(untouched.quiet);
  const std::string path = dir.file("options.yaml");
  EXPECT_EQ(refusal(dir, "door_witdh: 1\n"),
            "'door_witdh' in config file '" + path + "' is not an option here (did you mean 'door-width'?)");
  EXPECT_EQ(refusal(dir, "door-width: wide\n"), "'door-width' in config file '" + path + "' needs a number, not 'wide'");
  EXPECT_NE(refusal(dir, "door-width: -2\n").find("'door-width' in config file '" + path + "' must"), std::string::npos);
  EXPECT_EQ(refusal(dir, "quiet: 3\n"), "'quiet' in config file '" + path + "' is a switch: give true or false");
  EXPECT_EQ(refusal(dir, "door-width: [1, 2]\n"), "'door-width' in config file '" + path + "' takes one number, not a list");
}

TEST(OptionFile, ShapesAreOptionFileErrorsAndBadYamlIsNot) {
  TempDir dir;
  EXPECT_THROW(topocut::read_option_file(dir.write("a.yaml", "- one\n- two\n")), OptionFileError);
  EXPECT_THROW(topocut::read_option_file(dir.write("b.yaml", "[a, b]: 1\n")), OptionFileError);
  EXPECT_THROW(topocut::read_option_file(dir.write("c.yaml", "a: {b: 1}\n")), OptionFileError);
  try {
    topocut::read_option_file(dir.write("d.yaml", "a: [1, 2\n"));
    FAIL() << "bad YAML was read";
  } catch (const OptionFileError&) {
    FAIL() << "bad YAML is a file error, not a shape error";
  } catch (const topocut::Error& e) {
    EXPECT_NE(std::string(e.what()).find("is not valid YAML"), std::string::npos) << e.what();
  }
  EXPECT_THROW(topocut::read_option_file(dir.file("missing.yaml")), topocut::FileError);
}

}  // namespace
