#include "rooms_adapter.h"

#include <chrono>

#include "topocut/core/option_table.h"
#include "topocut/io/image_input.h"
#include "topocut/topocut.h"

namespace topocut_ros {

struct RoomsAdapter::State {
  topocut::GridArray thresholds;  // map_server's thresholds, from the parameters
  topocut::ImageLimits limits;    // the largest map segmented, as for every image the library reads
  topocut::IncrementalSegmenter segmenter;
  explicit State(const topocut::IncrementalOptions& options) : segmenter(options) {}
};

namespace {

// The segmenter options and thresholds from the parameters; every default is the library's own.
topocut::IncrementalOptions read_options(const DoubleParameter& number, const FlagParameter& flag,
                                         topocut::GridArray& thresholds) {
  topocut::IncrementalOptions options;
  topocut::SegmentOptions& s = options.segment;
  number("concavity", &s.concavity);
  number("door_width", &s.doors.max_width);
  number("fold_area", &s.merge.min_room_area);
  number("robot_radius", &s.binarize.robot_radius);
  number("opening", &s.binarize.opening_size);
  number("min_room_area", &s.contours.min_component_area);
  number("min_hole_area", &s.contours.min_hole_area);
  number("free_thresh", &thresholds.free_thresh);
  number("occupied_thresh", &thresholds.occupied_thresh);
  number("batch_fraction", &options.batch_fraction);
  auto on = [&](const char* name) {
    bool value = false;
    return flag(name, &value) && value;
  };
  for (const topocut::SegmentationRule& rule : topocut::segmentation_rules()) {
    std::string name = "no_" + rule.name;
    for (char& c : name) c = c == '-' ? '_' : c;
    if (on(name.c_str())) rule.turn_off(s);
  }
  topocut::validate(s);
  return options;
}

RoomsOutput output_of(const topocut::GridSegmentation& rooms) {
  RoomsOutput out;
  const cv::Mat& labels = rooms.segmentation.labels;  // already bottom-up (the array's order)
  out.labels.resize(labels.total());
  std::size_t k = 0;
  for (int r = 0; r < labels.rows; ++r) {
    const int* row = labels.ptr<int>(r);
    for (int c = 0; c < labels.cols; ++c) out.labels[k++] = static_cast<std::uint16_t>(row[c]);
  }
  for (std::size_t i = 0; i < rooms.segmentation.rooms.size(); ++i) {
    const topocut::Room& room = rooms.segmentation.rooms[i];
    RoomShape shape{room.id, {}, rooms.placements[i].inside.x, rooms.placements[i].inside.y};
    for (const topocut::Point2& p : room.polygon.outer) shape.outer.insert(shape.outer.end(), {p.x, p.y});
    out.rooms.push_back(std::move(shape));
  }
  for (const topocut::Passage& p : rooms.segmentation.passages)
    out.passages.insert(out.passages.end(), {p.cut.a.x, p.cut.a.y, p.cut.b.x, p.cut.b.y});
  out.json = topocut::rooms_to_json(rooms.segmentation, rooms.placements);
  return out;
}

}  // namespace

RoomsAdapter::RoomsAdapter(const DoubleParameter& number, const FlagParameter& flag) {
  topocut::GridArray thresholds;
  const topocut::IncrementalOptions options = read_options(number, flag, thresholds);
  state_ = std::make_unique<State>(options);
  state_->thresholds = thresholds;
  number("max_megapixels", &state_->limits.max_megapixels);
  topocut::validate(state_->limits);
}

RoomsAdapter::~RoomsAdapter() = default;

RoomsOutput RoomsAdapter::update(const MapInput& map) {
  if (map.size != static_cast<std::size_t>(map.width) * map.height)
    throw topocut::Error("the map's data holds " + std::to_string(map.size) + " values for " +
                         std::to_string(map.width) + " x " + std::to_string(map.height) + " cells");
  // Before any cell is read: a well-formed map of 2^31 cells would need about 30 GB to segment.
  if (static_cast<double>(map.width) * map.height > state_->limits.max_megapixels * 1e6)
    throw topocut::Error("the map has " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                         " cells, more than the limit of " + topocut::shortest_number(state_->limits.max_megapixels) +
                         " megapixels (parameter ~max_megapixels)");
  topocut::GridArray array = state_->thresholds;
  array.data = map.data;
  array.width = static_cast<int>(map.width);
  array.height = static_cast<int>(map.height);
  array.resolution = map.resolution;
  array.origin = {map.x, map.y, map.yaw};
  const topocut::OccupancyGrid grid = topocut::grid_from_array(array);  // validates the array
  const auto start = std::chrono::steady_clock::now();
  const topocut::Segmentation& result = state_->segmenter.update(grid);
  const double update_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!result.rooms.empty() && result.rooms.back().id > 0xffff)
    throw topocut::Error("room id " + std::to_string(result.rooms.back().id) + " does not fit the 16-bit label image");
  RoomsOutput out = output_of(topocut::in_frame(result, topocut::frame_of(array)));
  out.update_ms = update_ms;
  const char* kinds[] = {"unchanged", "incremental", "batch"};
  out.kind = kinds[static_cast<int>(state_->segmenter.last_update().kind)];
  return out;
}

}  // namespace topocut_ros
