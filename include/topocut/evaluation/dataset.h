#pragma once
// Running a segmenter over a Bormann-format dataset folder and scoring every image against its
// ground truth. For each map X the folder holds X.png (plain), X_furnitures.png (furnished) and
// X_gt_segmentation.png; Bormann et al. (ICRA 2016) publish 20 such maps at 0.05 m/px.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/segmentation.h"
#include "topocut/io/image_input.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/evaluation/segmentation_scores.h"
#include "topocut/io/map_loader.h"
#include "topocut/segmentation/segmenter.h"

namespace topocut {

enum class Variant {
  kPlain,      // X.png
  kFurnished,  // X_furnitures.png: the same building with furniture drawn in as obstacles
};

// "plain" or "furnished".
std::string to_string(Variant variant);

// Parses "plain" or "furnished"; throws Error on anything else.
Variant parse_variant(const std::string& text);

struct DatasetMap {
  std::string name;          // X
  std::string plain;         // path of X.png
  std::string furnished;     // path of X_furnitures.png
  std::string ground_truth;  // path of X_gt_segmentation.png

  const std::string& image(Variant variant) const { return variant == Variant::kPlain ? plain : furnished; }
};

// Lists the maps of a dataset folder: every X for which X_gt_segmentation.png exists, sorted by
// name (byte order). The image files are not checked here; a missing one fails only its own run.
// Throws Error if the folder does not exist, is not a directory, or holds no map.
std::vector<DatasetMap> discover_dataset(const std::string& folder);

// The variants of which at least one map of the folder has its image file, in the order plain,
// furnished: a folder of plain maps only (the sketches, raw SLAM maps) is evaluated as such.
std::vector<Variant> present_variants(const std::vector<DatasetMap>& maps);

// Keeps the maps named in names, in the order given (all maps when names is empty). Throws Error
// naming an unknown map and listing the known ones.
std::vector<DatasetMap> select_maps(const std::vector<DatasetMap>& maps, const std::vector<std::string>& names);

// The ground truth next to a Bormann-style map: X_gt_segmentation.png beside X.png or
// X_furnitures.png. Empty if there is no such file.
std::string find_ground_truth(const std::string& map_path);

// The outcome of one image. A failed image keeps ok = false and the reason in error; a missing one
// (no segmentation to score, e.g. a peer's result that was not published) also has missing = true.
// Their numbers are meaningless and every report leaves them out.
struct ImageResult {
  std::string map;
  Variant variant = Variant::kPlain;
  bool ok = false;
  bool missing = false;
  std::string error;
  int rooms = 0;          // segments larger than the ignore size (the ones precision averages over)
  int gt_rooms = 0;       // ground-truth rooms larger than the ignore size
  double recall = 0.0;    // fraction in [0, 1]
  double precision = 0.0; // fraction in [0, 1]
  double time_ms = 0.0;   // the whole segmentation of the image file, loading included
  MatchedRooms matched;           // one-to-one matches over the map's free pixels
  double precision_inside = 0.0;  // precision with segments clipped to the ground truth's rooms
  double far_share = 0.0;         // labelled cells farther than far_distance from every room
};

// Copies scores into result and marks it ok.
void apply_scores(const SegmentationScores& scores, ImageResult& result);

// Segments one image file; the runner times exactly this call.
using ImageSegmenter = std::function<Segmentation(const std::string& image_path)>;

// Thrown by an ImageSegmenter that has no result for an image (a folder of label images without that
// map's image): run_dataset reports the image as missing, not as failed.
class MissingSegmentation : public Error {
 public:
  using Error::Error;
};

struct DatasetRunOptions {
  std::vector<Variant> variants{Variant::kPlain, Variant::kFurnished};
  std::vector<std::string> maps;  // names to run; empty: every map of the folder
  SegmentOptions segment;         // handed to segment() unchanged
  MapLoadOptions load;            // the dataset's images are 0.05 m/px, MapLoadOptions' default
  EvaluationOptions evaluation;
  // Called after every image with a one-line status ("[3/40] lab_ipa furnished: ..."); may be empty.
  std::function<void(const std::string&)> progress;
  // Called for every image that was scored, with what it was scored on: the segment labels, the
  // ground truth's rooms and the map (an HtmlReport draws them); may be empty. An exception it
  // throws fails the image.
  std::function<void(const ImageResult&, const cv::Mat& segment_labels, const cv::Mat& room_labels, const OccupancyGrid& grid)>
      scored;
};

// The size map's ground truth must have: that of its first variant image whose header reads (nothing
// is decoded), or none when none reads (the variants then fail with their own error).
std::optional<ExpectedSize> map_image_size(const DatasetMap& map, const DatasetRunOptions& options);

// Runs segmenter on every selected image (map by map, variants in options' order), loads each
// ground truth once per map and each image's free cells (load_map with options.load), both outside
// the timing, and scores the labels (score_segmentation). Never throws for a single image: a failure
// (unreadable file, segmenter error, size mismatch) becomes a failed ImageResult.
// options.maps and options.segment are not used here (the caller chose maps and segmenter).
std::vector<ImageResult> run_dataset(const std::vector<DatasetMap>& maps, const DatasetRunOptions& options,
                                     const ImageSegmenter& segmenter);

// The library's own pipeline as an ImageSegmenter: load_map(path, options.load) then
// segment(grid, options.segment).
ImageSegmenter batch_segmenter(const DatasetRunOptions& options);

// Segmentations made by another tool, read instead of computed: for the map image X.png (or
// X_furnitures.png) the label image of the same name in labels_folder, read by read_region_labels()
// and restricted to the map's free cells (load_map with options.load). Throws MissingSegmentation when
// there is no such file, Error when it cannot be read or its size differs from the map's.
ImageSegmenter labels_segmenter(const std::string& labels_folder, const DatasetRunOptions& options);

// The variants (plain, furnished) for which labels_folder holds the label image of at least one map.
// Throws Error if labels_folder is not a folder or holds no label image of any map.
std::vector<Variant> labelled_variants(const std::vector<DatasetMap>& maps, const std::string& labels_folder);

// discover_dataset + select_maps(options.maps) + run_dataset with batch_segmenter(options).
// Throws Error only for a bad folder or an unknown map name.
std::vector<ImageResult> run_dataset(const std::string& folder, const DatasetRunOptions& options);

}  // namespace topocut
