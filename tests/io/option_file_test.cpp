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
  EXPECT_EQ(refusal(dir, "quiet: 3\n"), "'quiet' in config file '" + path + "' is a switch: give true or false, not '3'");
  EXPECT_EQ(refusal(dir, "quiet: [true]\n"), "'quiet' in config file '" + path + "' is a switch: give true or false, not a list");
  EXPECT_EQ(refusal(dir, "door-width: 0x10\n"), "'door-width' in config file '" + path + "' needs a number, not '0x10'");
  EXPECT_EQ(refusal(dir, "door-width: [1, 2]\n"), "'door-width' in config file '" + path + "' takes one number, not a list");
}

// The message read_option_file throws as an OptionFileError for text, or "" when it reads it.
std::string reading_refusal(const TempDir& dir, const std::string& text) {
  try {
    topocut::read_option_file(dir.write("options.yaml", text));
  } catch (const OptionFileError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionFile, TheReaderRefusesKeysTwiceEmptyKeysAndAliasFloods) {
  // In the reader, so that --config, load_segment_options() and Python's load_options() all refuse them.
  TempDir dir;
  const std::string path = dir.file("options.yaml");
  for (const char* twice : {"quiet: false\nquiet: false\n", "quiet: true\nquiet: false\n", "door-width: 1\ndoor-width: 2\n"}) {
    const std::string key = twice[0] == 'q' ? "quiet" : "door-width";
    EXPECT_EQ(reading_refusal(dir, twice), "'" + key + "' in config file '" + path + "' is given twice (line 2)") << twice;
  }
  EXPECT_EQ(reading_refusal(dir, "door_width: 1\nquiet: true\ndoor-width: 2\n"),
            "'door-width' in config file '" + path + "' is given twice (line 3)");
  EXPECT_EQ(reading_refusal(dir, "\"\": 1\n"), "config file '" + path + "', line 1: an empty key is no option name");
  EXPECT_EQ(reading_refusal(dir, "quiet: true\n'': x\n"), "config file '" + path + "', line 2: an empty key is no option name");
  // One 100 KiB anchor aliased 20 times: 2 MiB once expanded, from a file of 100 KiB; 5 times stays under 1 MiB.
  const auto aliased = [](int times) {
    std::string text = "door-width: &big " + std::string(100 << 10, '1') + "\nlist: [";
    for (int i = 0; i < times; ++i) text += std::string(i ? ", " : "") + "*big";
    return text + "]\n";
  };
  EXPECT_EQ(reading_refusal(dir, aliased(20)),
            "config file '" + path + "': its values add up to more than 1 MiB (an anchor repeated by aliases?); give each value once");
  EXPECT_EQ(reading_refusal(dir, aliased(5)), "");
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
