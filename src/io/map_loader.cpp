#include "topocut/io/map_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/core/value_ranges.h"
#include "topocut/io/image_input.h"
#include "topocut/io/map_load_flags.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Reads a required or optional finite number; the error names the field and the file.
double number_field(const YAML::Node& root, const char* key, const std::string& source, std::optional<double> fallback) {
  const YAML::Node node = root[key];
  if (!node) {
    if (fallback) return *fallback;
    throw Error("map YAML " + quoted(source) + " has no '" + key + "' field");
  }
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    throw Error("map YAML " + quoted(source) + ": '" + key + "' must be a number");
  }
  if (!std::isfinite(value)) throw Error("map YAML " + quoted(source) + ": '" + key + "' must be a finite number");
  return value;
}

}  // namespace

bool is_yaml_path(const std::string& path) {
  const std::string extension = lower(fs::path(path).extension().string());
  return extension == ".yaml" || extension == ".yml";
}

RosMapMetadata parse_ros_map_yaml(const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw Error("map YAML " + quoted(source) + " is not valid YAML (line " + std::to_string(e.mark.line + 1) + ")");
  }
  if (!root.IsMap()) throw Error("map YAML " + quoted(source) + " is not a map_server YAML (expected key: value fields)");

  RosMapMetadata m;
  const YAML::Node image = root["image"];
  if (!image) throw Error("map YAML " + quoted(source) + " has no 'image' field");
  if (!image.IsScalar() || image.as<std::string>().empty())
    throw Error("map YAML " + quoted(source) + ": 'image' must be a file name");
  m.image = image.as<std::string>();

  m.resolution = number_field(root, "resolution", source, std::nullopt);
  check_resolution(m.resolution, "map YAML " + quoted(source) + ": 'resolution'");

  const YAML::Node origin = root["origin"];
  if (!origin) throw Error("map YAML " + quoted(source) + " has no 'origin' field");
  if (!origin.IsSequence() || (origin.size() != 3 && origin.size() != 2))
    throw Error("map YAML " + quoted(source) + ": 'origin' must be [x, y, yaw]");
  double xyz[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < origin.size(); ++i) {
    try {
      xyz[i] = origin[i].as<double>();
    } catch (const YAML::Exception&) {
      throw Error("map YAML " + quoted(source) + ": 'origin' must be three numbers [x, y, yaw]");
    }
    if (!std::isfinite(xyz[i])) throw Error("map YAML " + quoted(source) + ": 'origin' must be finite");
  }
  check_world_coordinate(xyz[0], "map YAML " + quoted(source) + ": the 'origin' x");
  check_world_coordinate(xyz[1], "map YAML " + quoted(source) + ": the 'origin' y");
  m.origin = {xyz[0], xyz[1]};
  m.yaw = xyz[2];

  if (const YAML::Node negate = root["negate"]) {
    bool ok = false;
    try {
      const int value = negate.as<int>();
      if (value == 0 || value == 1) {
        m.negate = value == 1;
        ok = true;
      }
    } catch (const YAML::Exception&) {
      try {
        m.negate = negate.as<bool>();
        ok = true;
      } catch (const YAML::Exception&) {
      }
    }
    if (!ok) throw Error("map YAML " + quoted(source) + ": 'negate' must be 0 or 1");
  }

  m.occupied_thresh = number_field(root, "occupied_thresh", source, 0.65);
  m.free_thresh = number_field(root, "free_thresh", source, 0.196);
  if (m.occupied_thresh < 0.0 || m.occupied_thresh > 1.0)
    throw Error("map YAML " + quoted(source) + ": 'occupied_thresh' must lie in [0, 1]");
  if (m.free_thresh < 0.0 || m.free_thresh > 1.0)
    throw Error("map YAML " + quoted(source) + ": 'free_thresh' must lie in [0, 1]");
  if (m.free_thresh > m.occupied_thresh)
    throw Error("map YAML " + quoted(source) + ": 'free_thresh' must not exceed 'occupied_thresh'");

  if (const YAML::Node mode = root["mode"]) {
    std::string text;
    try {
      text = mode.as<std::string>();
    } catch (const YAML::Exception&) {
    }
    if (text == "trinary") {
      m.mode = RosMapMode::kTrinary;
    } else if (text == "scale") {
      m.mode = RosMapMode::kScale;
    } else if (text == "raw") {
      m.mode = RosMapMode::kRaw;
    } else {
      throw Error("map YAML " + quoted(source) + ": 'mode' must be trinary, scale or raw, got '" + text + "'");
    }
  }
  return m;
}

namespace {

// The levels of an image with N channels of type T (colour_channels of them colour, then alpha): a
// run of equal pixels (most of a map: long runs of one colour) takes the level and transparency of
// its first pixel, its rounded channel mean, written at once.
template <typename T, int N>
void image_levels(const cv::Mat& image, int colour_channels, bool has_alpha, double scale, double half, cv::Mat& levels,
                  cv::Mat& transparent) {
  // The level of every possible channel sum (the rounded mean on the 0..255 scale, computed in
  // doubles, in which an integer sum is exact), so that each run costs a sum and a lookup.
  const int max_sum = static_cast<int>(std::numeric_limits<T>::max()) * colour_channels;
  std::vector<unsigned char> level_of_sum(static_cast<std::size_t>(max_sum) + 1);
  for (int sum = 0; sum <= max_sum; ++sum) {
    level_of_sum[static_cast<std::size_t>(sum)] =
        cv::saturate_cast<unsigned char>(static_cast<double>(sum) * scale / colour_channels);
  }
  levels.create(image.size(), CV_8UC1);
  transparent.create(image.size(), CV_8UC1);
  constexpr std::size_t kPixelBytes = sizeof(T) * N;
  constexpr int kBlock = 8;  // pixels compared at once (fixed-size memcmps: a few vector compares)
  T block[kBlock * N];
  for (int r = 0; r < image.rows; ++r) {
    const T* in = image.ptr<T>(r);
    unsigned char* level = levels.ptr<unsigned char>(r);
    unsigned char* clear = transparent.ptr<unsigned char>(r);
    for (int c = 0; c < image.cols;) {
      const T* px = in + static_cast<std::size_t>(c) * N;
      for (int k = 0; k < kBlock; ++k) std::memcpy(block + k * N, px, kPixelBytes);
      int end = c + 1;  // the run of pixels equal to px: whole blocks, then single pixels
      while (end + kBlock <= image.cols && std::memcmp(in + static_cast<std::size_t>(end) * N, block, sizeof block) == 0) end += kBlock;
      while (end < image.cols && std::memcmp(in + static_cast<std::size_t>(end) * N, px, kPixelBytes) == 0) ++end;
      int sum = 0;
      for (int k = 0; k < colour_channels; ++k) sum += px[k];
      std::memset(level + c, level_of_sum[static_cast<std::size_t>(sum)], static_cast<std::size_t>(end - c));
      std::memset(clear + c, has_alpha && px[N - 1] < half ? 255 : 0, static_cast<std::size_t>(end - c));
      c = end;
    }
  }
}

template <typename T>
void image_levels(const cv::Mat& image, int colour_channels, bool has_alpha, double scale, double half, cv::Mat& levels,
                  cv::Mat& transparent) {
  switch (image.channels()) {
    case 1: return image_levels<T, 1>(image, colour_channels, has_alpha, scale, half, levels, transparent);
    case 2: return image_levels<T, 2>(image, colour_channels, has_alpha, scale, half, levels, transparent);
    case 3: return image_levels<T, 3>(image, colour_channels, has_alpha, scale, half, levels, transparent);
    default: return image_levels<T, 4>(image, colour_channels, has_alpha, scale, half, levels, transparent);
  }
}

void levels_of(const cv::Mat& image, const std::string& source, cv::Mat& levels, cv::Mat& transparent) {
  const int n = image.channels();
  const bool has_alpha = n == 2 || n == 4;
  const int colour_channels = has_alpha ? n - 1 : n;
  if (colour_channels < 1 || colour_channels > 3)
    throw Error("map image " + quoted(source) + " has " + std::to_string(n) + " channels; expected grey, grey+alpha, RGB or RGBA");
  if (image.depth() == CV_8U && n == 1) {  // the common case: the image is its own levels
    levels = image;
    transparent = cv::Mat::zeros(image.size(), CV_8UC1);
  } else if (image.depth() == CV_8U && n == 2) {  // grey + alpha: the grey channel is the level
    levels.create(image.size(), CV_8UC1);
    transparent.create(image.size(), CV_8UC1);
    for (int r = 0; r < image.rows; ++r) {
      const unsigned char* px = image.ptr<unsigned char>(r);
      unsigned char* level = levels.ptr<unsigned char>(r);
      unsigned char* clear = transparent.ptr<unsigned char>(r);
      for (int c = 0; c < image.cols; ++c) {
        level[c] = px[2 * c];
        clear[c] = px[2 * c + 1] < 128 ? 255 : 0;
      }
    }
  } else if (image.depth() == CV_8U) {
    image_levels<unsigned char>(image, colour_channels, has_alpha, 1.0, 128.0, levels, transparent);
  } else if (image.depth() == CV_16U) {
    image_levels<unsigned short>(image, colour_channels, has_alpha, 255.0 / 65535.0, 32768.0, levels, transparent);
  } else {
    throw Error("map image " + quoted(source) + " has an unsupported pixel depth (only 8- and 16-bit integers)");
  }
}

}  // namespace

void decode_map_image(const std::string& bytes, const std::string& source, cv::Mat& grey, cv::Mat& transparent,
                      const ImageLimits& limits) {
  const cv::Mat image = decode_image(bytes, source, limits);

  // Work in floats on the 0..255 scale so the channel mean is exact, as in map_server.
  double scale = 1.0;
  switch (image.depth()) {
    case CV_8U: scale = 1.0; break;
    case CV_16U: scale = 255.0 / 65535.0; break;
    default:
      throw Error("map image " + quoted(source) + " has an unsupported pixel depth (only 8- and 16-bit integers)");
  }
  std::vector<cv::Mat> channels;
  cv::split(image, channels);
  const int n = image.channels();
  const bool has_alpha = n == 2 || n == 4;
  const int colour_channels = has_alpha ? n - 1 : n;
  if (colour_channels < 1 || colour_channels > 3)
    throw Error("map image " + quoted(source) + " has " + std::to_string(n) + " channels; expected grey, grey+alpha, RGB or RGBA");
  grey = cv::Mat::zeros(image.size(), CV_32FC1);
  for (int c = 0; c < colour_channels; ++c) {
    cv::Mat f;
    channels[c].convertTo(f, CV_32F, scale / colour_channels);
    grey += f;
  }
  if (has_alpha) {
    const double half = image.depth() == CV_8U ? 128.0 : 32768.0;
    transparent = channels.back() < half;
  } else {
    transparent = cv::Mat::zeros(image.size(), CV_8UC1);
  }
}

namespace {

// The state map_server gives a cell of this grey level (0-255, mean of the colour channels).
unsigned char ros_state(float level, const RosMapMetadata& m) {
  const double v = m.negate ? 255.0 - level : static_cast<double>(level);
  double p = 0.0;
  if (m.mode == RosMapMode::kRaw) {
    const double value = std::round(v);
    if (value > 100.0) return kUnknown;  // not an occupancy percentage (255 is ROS's unknown)
    p = value / 100.0;
  } else {
    p = (255.0 - v) / 255.0;
  }
  if (p > m.occupied_thresh) return kOccupied;
  if (p < m.free_thresh) return kFree;
  return kUnknown;
}

}  // namespace

cv::Mat ros_cells(const cv::Mat& grey, const cv::Mat& transparent, const RosMapMetadata& m) {
  CV_Assert(grey.type() == CV_32FC1 && transparent.type() == CV_8UC1 && grey.size() == transparent.size());
  // A grey image's levels are whole numbers: their states are looked up with OpenCV's vectorised
  // passes instead of worked out per cell (most of the demo map's loading); an image holding other
  // numbers (a colour image's channel means) takes the formula per cell.
  cv::Mat lookup(1, 256, CV_8UC1);
  for (int level = 0; level < 256; ++level) lookup.at<unsigned char>(level) = ros_state(static_cast<float>(level), m);
  cv::Mat levels, back;
  grey.convertTo(levels, CV_8U);
  levels.convertTo(back, CV_32F);
  cv::Mat cells;
  if (cv::countNonZero(back != grey) == 0) {
    cv::LUT(levels, lookup, cells);
  } else {
    cells.create(grey.size(), CV_8UC1);
    for (int r = 0; r < grey.rows; ++r) {
      const float* g = grey.ptr<float>(r);
      unsigned char* out = cells.ptr<unsigned char>(r);
      for (int c = 0; c < grey.cols; ++c) out[c] = ros_state(g[c], m);
    }
  }
  cells.setTo(kUnknown, transparent);
  return cells;
}

void decode_map_levels(const std::string& bytes, const std::string& source, cv::Mat& levels, cv::Mat& transparent,
                       const ImageLimits& limits) {
  // A level is the channels' mean, whatever their order: libpng need not swap red and blue.
  levels_of(decode_image(bytes, source, limits, nullptr, ColourOrder::kAny), source, levels, transparent);
}

MapPalette plain_image_palette(const cv::Mat& levels, const cv::Mat& transparent, const MapLoadOptions& options) {
  return options.detect_palette ? detect_palette(levels, transparent, options.free_min, options.occupied_max)
                                : threshold_palette(options.free_min, options.occupied_max);
}

cv::Mat plain_image_cells(const cv::Mat& levels, const cv::Mat& transparent, const MapPalette& palette) {
  CV_Assert(levels.type() == CV_8UC1 && transparent.type() == CV_8UC1 && levels.size() == transparent.size());
  cv::Mat cells(levels.size(), CV_8UC1);
  const unsigned char* state = palette.state.data();
  for (int r = 0; r < levels.rows; ++r) {
    const unsigned char* level = levels.ptr<unsigned char>(r);
    const unsigned char* clear = transparent.ptr<unsigned char>(r);
    unsigned char* out = cells.ptr<unsigned char>(r);
    const int n = levels.cols;
    int c = 0;
    // Most of a map is long runs of one level: 16 opaque cells of one level are written at once.
    for (; c + 16 <= n; c += 16) {
      std::uint64_t words[4];  // the levels and transparency flags of the 16 cells
      std::memcpy(words, level + c, 16);
      std::memcpy(words + 2, clear + c, 16);
      const std::uint64_t all = 0x0101010101010101ULL * level[c];
      if (((words[0] ^ all) | (words[1] ^ all) | words[2] | words[3]) == 0) {
        std::memset(out + c, state[level[c]], 16);
        continue;
      }
      for (int k = c; k < c + 16; ++k) out[k] = clear[k] ? kUnknown : state[level[k]];
    }
    for (; c < n; ++c) out[c] = clear[c] ? kUnknown : state[level[c]];
  }
  return cells;
}

namespace {

// The image a ROS map_server YAML names, relative to the YAML's folder unless absolute.
std::string yaml_image_path(const std::string& yaml_path, const RosMapMetadata& m) {
  fs::path image = m.image;
  if (image.is_relative()) image = fs::path(yaml_path).parent_path() / image;
  return image.string();
}

OccupancyGrid load_yaml_map(const std::string& path, const MapLoadOptions& options, std::string* palette) {
  const RosMapMetadata m = parse_ros_map_yaml(read_input_file(path, "map YAML", kMaxMapYamlBytes), path);
  const std::string image = yaml_image_path(path, m);
  if (!fs::exists(image))
    throw FileError(ENOENT, image, "map YAML " + quoted(path) + " names image " + quoted(image) + ", which does not exist");
  cv::Mat grey, transparent;
  decode_map_image(read_input_file(image, "map image", max_image_file_bytes(options.limits)), image, grey, transparent,
                   options.limits);
  OccupancyGrid grid;
  grid.cells = ros_cells(grey, transparent, m);
  if (palette) {
    std::ostringstream text;
    text << "YAML: free below " << m.free_thresh << ", occupied above " << m.occupied_thresh << (m.negate ? ", negated" : "");
    *palette = text.str();
  }
  grid.resolution = m.resolution;
  grid.origin = m.origin;
  return grid;
}

OccupancyGrid load_image_map(const std::string& path, const MapLoadOptions& options, std::string* palette) {
  cv::Mat levels, transparent;
  decode_map_levels(read_input_file(path, "map image", max_image_file_bytes(options.limits)), path, levels, transparent,
                    options.limits);
  const MapPalette plain = plain_image_palette(levels, transparent, options);
  OccupancyGrid grid;
  grid.cells = plain_image_cells(levels, transparent, plain);
  if (palette) *palette = plain.description;
  grid.resolution = options.resolution;
  grid.origin = {0.0, 0.0};
  return grid;
}

}  // namespace

OccupancyGrid load_map(const std::string& path, const MapLoadOptions& options, std::string* palette) {
  if (path.empty()) throw Error("no map file given");
  if (!fs::exists(path)) throw FileError(ENOENT, path, "map file " + quoted(path) + " does not exist");
  validate(options);  // every option's range from the table the commands and bindings parse with
  OccupancyGrid grid = is_yaml_path(path) ? load_yaml_map(path, options, palette) : load_image_map(path, options, palette);
  validate(grid);
  return grid;
}

std::string ros_map_image_path(const std::string& yaml_path) {
  return yaml_image_path(yaml_path, parse_ros_map_yaml(read_input_file(yaml_path, "map YAML", kMaxMapYamlBytes), yaml_path));
}

std::vector<std::string> map_files(const std::string& path) {
  std::vector<std::string> files{path};
  if (!is_yaml_path(path) || !fs::is_regular_file(path)) return files;
  try {
    files.push_back(ros_map_image_path(path));
  } catch (const Error&) {
    // load_map reports a broken YAML with its own message; no image means no second input.
  }
  return files;
}

}  // namespace topocut
