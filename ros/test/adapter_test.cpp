// The node's adapter without a master: maps it must refuse before reading a cell (issue 28), the
// parameters checked against the option table, the segment service's batch rooms (those of the
// library's segment_grid() with the CLI's defaults, at the resolution the map was written with)
// and the room at a point (issue 26).
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "rooms_adapter.h"
#include "topocut/core/error.h"
#include "topocut/core/grid_array_options.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"
#include "topocut/io/map_load_flags.h"
#include "topocut/segmentation/incremental_segmenter.h"
#include "topocut/segmentation/segment_switches.h"
#include "topocut/topocut.h"

namespace {

using topocut_ros::Parameter;

// A parameter as the server holds it: a number, a bool or a text.
template <typename Value>
Parameter given(const std::string& name, Value value) {
  Parameter p;
  p.name = name;
  if constexpr (std::is_same_v<Value, bool>) {
    p.kind = Parameter::Kind::kFlag;
    p.flag = value;
  } else if constexpr (std::is_arithmetic_v<Value>) {
    p.kind = Parameter::Kind::kNumber;
    p.number = value;
  } else {
    p.kind = Parameter::Kind::kText;
    p.text = value;
  }
  return p;
}

topocut_ros::RoomsAdapter adapter_with(const std::vector<Parameter>& parameters = {}) {
  std::vector<std::string> unknown;
  return topocut_ros::RoomsAdapter(parameters, unknown);
}

// Why the adapter refuses parameters, or "" when it takes them.
std::string refusal(const std::vector<Parameter>& parameters) {
  try {
    adapter_with(parameters);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

std::string refusal(topocut_ros::RoomsAdapter& adapter, const topocut_ros::MapInput& map) {
  try {
    adapter.update(map);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// Two 3 m rooms side by side, walls 0.1 m thick, a 0.8 m door between them (nav_msgs values, rows
// bottom-up, 0.05 m cells).
struct TwoRooms {
  static constexpr int kWidth = 128, kHeight = 64;
  std::vector<std::int8_t> cells = std::vector<std::int8_t>(kWidth * kHeight, 100);
  TwoRooms() {
    for (int r = 2; r < kHeight - 2; ++r)
      for (int c = 2; c < kWidth - 2; ++c)
        if (c < 62 || c > 65 || (r >= 24 && r < 40)) cells[r * kWidth + c] = 0;
  }
  topocut_ros::MapInput map(double x = 0.0, double y = 0.0) const {
    return {cells.data(), cells.size(), kWidth, kHeight, 0.05f, x, y, 0.0};
  }
};

TEST(RosAdapter, AMapOfTwoToTheThirtyOneCellsIsRefusedBeforeItsCellsAreRead) {
  topocut_ros::RoomsAdapter adapter = adapter_with();
  topocut_ros::MapInput huge;
  huge.width = 65536;
  huge.height = 32768;
  huge.size = static_cast<std::size_t>(huge.width) * huge.height;  // well formed: 2^31 values
  huge.resolution = 0.05f;
  EXPECT_EQ(refusal(adapter, huge), "the map has 65536 x 32768 cells, more than the limit of 100 megapixels (parameter ~max_megapixels)");
  huge.width = 0xffffffffu;  // wider than an int
  huge.height = 1;
  huge.size = huge.width;
  EXPECT_NE(refusal(adapter, huge).find("more than the limit"), std::string::npos);

  // The next map is segmented.
  std::vector<std::int8_t> cells(60 * 40, 100);
  for (int r = 2; r < 38; ++r)
    for (int c = 2; c < 58; ++c) cells[r * 60 + c] = 0;
  topocut_ros::MapInput room{cells.data(), cells.size(), 60, 40, 0.05f};
  EXPECT_EQ(adapter.update(room).rooms.size(), 1u);
}

TEST(RosAdapter, TheLimitIsAParameter) {
  std::vector<std::int8_t> cells(2000 * 1000, 0);
  topocut_ros::MapInput map{cells.data(), cells.size(), 2000, 1000, 0.05f};
  topocut_ros::RoomsAdapter small = adapter_with({given("max_megapixels", 1.5)});
  EXPECT_EQ(refusal(small, map), "the map has 2000 x 1000 cells, more than the limit of 1.5 megapixels (parameter ~max_megapixels)");
  EXPECT_NE(refusal({given("max_megapixels", 5000)}), "");  // above the library's ceiling
}

TEST(RosAdapter, BadParameterValuesAreRefusedWithTheReason) {
  EXPECT_EQ(refusal({given("concavity", -1)}), "~concavity must lie in (0, 100000] metres, got -1");
  EXPECT_EQ(refusal({given("door_width", "wide")}), "~door_width needs a number, not 'wide'");
  EXPECT_EQ(refusal({given("no_merge", 1)}), "~no_merge is a switch: give true or false, not '1'");
  EXPECT_EQ(refusal({given("fold_area", true)}), "~fold_area needs a number, not 'true'");
  EXPECT_EQ(refusal({given("free_thresh", 2)}), "~free_thresh must be a share in [0, 1]");
  EXPECT_NE(refusal({given("parity", true), given("no_merge", true)}), "");  // a combination the CLI refuses too
  EXPECT_EQ(refusal({given("concavity", 3), given("no_merge", true), given("robot_radius", 0)}), "");
}

TEST(RosAdapter, TextParametersAreReadAsTheCommandLineReadsThem) {
  // roslaunch keeps <param value="yes"/> as a string, and type="str" any value: "2.5" was refused as
  // not a number and "yes" as not a switch, where the service's options and --config take both.
  EXPECT_EQ(refusal({given("concavity", "2.5"), given("no_merge", "yes"), given("free_thresh", "0.2")}), "");
  EXPECT_EQ(refusal({given("concavity", "0x10")}), "~concavity needs a number, not '0x10'");
  EXPECT_EQ(refusal({given("concavity", " 2")}), "~concavity needs a number, not ' 2'");
  EXPECT_EQ(refusal({given("no_merge", "1")}), "~no_merge is a switch: give true or false, not '1'");
  EXPECT_EQ(refusal({given("concavity", "-1")}), "~concavity must lie in (0, 100000] metres, got -1");
  // A text switch means what it says: "off" leaves the doors on, as the service's no_doors=off does.
  const TwoRooms two;
  EXPECT_EQ(adapter_with({given("no_doors", "off")}).segment(two.map(), {}).json, adapter_with().segment(two.map(), {}).json);
  EXPECT_EQ(adapter_with({given("no_doors", "on")}).segment(two.map(), {}).json,
            adapter_with().segment(two.map(), {"no_doors"}).json);
}

TEST(RosAdapter, UnknownParametersAreWarnedWithTheNearestName) {
  std::vector<std::string> unknown;
  topocut_ros::RoomsAdapter adapter({given("concavty", 3), given("door_width", 1.5), given("frame", "map")}, unknown);
  ASSERT_EQ(unknown.size(), 2u);
  EXPECT_EQ(unknown[0], "~concavty is not a parameter of topocut_node, ignored (did you mean ~concavity?)");
  EXPECT_EQ(unknown[1], "~frame is not a parameter of topocut_node, ignored");
}

TEST(RosAdapter, SegmentGivesTheLibrarysBatchRoomsAtTheWrittenResolution) {
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with();
  const topocut_ros::RoomsOutput out = adapter.segment(two.map(1.0, -2.0), {});
  // What `topocut segment` computes: the CLI's defaults, 0.05 m (not float32's 0.0500000007).
  topocut::GridArray array;
  array.data = two.cells.data();
  array.width = TwoRooms::kWidth;
  array.height = TwoRooms::kHeight;
  array.resolution = 0.05;
  array.origin = {1.0, -2.0, 0.0};
  const topocut::GridSegmentation expected =
      topocut::segment_grid(topocut::grid_from_array(array), topocut::frame_of(array), topocut::SegmentOptions{});
  ASSERT_EQ(expected.segmentation.rooms.size(), 2u);
  EXPECT_EQ(out.json, topocut::rooms_to_json(expected.segmentation, expected.placements));
  ASSERT_EQ(out.labels.size(), two.cells.size());
  for (int r = 0; r < TwoRooms::kHeight; ++r)
    for (int c = 0; c < TwoRooms::kWidth; ++c)
      ASSERT_EQ(out.labels[r * TwoRooms::kWidth + c], expected.segmentation.labels.at<int>(r, c)) << r << "," << c;
  ASSERT_EQ(out.passages.size(), 1u);
  EXPECT_TRUE(out.passages[0].door);
  EXPECT_NEAR(out.passages[0].width, 0.8, 0.051);
  EXPECT_EQ(out.kind, "segment");
}

TEST(RosAdapter, SegmentOptionsGoOverTheParametersAndAreChecked) {
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with({given("no_doors", true)});
  auto error = [&](const std::vector<std::string>& options) {
    try {
      adapter.segment(two.map(), options);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error({"concavty=3"}), "~concavty is not a parameter of topocut_node (did you mean ~concavity?)");
  EXPECT_EQ(error({"concavity=abc"}), "~concavity needs a number, not 'abc'");
  EXPECT_EQ(error({"frame=map"}), "~frame is not a parameter of topocut_node");
  EXPECT_EQ(error({"no_merge=1"}), "~no_merge is a switch: give true or false, not '1'");
  EXPECT_EQ(error({"door-width=-2"}), "~door-width must lie in (0, 100000] metres, got -2");
  // The parameter (no door cuts) holds unless a call turns it off again.
  const std::string doors_off = adapter.segment(two.map(), {}).json;
  EXPECT_EQ(doors_off, adapter_with().segment(two.map(), {"no_doors"}).json);
  const std::string doors_on = adapter.segment(two.map(), {"no_doors=false"}).json;
  EXPECT_EQ(doors_on, adapter_with().segment(two.map(), {}).json);
  EXPECT_NE(doors_on, doors_off);
  EXPECT_EQ(adapter.segment(two.map(), {"trivial", "concavity=1"}).rooms.size(), 1u);
}

TEST(RosAdapter, RoomAtAnswersFromThePublishedRoomsOnly) {
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with();
  topocut_ros::RoomShape room;
  EXPECT_EQ(adapter.room_at(1.0, 1.0, &room), 0);  // nothing published yet
  const topocut_ros::RoomsOutput out = adapter.update(two.map(10.0, 20.0));
  ASSERT_EQ(out.rooms.size(), 2u);
  for (const topocut_ros::RoomShape& expected : out.rooms) {
    EXPECT_EQ(adapter.room_at(expected.inside_x, expected.inside_y, &room), expected.id);
    EXPECT_EQ(room.id, expected.id);
    EXPECT_EQ(room.outer, expected.outer);
    EXPECT_EQ(room.area, expected.area);
    EXPECT_EQ(room.corridor, expected.corridor);
    EXPECT_TRUE(room.min_x <= room.inside_x && room.inside_x <= room.max_x && room.min_y <= room.inside_y &&
                room.inside_y <= room.max_y);
  }
  room = {};
  EXPECT_EQ(adapter.room_at(10.0 + 64 * 0.05, 20.0 + 5 * 0.05, &room), 0);  // in the dividing wall
  EXPECT_EQ(room.id, 0);
  EXPECT_EQ(adapter.room_at(0.0, 0.0, &room), 0);                          // off the map
  // segment_map is a what-if: a map segmented 100 m away changes neither the answers nor the ids.
  const topocut_ros::RoomsOutput elsewhere = adapter.segment(two.map(110.0, 20.0), {});
  ASSERT_EQ(elsewhere.rooms.size(), 2u);
  EXPECT_EQ(adapter.room_at(elsewhere.rooms[0].inside_x, elsewhere.rooms[0].inside_y, &room), 0);
  EXPECT_EQ(adapter.room_at(out.rooms[1].inside_x, out.rooms[1].inside_y, &room), out.rooms[1].id);
  // A live update is published: the map moved by 100 m has its rooms there.
  adapter.update(two.map(110.0, 20.0));
  EXPECT_EQ(adapter.room_at(out.rooms[0].inside_x, out.rooms[0].inside_y, &room), 0);
  EXPECT_NE(adapter.room_at(out.rooms[0].inside_x + 100.0, out.rooms[0].inside_y, &room), 0);
}

// The service's error for options over the start-up parameters, or "" when it segments.
std::string service_error(topocut_ros::RoomsAdapter& adapter, const topocut_ros::MapInput& map,
                          const std::vector<std::string>& options) {
  try {
    adapter.segment(map, options);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(RosAdapter, ServiceOptionsAreReadAsTheCommandLineReadsThem) {
  // concavity=0x10 and options given twice were taken; the command line refuses both.
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with();
  EXPECT_EQ(service_error(adapter, two.map(), {"concavity=0x10"}), "~concavity needs a number, not '0x10'");
  EXPECT_EQ(service_error(adapter, two.map(), {"concavity= 2"}), "~concavity needs a number, not ' 2'");
  EXPECT_EQ(service_error(adapter, two.map(), {"concavity=2", "concavity=3"}), "~concavity is given twice");
  EXPECT_EQ(service_error(adapter, two.map(), {"robot_radius=0.1", "robot-radius=0.1"}), "~robot-radius is given twice");
  EXPECT_EQ(service_error(adapter, two.map(), {"no_merge", "no-merge=false"}), "~no-merge is given twice");
  EXPECT_EQ(service_error(adapter, two.map(), {"trivial=yes", "concavity=+2"}), "");  // YAML's booleans, a signed number
  // A name left out is refused as --config refuses an empty key.
  EXPECT_EQ(service_error(adapter, two.map(), {"=3"}), "the option '=3': an empty name is no option name");
  EXPECT_EQ(service_error(adapter, two.map(), {""}), "the option '': an empty name is no option name");
  // A 1 MB name is not echoed whole: every message is one line of at most 200 characters.
  const std::string message = service_error(adapter, two.map(), {std::string(1 << 20, 'x') + "=1"});
  EXPECT_LE(message.size(), 200u);
  EXPECT_NE(message.find("is not a parameter of topocut_node"), std::string::npos) << message;
  EXPECT_EQ(service_error(adapter, two.map(), {"concavity\x1b[2J=1"}).find('\x1b'), std::string::npos);
}

TEST(RosAdapter, EveryBadNumberOfTheTableGivesTheLibrarysMessage) {
  // The walk of the command line's and Python's tests, through the service's options and the
  // start-up parameters: the message is the library's, with the parameter's name.
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with();
  int walked = 0;
  for (const auto& row : topocut::segment_option_rows()) {
    if (row.is_switch()) continue;
    const std::string name = topocut::underscored_option_name(row.name);
    for (const std::string value : {"-1", "nan", "inf", "0x10", "1e999", "abc", "2,5", "1e6"}) {
      std::string expected;
      try {
        topocut::SegmentSettings settings;
        topocut::set_option(row, settings, topocut::parse_option_number(value, "~" + name), "~" + name);
      } catch (const topocut::Error& e) {
        expected = e.what();
      }
      if (expected.empty()) continue;
      EXPECT_EQ(service_error(adapter, two.map(), {name + "=" + value}), expected) << name << " = " << value;
      EXPECT_EQ(refusal({given(name, value)}), expected) << name << " = " << value << " (a text parameter)";
      ++walked;
    }
  }
  EXPECT_GT(walked, 60);
}

// One spelling per option: every row of the segmentation and incremental tables is a parameter, '_'
// for '-', listed in --help with the default of the incremental segmenter's options (the node's),
// and taken at that default.
TEST(RosAdapter, EveryRowOfTheTablesIsAParameterWithItsDefault) {
  const std::string help = topocut_ros::parameters_help();
  const topocut::IncrementalOptions incremental;
  const topocut::SegmentSettings segment{incremental.segment, {}};
  auto expect_row = [&](const auto& row, const auto& defaults) {
    const std::string name = topocut::underscored_option_name(row.name);
    const double value = row.get(defaults);
    const std::string shown = row.is_switch() ? (value != 0.0 ? "true" : "false") : topocut::shortest_number(value);
    const std::size_t at = help.find("  _" + name + ":=");
    ASSERT_NE(at, std::string::npos) << name;
    const std::string line = help.substr(at, help.find('\n', at) - at);
    // A switch off by default shows no default (giving it means true).
    if (!row.is_switch() || value != 0.0) {
      EXPECT_NE(line.find("(default " + shown + ")"), std::string::npos) << line;
    }
    EXPECT_EQ(refusal({row.is_switch() ? given(name, value != 0.0) : given(name, value)}), "") << name;
  };
  for (const auto& row : topocut::segment_option_rows())
    expect_row(row, segment);
  for (const auto& row : topocut::incremental_option_rows()) expect_row(row, incremental);
  for (const auto& row : topocut::occupancy_threshold_rows()) expect_row(row, topocut::GridArray{});  // map_server's
  // The image limit is the map-loading row every command takes (--max-megapixels), not a row of its own.
  expect_row(*topocut::find_option(topocut::map_load_option_rows(), std::string(topocut::kMaxMegapixelsOption)),
             topocut::MapLoadOptions{});
  EXPECT_EQ(refusal({given("split_after", 0)}), "~split_after must be a whole number >= 1");
  EXPECT_EQ(refusal({given("neighbours_across_doors", 1)}), "~neighbours_across_doors is a switch: give true or false, not '1'");
}

TEST(RosAdapter, RoomAtRefusesAPointThatIsNotANumberWithTheReason) {
  // The service answered false with an empty error; now the reason, before and after a map.
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with();
  topocut_ros::RoomShape room;
  for (int segmented = 0; segmented < 2; ++segmented) {
    for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
      try {
        adapter.room_at(bad, 1.0, &room);
        ADD_FAILURE() << "took " << bad;
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("the point must have finite coordinates"), std::string::npos) << e.what();
      }
    }
    adapter.segment(two.map(), {});
  }
}

TEST(RosAdapter, SettlingGivesSegmentsRoomsWithTheLiveIds) {
  // A map seen in two steps (the right room first), then at rest: the settled rooms are the service's
  // (`topocut segment`'s) cell for cell under the live ids, which the right room keeps.
  TwoRooms half;
  for (int r = 0; r < TwoRooms::kHeight; ++r)
    for (int c = 0; c < 62; ++c) half.cells[r * TwoRooms::kWidth + c] = -1;
  const TwoRooms two;
  topocut_ros::RoomsAdapter adapter = adapter_with({given("settle_after", 0.5)});
  EXPECT_EQ(adapter.settle_after(), 0.5);
  EXPECT_TRUE(adapter.settle().rooms.empty());  // nothing to settle yet
  const topocut_ros::RoomsOutput first = adapter.update(half.map());
  ASSERT_EQ(first.rooms.size(), 1u);
  adapter.update(two.map());
  const topocut_ros::RoomsOutput settled = adapter.settle();
  const topocut_ros::RoomsOutput batch = adapter.segment(two.map(), {});
  EXPECT_EQ(settled.kind, "settled");
  ASSERT_EQ(settled.rooms.size(), batch.rooms.size());
  const int right = settled.labels[32 * TwoRooms::kWidth + 100];
  EXPECT_EQ(right, first.rooms[0].id);
  for (std::size_t k = 0; k < settled.labels.size(); ++k)
    ASSERT_EQ(settled.labels[k] == right, batch.labels[k] == batch.labels[32 * TwoRooms::kWidth + 100]) << k;
  topocut_ros::RoomShape room;
  EXPECT_EQ(adapter.room_at(settled.rooms[0].inside_x, settled.rooms[0].inside_y, &room), settled.rooms[0].id);
}

TEST(RosAdapter, TheIdLedgerKeepsIdsAcrossARestart) {
  const std::string path = testing::TempDir() + "topocut_adapter_ledger.txt";
  std::remove(path.c_str());
  TwoRooms half;
  for (int r = 0; r < TwoRooms::kHeight; ++r)
    for (int c = 0; c < 62; ++c) half.cells[r * TwoRooms::kWidth + c] = -1;
  const TwoRooms two;
  std::vector<std::uint16_t> before;
  {
    topocut_ros::RoomsAdapter adapter = adapter_with({given("id_ledger", path)});
    EXPECT_FALSE(adapter.save_ledger());  // nothing published yet
    adapter.update(half.map());
    before = adapter.update(two.map()).labels;
    EXPECT_TRUE(adapter.save_ledger());
  }
  // The right room was seen first: a fresh start numbers the rooms otherwise.
  ASSERT_NE(adapter_with().update(two.map()).labels, before);
  topocut_ros::RoomsAdapter restarted = adapter_with({given("id_ledger", path)});
  EXPECT_EQ(restarted.update(two.map()).labels, before);
  // A damaged ledger stops the node with the reason.
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("topocut-id-ledger 1\nnext_id 0\n", f);
  std::fclose(f);
  EXPECT_NE(refusal({given("id_ledger", path)}).find("~id_ledger " + path + ": the id ledger's next_id"), std::string::npos);
  EXPECT_EQ(refusal({given("id_ledger", 3.0)}), "~id_ledger needs the path of a file");
  std::remove(path.c_str());
}

}  // namespace
