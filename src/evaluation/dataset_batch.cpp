// The dataset runner bound to the library's own batch pipeline. Kept apart from dataset.cpp so that
// code which brings its own segmenter does not link segment().
#include "topocut/evaluation/dataset.h"

namespace topocut {

ImageSegmenter batch_segmenter(const DatasetRunOptions& options) {
  return [load = options.load, segment_options = options.segment](const std::string& image_path) {
    return segment(load_map(image_path, load), segment_options);
  };
}

std::vector<ImageResult> run_dataset(const std::string& folder, const DatasetRunOptions& options) {
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(folder), options.maps);
  return run_dataset(maps, options, batch_segmenter(options));
}

}  // namespace topocut
