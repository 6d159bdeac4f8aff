#pragma once
// The maps the CLI tests run the binary on: the checkout's bundled maps and a small one written on the fly.
#include <string>

#include <opencv2/core.hpp>

#include "io/temp_dir.h"
#include "io/test_images.h"

namespace topocut::testing {

// A file of the checkout's maps/ folder, by its name (e.g. "floorplan.yaml").
inline std::string bundled(const std::string& name) { return std::string(TOPOCUT_SOURCE_DIR "/maps/") + name; }

// A small map: a free room in an occupied frame, written as dir/map.png; its path.
inline std::string small_map(const TempDir& dir) {
  cv::Mat map(40, 60, CV_8UC1, cv::Scalar(0));
  map(cv::Rect(2, 2, 56, 36)).setTo(255);
  write_test_image(dir.file("map.png"), map);
  return dir.file("map.png");
}

}  // namespace topocut::testing
