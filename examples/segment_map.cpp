// Segments a map through the installed topocut package: a map file (ROS YAML or image) when one is
// given, with the segmentation options of a robot's YAML file when that is given too (the keys of
// `topocut segment --config`), else an int8 occupancy grid held in memory as a ROS node holds a
// nav_msgs/OccupancyGrid.
//   cmake -S examples -B build-example -DCMAKE_PREFIX_PATH=<topocut prefix> && cmake --build build-example
//   build-example/segment_map maps/floorplan.yaml [examples/robot.yaml]
#include <cstdint>
#include <iostream>
#include <vector>

#include <topocut/topocut.h>

namespace {

// Two 4 m x 3 m rooms side by side, joined by a 1 m door; -1 (unknown) outside, 100 walls, 0 free.
// Row 0 is the bottom row, as in nav_msgs/OccupancyGrid.
std::vector<std::int8_t> two_rooms(int width, int height) {
  std::vector<std::int8_t> cells(static_cast<std::size_t>(width * height), -1);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const bool border = r < 2 || c < 2 || r >= height - 2 || c >= width - 2;
      const bool wall = c >= 80 && c < 84 && !(r >= 25 && r < 45);
      cells[static_cast<std::size_t>(r * width + c)] = border || wall ? 100 : 0;
    }
  return cells;
}

void print(const topocut::GridSegmentation& result) {
  const topocut::Segmentation& s = result.segmentation;
  for (std::size_t k = 0; k < s.rooms.size(); ++k)
    std::cout << "room " << s.rooms[k].id << ": " << s.rooms[k].area << " m2, inside (" << result.placements[k].inside.x << ", "
              << result.placements[k].inside.y << ")\n";
  for (const topocut::Passage& p : s.passages)
    std::cout << "passage " << p.room_a << " - " << p.room_b << ": " << p.width << " m " << (p.door ? "door" : "opening") << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc > 1) {
      const topocut::SegmentOptions options = argc > 2 ? topocut::load_segment_options(argv[2]) : topocut::SegmentOptions{};
      print(topocut::segment_grid(topocut::load_map(argv[1]), topocut::GridFrame{}, options));
      return 0;
    }
    std::cout << "topocut " << TOPOCUT_VERSION << ", two rooms held in memory:\n";
    const int width = 164, height = 64;
    const std::vector<std::int8_t> cells = two_rooms(width, height);
    topocut::GridArray grid;  // int8 occupancy, bottom-up rows: the defaults
    grid.data = cells.data();
    grid.width = width;
    grid.height = height;
    grid.resolution = 0.05;
    grid.origin = {-2.0, -1.5, 0.0};
    topocut::SegmentOptions options;
    options.concavity = 2.0;
    print(topocut::segment_grid(grid, options));
  } catch (const topocut::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
