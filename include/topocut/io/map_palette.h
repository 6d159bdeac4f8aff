#pragma once
// How the grey levels of a plain map image (no YAML) mean free, occupied and unknown. Clean drawings
// use black walls on white; SLAM tools write grey walls (127, 153), light-grey or black unknown and
// partly observed greys in between. A fixed threshold pair reads some of them wrongly, so the
// palette is read from the image itself: its histogram's modes, and the level covering most of the
// border (the unexplored surroundings) as unknown.
#include <array>
#include <string>

#include <opencv2/core.hpp>

namespace topocut {

// The cell state (kFree / kOccupied / kUnknown) of every grey level 0..255.
struct MapPalette {
  std::array<unsigned char, 256> state{};
  std::string description;  // one line for people, e.g. "free 255, unknown 230, occupied 127 (detected)"
};

struct PaletteDetectionOptions {
  // A mode is a histogram maximum within +-mode_separation levels holding min_mode_share (0..1) of
  // the pixels not at the border's level, so that padding a map with unknown changes nothing.
  int mode_separation = 16;
  double min_mode_share = 0.005;
  // Levels within this of the free mode are free, no other (anti-aliased greys by walls stay out);
  // 4 around 255 is Bormann et al.'s "> 250 is free".
  int free_tolerance = 4;
  // The border's most common level is unknown when it covers at least this share of the border.
  double min_border_share = 0.5;
  // With only two modes (free and one other), the other is occupied when darker than this, unknown
  // otherwise: black on white is a drawing's walls, a single grey is a SLAM map's unknown.
  int dark_level = 64;
};

// Free above free_min, occupied below occupied_max, unknown between (DESIGN.md's plain-image rule).
MapPalette threshold_palette(int free_min, int occupied_max);

// The palette of a map image (levels CV_8UC1; transparent CV_8UC1, non-zero: unknown, not counted):
// the brightest mode free, the border's level unknown, the darkest other mode occupied, other levels
// as their nearest non-free mode. threshold_palette(fallback_free_min, fallback_occupied_max) when
// there is no bright mode or only one. Deterministic.
MapPalette detect_palette(const cv::Mat& levels, const cv::Mat& transparent, int fallback_free_min, int fallback_occupied_max,
                          const PaletteDetectionOptions& options = {});

}  // namespace topocut
