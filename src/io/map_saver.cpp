#include "topocut/io/map_saver.h"

#include <charconv>
#include <filesystem>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/map_loader.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {
// Shortest text that reads back as the same double ("0.05", not "0.050000000000000003").
std::string shortest(double v) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}
}  // namespace

cv::Mat ros_map_image(const OccupancyGrid& grid) {
  validate(grid);
  // map_saver's encoding: these values round-trip through the default thresholds of the loader.
  cv::Mat image(grid.cells.size(), CV_8UC1, cv::Scalar(205));
  image.setTo(254, grid.cells == kFree);
  image.setTo(0, grid.cells == kOccupied);
  return image;
}

std::string map_image_path(const std::string& yaml_path, const MapSaveOptions& options) {
  return fs::path(yaml_path).replace_extension(options.image_extension).string();
}

void save_map(const std::string& yaml_path, const OccupancyGrid& grid, const MapSaveOptions& options) {
  if (!is_yaml_path(yaml_path)) throw Error("cannot save map '" + yaml_path + "': the file name must end in .yaml");
  if (options.image_extension.empty() || options.image_extension[0] != '.')
    throw Error("cannot save map '" + yaml_path + "': the image extension must start with a dot, e.g. .pgm");
  const fs::path image = map_image_path(yaml_path, options);
  check_writable(yaml_path);
  check_writable(image.string());
  const cv::Mat pixels = ros_map_image(grid);

  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "image" << YAML::Value << image.filename().string();
  out << YAML::Key << "mode" << YAML::Value << "trinary";
  out << YAML::Key << "resolution" << YAML::Value << shortest(grid.resolution);
  out << YAML::Key << "origin" << YAML::Value << YAML::Flow << YAML::BeginSeq << shortest(grid.origin.x) << shortest(grid.origin.y)
      << "0.0" << YAML::EndSeq;
  out << YAML::Key << "negate" << YAML::Value << 0;
  out << YAML::Key << "occupied_thresh" << YAML::Value << "0.65";
  out << YAML::Key << "free_thresh" << YAML::Value << "0.196";
  out << YAML::EndMap;
  if (!out.good()) throw Error("cannot save map '" + yaml_path + "': " + out.GetLastError());

  write_image_atomically(image.string(), pixels);
  write_file_atomically(yaml_path, std::string(out.c_str()) + "\n");
}

}  // namespace topocut
