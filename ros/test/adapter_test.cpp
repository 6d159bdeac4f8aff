// The node's adapter without a master (issue 28): a well-formed map of 2^31 cells, and any map
// above the ~max_megapixels parameter, is refused with one sentence before a cell is read (the
// data pointer here is null: reading a cell would crash), and the adapter answers the next map.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rooms_adapter.h"

namespace {

topocut_ros::RoomsAdapter adapter_with(double max_megapixels) {
  return topocut_ros::RoomsAdapter(
      [max_megapixels](const std::string& name, double* value) {
        if (name != "max_megapixels" || max_megapixels <= 0) return false;
        *value = max_megapixels;
        return true;
      },
      [](const std::string&, bool*) { return false; });
}

std::string refusal(topocut_ros::RoomsAdapter& adapter, const topocut_ros::MapInput& map) {
  try {
    adapter.update(map);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(RosAdapter, AMapOfTwoToTheThirtyOneCellsIsRefusedBeforeItsCellsAreRead) {
  topocut_ros::RoomsAdapter adapter = adapter_with(0);
  topocut_ros::MapInput huge;
  huge.width = 65536;
  huge.height = 32768;
  huge.size = static_cast<std::size_t>(huge.width) * huge.height;  // well formed: 2^31 values
  huge.resolution = 0.05;
  EXPECT_EQ(refusal(adapter, huge), "the map has 65536 x 32768 cells, more than the limit of 100 megapixels (parameter ~max_megapixels)");
  huge.width = 0xffffffffu;  // wider than an int
  huge.height = 1;
  huge.size = huge.width;
  EXPECT_NE(refusal(adapter, huge).find("more than the limit"), std::string::npos);

  // The next map is segmented.
  std::vector<std::int8_t> cells(60 * 40, 100);
  for (int r = 2; r < 38; ++r)
    for (int c = 2; c < 58; ++c) cells[r * 60 + c] = 0;
  topocut_ros::MapInput room{cells.data(), cells.size(), 60, 40, 0.05};
  EXPECT_EQ(adapter.update(room).rooms.size(), 1u);
}

TEST(RosAdapter, TheLimitIsAParameter) {
  std::vector<std::int8_t> cells(2000 * 1000, 0);
  topocut_ros::MapInput map{cells.data(), cells.size(), 2000, 1000, 0.05};
  topocut_ros::RoomsAdapter small = adapter_with(1.5);
  EXPECT_EQ(refusal(small, map), "the map has 2000 x 1000 cells, more than the limit of 1.5 megapixels (parameter ~max_megapixels)");
  EXPECT_THROW(adapter_with(5000), std::runtime_error);  // above the library's ceiling
}

}  // namespace
