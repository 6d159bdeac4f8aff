#include "topocut/evaluation/dataset.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/io/image_input.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {

constexpr const char* kGroundTruthSuffix = "_gt_segmentation.png";

std::string status_line(std::size_t index, std::size_t total, const ImageResult& result) {
  std::string line = "[";  // appended: GCC 12 warns falsely (-Wrestrict) on "literal" + a temporary string
  line += std::to_string(index) + "/" + std::to_string(total) + "] " + result.map + " " + to_string(result.variant) + ": ";
  if (result.missing) return line + "missing: " + result.error;
  if (!result.ok) return line + "FAILED: " + result.error;
  return line + format("rooms %d (ground truth %d), recall %.3f, precision %.3f, F1 %.3f, %.0f ms", result.rooms,
                       result.gt_rooms, result.recall, result.precision, result.matched.f1, result.time_ms);
}

}  // namespace

std::optional<ExpectedSize> map_image_size(const DatasetMap& map, const DatasetRunOptions& options) {
  for (const Variant variant : options.variants) {
    try {
      const ImageHeader header = read_image_size(map.image(variant), "map image", options.load.limits);
      return ExpectedSize{header.width, header.height, "the map"};
    } catch (const Error&) {
    }
  }
  return std::nullopt;
}

void apply_scores(const SegmentationScores& scores, ImageResult& result) {
  result.ok = true;
  result.rooms = scores.overlap.segments;
  result.gt_rooms = scores.overlap.rooms;
  result.recall = scores.overlap.recall;
  result.precision = scores.overlap.precision;
  result.matched = scores.matched;
  result.precision_inside = scores.precision_inside;
  result.far_share = scores.far_share;
}

std::string to_string(Variant variant) { return variant == Variant::kPlain ? "plain" : "furnished"; }

Variant parse_variant(const std::string& text) {
  if (text == "plain") return Variant::kPlain;
  if (text == "furnished") return Variant::kFurnished;
  throw Error("unknown variant '" + text + "' (expected plain or furnished)");
}

std::vector<DatasetMap> discover_dataset(const std::string& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec)) throw Error("dataset folder '" + folder + "' does not exist");
  if (!fs::is_directory(folder, ec)) throw Error("dataset path '" + folder + "' is not a folder");
  std::vector<DatasetMap> maps;
  const std::string suffix = kGroundTruthSuffix;
  fs::directory_iterator it(folder, ec);
  if (ec) throw Error("cannot list dataset folder '" + folder + "': " + ec.message());
  for (const fs::directory_entry& entry : it) {
    const std::string file = entry.path().filename().string();
    if (file.size() <= suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    DatasetMap map;
    map.name = file.substr(0, file.size() - suffix.size());
    map.plain = (fs::path(folder) / (map.name + ".png")).string();
    map.furnished = (fs::path(folder) / (map.name + "_furnitures.png")).string();
    map.ground_truth = entry.path().string();
    maps.push_back(std::move(map));
  }
  if (maps.empty()) {
    throw Error("dataset folder '" + folder + "' holds no map (no file named X" + suffix + ")");
  }
  std::sort(maps.begin(), maps.end(), [](const DatasetMap& a, const DatasetMap& b) { return a.name < b.name; });
  return maps;
}

std::vector<Variant> present_variants(const std::vector<DatasetMap>& maps) {
  std::vector<Variant> variants;
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    for (const DatasetMap& map : maps) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(map.image(variant), ec)) {
        variants.push_back(variant);
        break;
      }
    }
  }
  return variants;
}

std::vector<DatasetMap> select_maps(const std::vector<DatasetMap>& maps, const std::vector<std::string>& names) {
  if (names.empty()) return maps;
  std::vector<DatasetMap> selected;
  for (const std::string& name : names) {
    const auto found = std::find_if(maps.begin(), maps.end(), [&](const DatasetMap& m) { return m.name == name; });
    if (found == maps.end()) {
      std::string known;
      for (const DatasetMap& m : maps) known += (known.empty() ? "" : ", ") + m.name;
      throw Error("the dataset has no map '" + name + "' (maps: " + known + ")");
    }
    selected.push_back(*found);
  }
  return selected;
}

std::string find_ground_truth(const std::string& map_path) {
  const fs::path path(map_path);
  std::string stem = path.stem().string();
  const std::string furnished = "_furnitures";
  if (stem.size() > furnished.size() && stem.compare(stem.size() - furnished.size(), furnished.size(), furnished) == 0)
    stem.resize(stem.size() - furnished.size());
  const fs::path candidate = path.parent_path() / (stem + kGroundTruthSuffix);
  std::error_code error;
  if (candidate != path && fs::is_regular_file(candidate, error)) return candidate.string();
  return {};
}

std::vector<ImageResult> run_dataset(const std::vector<DatasetMap>& maps, const DatasetRunOptions& options,
                                     const ImageSegmenter& segmenter) {
  std::vector<ImageResult> results;
  const std::size_t total = maps.size() * options.variants.size();
  for (const DatasetMap& map : maps) {
    // The ground truth is shared by both variants; a bad one fails them both with its reason.
    std::optional<cv::Mat> rooms;
    std::string ground_truth_error;
    try {
      const std::optional<ExpectedSize> size = map_image_size(map, options);
      rooms = ground_truth_rooms(load_ground_truth(map.ground_truth, options.load.limits, size ? &*size : nullptr),
                                 options.evaluation);
    } catch (const std::exception& e) {
      ground_truth_error = e.what();
    }
    for (const Variant variant : options.variants) {
      ImageResult result;
      result.map = map.name;
      result.variant = variant;
      try {
        if (!rooms) throw Error(ground_truth_error);
        const auto start = std::chrono::steady_clock::now();
        const Segmentation segmentation = segmenter(map.image(variant));
        const auto stop = std::chrono::steady_clock::now();
        result.time_ms = std::chrono::duration<double, std::milli>(stop - start).count();
        // The map's own cells say which pixels are free (matched rooms count only those) and its scale.
        const OccupancyGrid grid = load_map(map.image(variant), options.load);
        ImageResult scored = result;
        apply_scores(score_segmentation(segmentation.labels, *rooms, grid.cells == kFree, grid.resolution,
                                        options.evaluation),
                     scored);
        if (options.scored) options.scored(scored, segmentation.labels, *rooms, grid);
        result = scored;  // ok only once everything for the image has succeeded
      } catch (const MissingSegmentation& e) {
        result.missing = true;
        result.error = e.what();
      } catch (const std::bad_alloc&) {
        result.error = "out of memory";
      } catch (const std::exception& e) {
        result.error = e.what();
      }
      if (!result.ok) result.time_ms = 0.0;
      results.push_back(result);
      if (options.progress) options.progress(status_line(results.size(), total, result));
    }
  }
  return results;
}

}  // namespace topocut
