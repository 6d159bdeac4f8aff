#pragma once
// The width of the space on one side of a cut, measured one way for the cut rules (cuts/cut_search.h,
// on the free-space polygon) and for merging (merging/room_graph.h, on a room's pieces): the widest
// chord parallel to the cut at kSideWidthSamples depths evenly spaced up to depth beyond the cut's
// middle, since a door's frame is narrower than the room behind it. Only the chord differs between the
// two: each passes its own.
#include <algorithm>
#include <optional>

namespace topocut {

inline constexpr int kSideWidthSamples = 8;

// The widest chord_at(d) for d = depth k / kSideWidthSamples, k = 1 .. kSideWidthSamples (any length
// unit, the same for depth, enough and the chords), stopping at the first d outside the space
// (chord_at returns std::nullopt: past the side's wall) or once a chord reaches enough (the side is
// wide enough for the caller's test). 0 when the first depth is already outside.
template <class ChordAt>
double sampled_side_width(double depth, double enough, const ChordAt& chord_at) {
  double widest = 0.0;
  for (int k = 1; k <= kSideWidthSamples; ++k) {
    const std::optional<double> chord = chord_at(depth * k / kSideWidthSamples);
    if (!chord) break;
    widest = std::max(widest, *chord);
    if (widest >= enough) break;
  }
  return widest;
}

}  // namespace topocut
