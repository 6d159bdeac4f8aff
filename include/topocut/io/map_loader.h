#pragma once
// Loading occupancy grids from images and ROS map_server YAML files into the three-state grid.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "topocut/core/occupancy_grid.h"
#include "topocut/io/image_input.h"
#include "topocut/io/map_palette.h"

namespace topocut {

struct MapLoadOptions {
  // Used for plain images (a YAML's own resolution always wins); metres per cell.
  double resolution = 0.05;
  // Plain images: the palette (which grey levels are free, occupied, unknown) is read from the
  // image itself (map_palette.h), so grey walls and black or grey unknown work. false, or a palette
  // the image does not show: levels above free_min are free, below occupied_max occupied, the rest
  // unknown (DESIGN.md's rule; free_min = 250 is Bormann et al.'s "> 250 is free").
  bool detect_palette = true;
  int free_min = 250;
  int occupied_max = 50;
  ImageLimits limits;  // pixel limit of the image, checked on its header before decoding
};

// How a ROS map_server image is interpreted (the YAML's `mode`).
enum class RosMapMode {
  kTrinary,  // occupied / free / unknown by the two thresholds
  kScale,    // ROS keeps the middle band as a probability; in a three-state grid it is unknown
  kRaw,      // the pixel value is the occupancy in percent (0..100), anything else unknown
};

// The fields of a ROS map_server YAML file.
struct RosMapMetadata {
  std::string image;             // as written in the YAML (relative to the YAML's folder unless absolute)
  double resolution = 0.0;       // metres per cell
  Point2 origin;                 // world position of the lower-left corner of the lower-left cell
  double yaw = 0.0;              // radians; read but ignored, as by most of ROS
  bool negate = false;           // white is occupied, black free
  double occupied_thresh = 0.65; // occupancy probability above which a cell is occupied
  double free_thresh = 0.196;    // occupancy probability below which a cell is free
  RosMapMode mode = RosMapMode::kTrinary;
};

// Parses ROS map_server YAML text. `image`, `resolution` and `origin` are required; `negate`,
// `occupied_thresh`, `free_thresh` and `mode` default to ROS map_saver's values (0, 0.65, 0.196,
// trinary). Throws Error naming source_name and the field on a missing or invalid field.
RosMapMetadata parse_ros_map_yaml(const std::string& yaml_text, const std::string& source_name);

// Decodes image bytes (PNG, PGM/PPM, JPEG, BMP or TIFF within limits: image_input.h) into one grey
// channel (CV_32FC1 on the 0..255 scale,
// the mean of the colour channels as ROS does; 16-bit scaled down) and a transparency mask (CV_8UC1, 255 where
// the pixel is transparent, alpha < 128). Throws Error naming source_name if it is not an image.
void decode_map_image(const std::string& bytes, const std::string& source_name, cv::Mat& grey,
                      cv::Mat& transparent, const ImageLimits& limits = {});

// Three-state cells from a grey image and its transparency mask with ROS map_server semantics:
// p = (255 - v) / 255 (p = v / 255 when negate; raw mode: p = v / 100 for v <= 100); occupied if
// p > occupied_thresh, free if p < free_thresh, otherwise unknown. Transparent pixels are unknown.
cv::Mat ros_cells(const cv::Mat& grey, const cv::Mat& transparent, const RosMapMetadata& metadata);

// The grey level of every pixel of a plain image (CV_8UC1: the rounded mean of the colour channels,
// 16-bit scaled to 8) and its transparency mask (CV_8UC1, 255 where alpha < half). Throws Error naming
// source_name if the bytes are not an image.
void decode_map_levels(const std::string& bytes, const std::string& source_name, cv::Mat& levels, cv::Mat& transparent,
                       const ImageLimits& limits = {});

// The palette load_map() uses for a plain image: detected (options.detect_palette) or the fixed
// thresholds options.free_min / occupied_max.
MapPalette plain_image_palette(const cv::Mat& levels, const cv::Mat& transparent, const MapLoadOptions& options);

// Three-state cells of a plain image from its levels and palette; transparent pixels are unknown.
cv::Mat plain_image_cells(const cv::Mat& levels, const cv::Mat& transparent, const MapPalette& palette);

// Loads a map: a ROS map_server YAML (image, resolution, origin, negate, occupied_thresh,
// free_thresh, mode trinary/scale/raw, with ROS semantics) or an image (PNG, PGM/PPM, JPEG, BMP, TIFF;
// grey, RGB, RGBA, grey+alpha) within options.limits; both only from regular files. If palette is
// given, it receives a one-line description of how the cells were
// read (the detected palette, the fixed thresholds, or the YAML's). Throws Error naming the file and
// the problem on any bad input.
OccupancyGrid load_map(const std::string& path, const MapLoadOptions& options = {}, std::string* palette = nullptr);

// The image a ROS map YAML names (relative to the YAML's folder unless absolute). Throws Error on a
// YAML load_map would refuse.
std::string ros_map_image_path(const std::string& yaml_path);

// The files load_map reads for path: path itself and, for a ROS map YAML, the image it names (so
// that outputs can be checked against every input before the work starts).
std::vector<std::string> map_files(const std::string& path);

// True if path names a YAML file by its extension (.yaml or .yml).
bool is_yaml_path(const std::string& path);

}  // namespace topocut
