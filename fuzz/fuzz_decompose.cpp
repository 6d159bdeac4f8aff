// libFuzzer target: the dual-space decomposition on fuzzed polygons with small integer coordinates.
// Input bytes become rings in one of three shapes (raw vertex lists, star-shaped rings, x-monotone
// "histogram" floor plans with rectangular holes); invalid polygons must be rejected with a
// topocut::Error, valid ones must be tiled: every piece has positive area, outer ring CCW, holes CW,
// and the piece areas sum to the input area plus the absorbed holes' area.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/decomposition/decompose.h"

namespace {

using topocut::Point2;
using topocut::PolygonWithHoles;
using topocut::Ring;
using topocut::fuzz::ByteReader;

constexpr double kPi = 3.14159265358979323846;

Ring raw_ring(ByteReader& in) {
  Ring ring;
  const int n = 3 + in.next() % 22;
  for (int i = 0; i < n; ++i) ring.push_back({double(in.next() % 64), double(in.next() % 64)});
  return ring;
}

Ring star_ring(ByteReader& in, double cx, double cy, int max_radius) {
  Ring ring;
  const int n = 3 + in.next() % 30;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * i / n;
    const double radius = 1 + in.next() % max_radius;
    ring.push_back({std::round(cx + radius * std::cos(angle)), std::round(cy + radius * std::sin(angle))});
  }
  return ring;
}

// An x-monotone floor plan: columns of random width and height over a flat floor (always simple).
Ring histogram_ring(ByteReader& in) {
  Ring ring{{0, 0}};
  const int columns = 1 + in.next() % 16;
  double x = 0;
  std::vector<std::pair<double, double>> tops;
  for (int i = 0; i < columns; ++i) {
    const double width = 1 + in.next() % 8;
    const double height = 1 + in.next() % 24;
    tops.push_back({x, height});
    x += width;
    tops.push_back({x, height});
  }
  ring.push_back({x, 0});
  for (auto it = tops.rbegin(); it != tops.rend(); ++it) {
    const Point2 p{it->first, it->second};
    if (ring.back() == p) continue;
    ring.push_back(p);
  }
  return ring;
}

Ring rectangle(ByteReader& in) {
  const double x = in.next() % 64, y = in.next() % 24;
  const double w = 1 + in.next() % 6, h = 1 + in.next() % 6;
  return {{x, y}, {x, y + h}, {x + w, y + h}, {x + w, y}};  // clockwise
}

PolygonWithHoles polygon_from(ByteReader& in, std::uint8_t mode) {
  PolygonWithHoles polygon;
  const int holes = in.next() % 4;
  switch (mode % 3) {
    case 0:
      polygon.outer = raw_ring(in);
      for (int i = 0; i < holes; ++i) polygon.holes.push_back(raw_ring(in));
      break;
    case 1:
      polygon.outer = star_ring(in, 32, 32, 31);
      for (int i = 0; i < holes; ++i) {
        const double cx = 16 + in.next() % 32, cy = 16 + in.next() % 32;
        polygon.holes.push_back(star_ring(in, cx, cy, 6));
      }
      break;
    default:
      polygon.outer = histogram_ring(in);
      for (int i = 0; i < holes; ++i) polygon.holes.push_back(rectangle(in));
      break;
  }
  return polygon;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  ByteReader in(data, size);
  const std::uint8_t mode = in.next();
  const std::uint8_t flags = in.next();
  DecompositionOptions options;
  options.tau = 0.5 + (in.next() % 32) * 0.5;
  options.max_rounds = 1 + in.next() % 20;
  options.selection = (flags & 1) ? CutSelection::kReference : CutSelection::kGreedy;
  options.concavity = (flags & 2) ? ConcavityMeasure::kHierarchical : ConcavityMeasure::kStraightLine;
  options.candidates = (flags & 4) ? CandidateCuts::kReference : CandidateCuts::kValidated;
  options.pocket_polygon = (flags & 8) ? PocketPolygon::kReference : PocketPolygon::kSplitOnBridge;
  options.skinny_cuts = static_cast<SkinnyCutFilter>((flags >> 4) % 3);
  options.absorb_small_holes = !(flags & 64);
  options.restore_holes = !(flags & 128);
  const PolygonWithHoles polygon = polygon_from(in, mode);

  Decomposition result;
  try {
    result = decompose(polygon, options);
  } catch (const Error&) {
    return 0;  // rejected as invalid input: the promised behaviour
  }
  if (result.pieces.empty()) fuzz::fail("a valid polygon gave no pieces");
  double pieces_area = 0.0;
  for (const PolygonWithHoles& piece : result.pieces) {
    if (piece.outer.size() < 3) fuzz::fail("a piece with fewer than three vertices");
    if (!(signed_area(piece.outer) > 0.0)) fuzz::fail("a piece whose outer ring is not counter-clockwise");
    for (const Ring& hole : piece.holes) {
      if (!(signed_area(hole) < 0.0)) fuzz::fail("a piece hole that is not clockwise");
    }
    const double a = area(piece);
    if (!(a > 0.0)) fuzz::fail("a piece without positive area");
    pieces_area += a;
  }
  double absorbed = 0.0;
  for (const Ring& hole : result.absorbed_holes) absorbed += std::abs(signed_area(hole));
  const double expected = area(polygon) + absorbed;
  if (std::abs(pieces_area - expected) > 1e-6 * std::max(1.0, expected)) {
    fuzz::fail("pieces do not tile the input: pieces " + std::to_string(pieces_area) + " vs input + absorbed holes " +
               std::to_string(expected));
  }
  return 0;
}
