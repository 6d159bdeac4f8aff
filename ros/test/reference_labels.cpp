// The library's answer for the maps the node test publishes, computed without ROS, so that the test
// can check the node's messages cell for cell.
//   topocut_node_reference export MAP OUT    map file -> OUT as a grid file (below)
//   topocut_node_reference replay DIR GRID... incremental segmentation of the grids in order; writes
//       DIR/labels_K.u16 (little-endian uint16, rows bottom-up as nav_msgs/OccupancyGrid) and
//       DIR/rooms_K.json (rooms_to_json) for K = 0, 1, ...
// Grid file: one text line "topocut-grid W H RESOLUTION ORIGIN_X ORIGIN_Y\n", then W*H int8 values
// (-1 unknown, 0 free, 100 occupied), row 0 at the origin (bottom-up).
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "topocut/topocut.h"

namespace {

void export_map(const std::string& map, const std::string& out_path) {
  const topocut::OccupancyGrid grid = topocut::load_map(map);
  std::ofstream out(out_path, std::ios::binary);
  out.precision(17);
  out << "topocut-grid " << grid.width() << " " << grid.height() << " " << grid.resolution << " " << grid.origin.x << " "
      << grid.origin.y << "\n";
  for (int r = grid.height() - 1; r >= 0; --r)
    for (int c = 0; c < grid.width(); ++c) {
      const unsigned char v = grid.cells.at<unsigned char>(r, c);
      out.put(static_cast<char>(v == topocut::kFree ? 0 : v == topocut::kOccupied ? 100 : -1));
    }
  if (!out) throw topocut::Error("cannot write " + out_path);
}

struct GridFile {
  int width = 0, height = 0;
  double resolution = 0.0, x = 0.0, y = 0.0;
  std::vector<char> values;
};

GridFile read_grid(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, tag;
  std::getline(in, line);
  GridFile g;
  std::istringstream header(line);
  header >> tag >> g.width >> g.height >> g.resolution >> g.x >> g.y;
  if (tag != "topocut-grid" || g.width <= 0 || g.height <= 0) throw topocut::Error(path + " is not a grid file");
  g.values.resize(static_cast<std::size_t>(g.width) * g.height);
  in.read(g.values.data(), static_cast<std::streamsize>(g.values.size()));
  if (!in) throw topocut::Error(path + " is truncated");
  return g;
}

void replay(const std::string& dir, const std::vector<std::string>& grids) {
  topocut::IncrementalSegmenter segmenter;  // the node's defaults
  for (std::size_t k = 0; k < grids.size(); ++k) {
    const GridFile g = read_grid(grids[k]);
    topocut::GridArray array;
    array.data = g.values.data();
    array.width = g.width;
    array.height = g.height;
    array.resolution = g.resolution;  // the node reads float32 0.0500000007 as the 0.05 written
    array.origin = {g.x, g.y, 0.0};
    const topocut::Segmentation& result = segmenter.update(topocut::grid_from_array(array));
    std::ofstream labels(dir + "/labels_" + std::to_string(k) + ".u16", std::ios::binary);
    for (int r = result.labels.rows - 1; r >= 0; --r)  // the library's rows are top-down
      for (int c = 0; c < result.labels.cols; ++c) {
        const auto v = static_cast<std::uint16_t>(result.labels.at<int>(r, c));
        labels.put(static_cast<char>(v & 0xff));
        labels.put(static_cast<char>(v >> 8));
      }
    std::ofstream(dir + "/rooms_" + std::to_string(k) + ".json")
        << topocut::rooms_to_json(result, topocut::in_frame(result, topocut::GridFrame{}).placements);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.size() == 3 && args[0] == "export") {
      export_map(args[1], args[2]);
    } else if (args.size() >= 3 && args[0] == "replay") {
      replay(args[1], {args.begin() + 2, args.end()});
    } else {
      std::cerr << "usage: topocut_node_reference export MAP OUT | replay DIR GRID...\n";
      return 2;
    }
  } catch (const std::exception& e) {
    std::cerr << "topocut_node_reference: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
