#include "topocut/core/option_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/option_choice.h"
#include "topocut/core/value_ranges.h"

namespace topocut {
namespace {

TEST(OptionTable, ShortestNumberIsReadableAndReadsBack) {
  EXPECT_EQ(shortest_number(0.05), "0.05");
  EXPECT_EQ(shortest_number(2.5), "2.5");
  EXPECT_EQ(shortest_number(250.0), "250");
  EXPECT_EQ(shortest_number(0.0), "0");
  for (const double value : {0.05, 0.1 + 0.2, 1.0 / 3.0, 1e-4, 123456.789, 0.15}) {
    EXPECT_EQ(std::stod(shortest_number(value)), value) << shortest_number(value);
  }
}

TEST(OptionTable, RangesAreCheckedWithTheOptionsName) {
  EXPECT_NO_THROW(check_option_value(OptionRange::kPositive, 0.5, "--concavity"));
  EXPECT_THROW(check_option_value(OptionRange::kPositive, 0.0, "--concavity"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kPositive, std::numeric_limits<double>::infinity(), "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kNonNegative, 0.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kNonNegative, -1e-9, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kNonNegative, std::nan(""), "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kFraction, 1.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kFraction, 0.0, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kFraction, 1.5, "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kGreyLevel, 255.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kGreyLevel, 250.5, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kGreyLevel, 256.0, "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kShare, 0.0, "x"));
  EXPECT_NO_THROW(check_option_value(OptionRange::kShare, 1.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kShare, 1.01, "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kShareBelowOne, 0.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kShareBelowOne, 1.0, "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kCount, 1.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kCount, 0.0, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kCount, 2.5, "x"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kWholeNumber, 0.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kWholeNumber, -1.0, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kWholeNumber, std::nan(""), "x"), Error);
  // A seed is any 32-bit value, and nothing past it.
  EXPECT_NO_THROW(check_option_value(OptionRange::kSeed, 4294967295.0, "x"));
  EXPECT_THROW(check_option_value(OptionRange::kSeed, 4294967296.0, "x"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kSeed, 1.5, "x"), Error);
  try {
    check_option_value(OptionRange::kPositive, -1.0, "--door-width");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--door-width must be a positive number");
  }
}

// Lengths, areas and resolutions are the library's own ranges (value_ranges.h), with its message.
TEST(OptionTable, LengthAreaAndResolutionRangesAreTheLibrarysOwn) {
  EXPECT_NO_THROW(check_option_value(OptionRange::kLength, kMaxLength, "--concavity"));
  EXPECT_THROW(check_option_value(OptionRange::kLength, 0.0, "--concavity"), Error);
  EXPECT_THROW(check_option_value(OptionRange::kLength, kMaxLength * 1.01, "--concavity"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kLengthOrZero, 0.0, "--robot-radius"));
  EXPECT_THROW(check_option_value(OptionRange::kLengthOrZero, std::nan(""), "--robot-radius"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kArea, kMaxLength * kMaxLength, "--fold-area"));
  EXPECT_THROW(check_option_value(OptionRange::kArea, -1.0, "--fold-area"), Error);
  EXPECT_NO_THROW(check_option_value(OptionRange::kResolution, kMinResolution, "--resolution"));
  EXPECT_THROW(check_option_value(OptionRange::kResolution, kMaxResolution * 2, "--resolution"), Error);
  try {
    check_option_value(OptionRange::kLength, 1e6, "--door-width");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--door-width must lie in (0, 100000] metres, got 1e+06");
  }
}

TEST(OptionTable, InRangeIsWhatTheCheckLetsThrough) {
  const OptionRange ranges[] = {OptionRange::kSwitch,      OptionRange::kPositive,      OptionRange::kNonNegative,
                                OptionRange::kFraction,    OptionRange::kGreyLevel,     OptionRange::kLength,
                                OptionRange::kLengthOrZero, OptionRange::kArea,         OptionRange::kResolution,
                                OptionRange::kShare,       OptionRange::kShareBelowOne, OptionRange::kCount,
                                OptionRange::kWholeNumber, OptionRange::kSeed,      OptionRange::kAny};
  const double values[] = {-1.0, 0.0, kMinResolution, 0.5, 1.0, 2.5, 255.0, kMaxLength, 2 * kMaxLength, kMaxLength * kMaxLength,
                           std::nan(""), std::numeric_limits<double>::infinity()};
  for (const OptionRange range : ranges)
    for (const double value : values) {
      bool passes = true;
      try {
        check_option_value(range, value, "x");
      } catch (const Error&) {
        passes = false;
      }
      EXPECT_EQ(option_value_in_range(range, value), passes) << static_cast<int>(range) << " " << value;
    }
}

// A struct checked through its table names the first row out of range, as the command line does.
TEST(OptionTable, CheckingRowsNamesTheFirstOptionOutOfRange) {
  struct Sizes {
    double width = 1.0;
    double share = 0.5;
  };
  const std::vector<OptionRow<Sizes>> rows = {field_row("width", "M", OptionRange::kLength, &Sizes::width, "w"),
                                              field_row("share", "F", OptionRange::kShare, &Sizes::share, "s")};
  Sizes sizes;
  EXPECT_NO_THROW(check_option_rows(rows, sizes));
  sizes.share = 2.0;
  try {
    check_option_rows(rows, sizes);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--share must be a share in [0, 1]");
  }
  sizes.width = 0.0;
  try {
    check_option_rows(rows, sizes);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "--width must lie in (0, 100000] metres, got 0");
  }
}

TEST(OptionTable, ANumberIsTheWholeText) {
  EXPECT_EQ(parse_option_number("2.5", "--concavity"), 2.5);
  EXPECT_EQ(parse_option_number("-1e-3", "x"), -1e-3);
  EXPECT_THROW(parse_option_number("2.5m", "x"), Error);
  EXPECT_THROW(parse_option_number("", "x"), Error);
  EXPECT_THROW(parse_option_number("metres", "x"), Error);
}


TEST(OptionTable, NumbersAreReadAsDecimalsOnly) {
  EXPECT_EQ(parse_option_number("2.5", "--x"), 2.5);
  EXPECT_EQ(parse_option_number("+2.5", "--x"), 2.5);
  EXPECT_EQ(parse_option_number("-1e-3", "--x"), -1e-3);
  EXPECT_EQ(parse_option_number(".5", "--x"), 0.5);
  EXPECT_TRUE(std::isnan(parse_option_number("nan", "--x")));  // read, for the range to refuse by name
  EXPECT_TRUE(std::isinf(parse_option_number("inf", "--x")));
  for (const std::string bad : {"0x10", "0X1p3", " 1", "1 ", "1,5", "", "+", "-", "+-1", "1e999", "abc", "1.5m", "--1"}) {
    try {
      parse_option_number(bad, "--concavity");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), "--concavity needs a number, not '" + bad + "'");
    }
  }
}

TEST(OptionTable, SwitchValuesAreYamlsBooleans) {
  for (const std::string on : {"true", "True", "TRUE", "yes", "y", "on", "ON"}) EXPECT_EQ(parse_switch_value(on), true) << on;
  for (const std::string off : {"false", "no", "N", "off", "Off"}) EXPECT_EQ(parse_switch_value(off), false) << off;
  for (const std::string neither : {"1", "0", "", "tRUE", "yes!", "0x1"}) EXPECT_FALSE(parse_switch_value(neither)) << neither;
  EXPECT_EQ(switch_value_error("--trivial", "1"), "--trivial is a switch: give true or false, not '1'");
  EXPECT_EQ(given_twice_error("~concavity"), "~concavity is given twice");
}

enum class Shape { kRound, kSquare, kStar };
struct Drawing {
  Shape shape = Shape::kSquare;
};

// A choice reads back the name it was given, lists its names in order, and refuses any other name
// (case included) with one message naming them, leaving the field as it was.
TEST(OptionTable, AChoiceSetsTheValueItsNameNames) {
  const ChoiceRow<Drawing> row = choice_row<Drawing, Shape>(
      "shape", &Drawing::shape, {{"round", Shape::kRound}, {"square", Shape::kSquare}}, "how it is drawn");
  EXPECT_EQ(row.value_name(), "round|square");
  Drawing drawing;
  EXPECT_EQ(row.get(drawing), "square");
  set_choice(row, drawing, "round", "--shape");
  EXPECT_EQ(drawing.shape, Shape::kRound);
  EXPECT_EQ(row.get(drawing), "round");
  try {
    set_choice(row, drawing, "Square", "--shape");
    FAIL() << "a name not listed was taken";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--shape must be one of 'round', 'square', got 'Square'");
  }
  EXPECT_EQ(drawing.shape, Shape::kRound);
  drawing.shape = Shape::kStar;  // a value the row does not name has no name
  EXPECT_EQ(row.get(drawing), "");
}

}  // namespace
}  // namespace topocut
