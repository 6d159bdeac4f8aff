// The dataset runner fed with label images that another tool made (the peers' published results).
#include <cstdint>
#include <filesystem>

#include "topocut/core/error.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/region_labels.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {

// The label image for a map image: the same file name, as PNG, in the labels folder.
fs::path label_image_path(const fs::path& folder, const std::string& map_image) {
  return folder / (fs::path(map_image).stem().string() + ".png");
}

void check_folder(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw Error("label folder '" + folder + "' does not exist or is not a folder");
}

}  // namespace

ImageSegmenter labels_segmenter(const std::string& labels_folder, const DatasetRunOptions& options) {
  check_folder(labels_folder);
  return [folder = fs::path(labels_folder), load = options.load](const std::string& image_path) {
    const fs::path path = label_image_path(folder, image_path);
    std::error_code ec;
    if (!fs::exists(path, ec)) throw MissingSegmentation("no label image " + path.string());
    Segmentation segmentation;
    // The map first: its size is the one the label image's header must declare, so that a label image
    // of the wrong size is refused before a pixel of it is decoded.
    const OccupancyGrid grid = load_map(image_path, load);
    const ExpectedSize map_size{static_cast<std::uint64_t>(grid.width()), static_cast<std::uint64_t>(grid.height()), "the map"};
    segmentation.labels = read_region_labels(path.string(), load.limits, &map_size);
    // Tools draw their regions over walls and unknown space in their own ways; only the free cells
    // are compared, as for topocut's own labels.
    segmentation.labels.setTo(0, grid.cells != kFree);
    segmentation.resolution = grid.resolution;
    segmentation.origin = grid.origin;
    return segmentation;
  };
}

std::vector<Variant> labelled_variants(const std::vector<DatasetMap>& maps, const std::string& labels_folder) {
  check_folder(labels_folder);
  std::vector<Variant> variants;
  for (const Variant variant : {Variant::kPlain, Variant::kFurnished}) {
    for (const DatasetMap& map : maps) {
      std::error_code ec;
      if (fs::is_regular_file(label_image_path(labels_folder, map.image(variant)), ec)) {
        variants.push_back(variant);
        break;
      }
    }
  }
  if (variants.empty()) {
    throw Error("label folder '" + labels_folder + "' holds no label image of a map of the dataset (X.png for map X)");
  }
  return variants;
}

}  // namespace topocut
