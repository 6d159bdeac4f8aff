#include "topocut/segmentation/segmenter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <optional>
#include <string>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/decomposition/ring_intersections.h"
#include "topocut/map/rasterize.h"
#include "topocut/map/simplify.h"
#include "topocut/segmentation/polygon_split.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/segment_times.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace topocut {

void validate(const SegmentOptions& options) {
  // Every number through its table's row, in the pipeline's order.
  check_option_rows(segment_number_option_rows(), options);
  check_option_rows(binarize_option_rows(), options.binarize);
  validate(options.cleaning);
  check_option_rows(contour_option_rows(), options.contours);
  validate(options.doors);
  check_option_rows(decomposition_option_rows(), options.decomposition);
  validate(options.merge);
  validate(options.open_rooms);
  validate(options.kinds);
}

namespace {

// The binarization's steps that can take free space away, as a sentence's end naming their sizes.
std::string binarization_steps(const OccupancyGrid& grid, const BinarizeOptions& b) {
  const auto metres = [](double v) { return format("%g m", v); };
  std::string steps;
  const auto add = [&steps](const std::string& step) { steps += (steps.empty() ? "" : " and ") + step; };
  if (b.robot_radius > 0.0) add("inflating obstacles by the robot radius (" + metres(b.robot_radius) + ")");
  if (b.opening_size > 0.0) {
    const bool larger = b.opening_size / grid.resolution > std::min(grid.width(), grid.height());
    add("opening it with a square of " + metres(b.opening_size) +
        (larger ? " a side, more than the map's " + metres(std::min(grid.width(), grid.height()) * grid.resolution) : " a side"));
  }
  if (b.median_size > 0.0) add("filtering it with a median window of " + metres(b.median_size));
  return steps.empty() ? "binarizing the map" : steps;
}

// Whether any cell of the grid is free; stops at the first one instead of comparing the whole map.
bool has_free_cell(const cv::Mat& cells) {
  for (int r = 0; r < cells.rows; ++r) {
    const unsigned char* row = cells.ptr<unsigned char>(r);
    if (std::memchr(row, kFree, static_cast<std::size_t>(cells.cols)) != nullptr) return true;
  }
  return false;
}

}  // namespace

cv::Mat segmentation_free_space(const OccupancyGrid& grid, const SegmentOptions& options) {
  validate(grid);
  if (!has_free_cell(grid.cells)) throw Error("the map has no free space (no cell is free)");
  cv::Mat free = free_space_mask(grid, options.binarize);
  if (cv::countNonZero(free) == 0) throw Error("no free space is left after " + binarization_steps(grid, options.binarize));
  return free;
}

namespace {

// Whether rule is a row of stage that is on; one that is runs now, so the trace notes it.
bool starts(const SegmentationRule& rule, RuleStage stage, const SegmentOptions& options) {
  if (!row_is_on(rule, stage, options)) return false;
  note_rule_run(rule);
  return true;
}

// The front end's second half: the free space cleaned by the list's cleaning rows as the floor to
// decompose, and the cells to label. A cleaning that would leave no floor is not applied (a map
// smaller than a room).
SegmentationInput cleaned_input(const OccupancyGrid& grid, cv::Mat free, const SegmentOptions& options) {
  SegmentationInput input;
  input.floor = std::move(free);
  input.labelled = grid;
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!starts(rule, RuleStage::kClean, options)) continue;
    CleanedFreeSpace cleaned = rule.clean(input.floor, grid.cells, grid.resolution, options);
    if (cv::countNonZero(cleaned.floor) == 0) continue;
    input.floor = cleaned.floor;
    // An unknown speck enclosed by floor is floor the sensor never reported (a cell between two
    // readings, a grey pixel of a half-seen spot), so it gets the room like the floor around it;
    // occupied specks (chair legs) stay obstacles.
    input.labelled.cells = cells_after_cleaning(input.labelled.cells, cleaned);
    input.cleaned = std::move(cleaned);
  }
  return input;
}

bool trivial_binarization(const BinarizeOptions& b) {
  return b.robot_radius == 0.0 && b.opening_size == 0.0 && b.median_size == 0.0;
}

constexpr double kMaxReach = 1 << 28;  // cells: beyond every map's side, and a few of them add up within an int

// How far (cells) a changed cell can change the binarized free space: inflation radius, opening
// and median windows, plus slack for rounding. Summed in double and capped far beyond any map's
// side (windows are clipped to the map): lengths at their limit and the finest resolution overflow an int.
int binarization_reach(const BinarizeOptions& b, double resolution) {
  if (trivial_binarization(b)) return 0;
  double reach = 2;
  if (b.robot_radius > 0.0) reach += std::ceil(b.robot_radius / resolution) + 1;
  if (b.opening_size > 0.0) reach += std::round(b.opening_size / resolution) + 1;
  if (b.median_size > 0.0) reach += std::floor(std::round(b.median_size / resolution) / 2) + 2;
  return static_cast<int>(std::min(reach, kMaxReach));
}

// How far (cells) a changed cell can change what the cleaning keeps: the thickness test (a disc of
// min_width, grown by a quarter of it) and the obstacle specks change the floor nearby; whether a
// removed cell is inside the building (labelled) or outside (not) depends on the structure within
// inside_closing of it, so a wall seen there can bring it in or leave it out.
int cleaning_reach(const FreeSpaceCleaningOptions& o, double resolution, bool with_closing = true) {
  const double metres = 1.25 * o.min_width + o.max_obstacle_speck + (with_closing ? o.inside_closing : 0.0);
  return static_cast<int>(std::min(std::ceil(metres / resolution) + 2, kMaxReach));
}

// The box (context's frame) of the thin parts the cleaning of context judged (ray or not, by all their
// cells) that reach into inner and run out of the context across the map: the whole map's cleaning
// would judge them on more cells. Empty when every such part lies within context but for the map's
// own edges.
cv::Rect thin_parts_cut(const CleanedFreeSpace& cleaned, const cv::Rect& context, const cv::Rect& inner, const cv::Size& map) {
  cv::Rect box;
  for (const cv::Rect& part : cleaned.thin_parts) {
    if ((part & inner).empty()) continue;
    const bool cut = (part.x == 0 && context.x > 0) || (part.y == 0 && context.y > 0) ||
                     (part.br().x == context.width && context.br().x < map.width) ||
                     (part.br().y == context.height && context.br().y < map.height);
    if (cut) box |= part;
  }
  return box;
}

// What cells_after_cleaning() needs of a cleaning, seen through box (a view: nothing is copied).
CleanedFreeSpace cropped_cleaning(const CleanedFreeSpace& cleaned, const cv::Rect& box) {
  CleanedFreeSpace part;
  part.removed = cleaned.removed(box);
  part.outside_cells = cleaned.outside_cells;  // counts of the whole: only tell whether to look at all
  part.speck_cells = cleaned.speck_cells;
  part.window = (cleaned.window & box) - box.tl();
  return part;
}

cv::Rect grown_within(const cv::Rect& r, int margin, const cv::Size& size) {
  return cv::Rect(r.x - margin, r.y - margin, r.width + 2 * margin, r.height + 2 * margin) & cv::Rect(cv::Point(), size);
}

}  // namespace

int front_end_reach(const SegmentOptions& options, double resolution) {
  return binarization_reach(options.binarize, resolution) + (options.clean ? cleaning_reach(options.cleaning, resolution) : 0);
}

// The cleaning of a window is given its reach beyond it, and the inside_closing again: the
// building's inside is judged by closing gaps up to inside_closing, and a ray ends on what lies
// around it.
int front_end_context(const SegmentOptions& options, double resolution) {
  const FreeSpaceCleaningOptions& o = options.cleaning;
  const int cleaning = static_cast<int>(std::min(cleaning_reach(o, resolution) + std::ceil(o.inside_closing / resolution), kMaxReach));
  return binarization_reach(options.binarize, resolution) + (options.clean ? cleaning : 0);
}

SegmentationInput segmentation_input(const OccupancyGrid& grid, const SegmentOptions& options) {
  return cleaned_input(grid, segmentation_free_space(grid, options), options);
}

int front_end_local_reach(const SegmentOptions& options, double resolution) {
  if (!options.clean || options.cleaning.inside_closing <= 0.0 || !trivial_binarization(options.binarize)) return -1;
  return cleaning_reach(options.cleaning, resolution, false);
}

SegmentationInput segmentation_input(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options) {
  return segmentation_input(grid, window, options, front_end_context(options, grid.resolution));
}

SegmentationInput segmentation_input(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options,
                                     int context_cells) {
  const cv::Rect context = grown_within(window, context_cells, grid.cells.size());
  const OccupancyGrid part = crop(grid, context);
  const cv::Rect inner = window - context.tl();
  cv::Mat free = has_free_cell(part.cells) ? free_space_mask(part, options.binarize) : cv::Mat();
  SegmentationInput input;
  // Without a binarization the mask holds the free cells, which has_free_cell found: no count needed.
  if (free.empty() || (!trivial_binarization(options.binarize) && cv::countNonZero(free) == 0)) {
    input.floor = cv::Mat::zeros(window.size(), CV_8UC1);
    input.labelled = crop(grid, window);
    return input;
  }
  input.labelled = crop(part, inner);
  // cleaned_input() over the context, its cells after the cleaning taken over the window only.
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!starts(rule, RuleStage::kClean, options)) continue;
    const CleanedFreeSpace cleaned = rule.clean(free, part.cells, part.resolution, options);
    free = cleaned.floor;
    input.labelled.cells = cells_after_cleaning(input.labelled.cells, cropped_cleaning(cleaned, inner));
    const cv::Rect cut = thin_parts_cut(cleaned, context, inner, grid.cells.size());
    if (!cut.empty()) input.thin_parts_cut |= cut + context.tl();
  }
  input.floor = free(inner).clone();
  return input;
}

namespace {

// The cut rows (segmentation_rules()) in order, each clear of the earlier ones' cuts, then the
// decomposition rows on each part of the polygon the cuts leave, each on the pieces of the one before.
// With fallible false, the cut rules that may fail are left out.
PieceSet decompose_polygon(const PolygonWithHoles& polygon, double resolution, const SegmentOptions& options, bool fallible,
                           SegmentTimes* times) {
  StageTimer timer(times, SegmentStage::kCuts);
  PieceSet set;
  const CutSearchIndex index(polygon, resolution, options.doors);  // every cut row searches the same edges
  for (const SegmentationRule& rule : segmentation_rules()) {
    if ((rule.may_fail && !fallible) || !starts(rule, RuleStage::kCut, options)) continue;
    for (const Segment2& cut : rule.find_cuts(polygon, resolution, options.doors, set.cuts, &index)) set.add_cut(cut, rule.cut_rule);
  }
  timer.next(SegmentStage::kDecomposition);
  std::vector<PolygonWithHoles> parts = split_polygon(polygon, set.cuts);
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!starts(rule, RuleStage::kDecompose, options)) continue;
    std::vector<PolygonWithHoles> pieces;
    for (const PolygonWithHoles& part : parts) {
      Decomposition result = rule.decompose(part, resolution, options);
      pieces.insert(pieces.end(), std::make_move_iterator(result.pieces.begin()), std::make_move_iterator(result.pieces.end()));
      for (const Cut& cut : result.cuts) set.add_cut(cut.segment, CutRule::kDecomposition);
    }
    parts = std::move(pieces);
  }
  set.pieces = std::move(parts);
  return set;
}

}  // namespace

PolygonWithHoles simplified_where_valid(const PolygonWithHoles& exact, double tolerance) {
  PolygonWithHoles polygon = simplify_polygon(exact, tolerance);
  // Restoring a ring can only remove crossings with it, so a few rounds reach a valid polygon (the
  // exact one at worst).
  for (int round = 0; round < 4; ++round) {
    const std::vector<int> bad = intersecting_rings(polygon);
    if (bad.empty()) return polygon;
    for (const int r : bad) {
      if (r == 0) polygon.outer = exact.outer;
      else polygon.holes[static_cast<std::size_t>(r - 1)] = exact.holes[static_cast<std::size_t>(r - 1)];
    }
  }
  return exact;
}

PieceSet decompose_pieces(const FreeSpaceComponent& component, double resolution, const SegmentOptions& options,
                          SegmentTimes* times) {
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  // Without a decomposition (--trivial) the cuts would split nothing: the component is one piece.
  if (std::none_of(rules.begin(), rules.end(), [&](const SegmentationRule& r) { return row_is_on(r, RuleStage::kDecompose, options); })) {
    PieceSet set;
    set.pieces.push_back(component.polygon);
    return set;
  }
  // The outline rows' polygon first (simplified), with every cut rule; a wall line grazing a corner
  // may leave a degenerate part, and simplified rings may touch after all (a very thin wall or gap),
  // so each failure falls back to the next try, the exact polygon without the rules that may fail last.
  const bool fallible_on =
      std::any_of(rules.begin(), rules.end(), [&](const SegmentationRule& r) { return r.may_fail && row_is_on(r, RuleStage::kCut, options); });
  auto attempt = [&](const PolygonWithHoles& polygon, bool last) -> std::optional<PieceSet> {
    if (fallible_on) {
      try {
        return decompose_polygon(polygon, resolution, options, true, times);
      } catch (const Error&) {
      }
    }
    if (last) return decompose_polygon(polygon, resolution, options, false, times);
    try {
      return decompose_polygon(polygon, resolution, options, false, times);
    } catch (const Error&) {
      return std::nullopt;
    }
  };
  try {
    std::optional<PolygonWithHoles> outline;
    {
      const StageTimer timer(times, SegmentStage::kFrontEnd);
      for (const SegmentationRule& rule : rules) {
        if (!starts(rule, RuleStage::kOutline, options)) continue;
        outline = rule.outline(outline ? *outline : component.polygon, options);
      }
    }
    if (outline) {
      if (std::optional<PieceSet> set = attempt(*outline, false)) return *set;
    }
    return *attempt(component.polygon, true);
  } catch (const Error& e) {
    throw Error("decomposing the free-space component at cell (" + std::to_string(component.first_pixel.x) + ", " +
                std::to_string(component.first_pixel.y) + ") failed: " + e.what());
  }
}

PieceSet decompose_component(const FreeSpaceComponent& component, const OccupancyGrid& grid, const SegmentOptions& options,
                             SegmentTimes* times) {
  const PieceSet pieces = decompose_pieces(component, grid.resolution, options, times);
  const StageTimer timer(times, SegmentStage::kMerging);
  return merge_rooms(component, pieces, grid.cells, grid.resolution, options, segmentation_rules());
}

SegmentOptions parity_segment_options(double concavity) {
  SegmentOptions options;
  options.concavity = concavity;
  for (const SegmentationRule& rule : segmentation_rules())
    if (rule.turn_off) rule.turn_off(options);
  options.labels.cover_absorbed_obstacles = false;
  options.contours.min_component_area = ContourOptions{}.min_component_area;
  return options;
}

cv::Rect segmentation_box(const OccupancyGrid& grid, const SegmentOptions& options) {
  validate(grid);
  const cv::Rect box = known_box(grid.cells);
  if (box.empty()) return cv::Rect(0, 0, grid.width(), grid.height());
  // Wider than every stage looks beyond a cell: the cleaning's closing and thickness test, the
  // robot radius, the opening and the median filter.
  const BinarizeOptions& b = options.binarize;
  const double reach = options.cleaning.inside_closing + options.cleaning.min_width + options.cleaning.max_obstacle_speck +
                       b.robot_radius + b.opening_size + b.median_size;
  // Capped at the map's size (the box is clipped to it anyway): lengths up to their limit at the
  // finest resolution would overflow an int.
  const int margin = static_cast<int>(std::min(std::ceil(reach / grid.resolution), double(std::max(grid.width(), grid.height())))) + 4;
  return cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) &
         cv::Rect(0, 0, grid.width(), grid.height());
}

namespace {

// The cells of grid that segment_input() labels: its free cells where to_label is set.
OccupancyGrid labelled_only(const OccupancyGrid& grid, const cv::Mat& to_label) {
  OccupancyGrid out = grid;
  out.cells = grid.cells.clone();
  out.cells.setTo(kOccupied, (to_label == 0) & (grid.cells == kFree));
  return out;
}

// The spans of after's rooms given those of before's: kept_spans() where after keeps some of before's
// rooms in their order (a row that drops rooms, or changes none), else the rooms rasterized anew.
std::vector<CellSpan> spans_after(const std::vector<PolygonWithHoles>& before, std::vector<CellSpan> spans,
                                  const std::vector<PolygonWithHoles>& after, cv::Size size) {
  std::vector<int> new_index(before.size(), -1);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < before.size() && kept < after.size(); ++i)
    if (before[i] == after[kept]) new_index[i] = static_cast<int>(kept++);
  if (kept < after.size()) return polygon_spans(after, size);
  if (after.size() == before.size()) return spans;  // the same rooms
  return kept_spans(spans, new_index);
}

}  // namespace

Segmentation segment_input(const SegmentationInput& input, const SegmentOptions& options, const cv::Mat& to_label,
                           SegmentTimes* times) {
  const OccupancyGrid& grid = input.labelled;
  FreeSpacePolygons polygons;
  {
    const StageTimer timer(times, SegmentStage::kFrontEnd);
    polygons = free_space_polygons(input.floor, grid.resolution, options.contours);
  }
  PieceSet pieces;
  for (const FreeSpaceComponent& component : polygons.components)
    pieces.append(decompose_component(component, grid, options, times));
  if (pieces.pieces.empty()) {  // a window whose floor holds no component: no room
    Segmentation none;
    none.labels = cv::Mat::zeros(grid.cells.size(), CV_32SC1);
    none.resolution = grid.resolution;
    none.origin = grid.origin;
    return none;
  }
  const std::vector<SegmentationRule>& rules = segmentation_rules();
  StageTimer timer(times, SegmentStage::kOpenRooms);
  // The rooms rasterized once for the open rooms and the labelling, again only if a row did more
  // than drop some of them.
  std::vector<CellSpan> spans = polygon_spans(pieces.pieces, grid.cells.size());
  for (const SegmentationRule& rule : rules) {
    if (!starts(rule, RuleStage::kRooms, options)) continue;
    PieceSet next = rule.on_rooms(pieces, grid, options, spans);
    spans = spans_after(pieces.pieces, std::move(spans), next.pieces, grid.cells.size());
    pieces = std::move(next);
  }
  timer.next(SegmentStage::kLabelling);
  const OccupancyGrid cells = to_label.empty() ? grid : labelled_only(grid, to_label);
  Segmentation segmentation;
  for (const SegmentationRule& rule : rules) {
    if (!starts(rule, RuleStage::kLabel, options)) continue;
    segmentation = rule.label(cells, pieces, options, spans);
  }
  BuildingInside inside(cells.cells);
  for (const SegmentationRule& rule : rules) {
    if ((rule.whole_map && !to_label.empty()) || !starts(rule, RuleStage::kLeaveOut, options)) continue;
    rule.leave_out(segmentation, cells, input.floor, options, inside);
  }
  timer.next(SegmentStage::kOutputs);
  // Once the rooms are final, whatever decided them; a window labelling only part of its cells
  // leaves the whole-map rows to its caller (its rooms' neighbours lie partly beyond it).
  for (const SegmentationRule& rule : rules) {
    if ((rule.whole_map && !to_label.empty()) || !starts(rule, RuleStage::kDescribe, options)) continue;
    rule.describe(segmentation, options);
  }
  return segmentation;
}

Segmentation segment_window(const OccupancyGrid& grid, const cv::Rect& window, const SegmentOptions& options,
                            SegmentationInput* used, SegmentTimes* times) {
  SegmentationInput local;
  SegmentationInput& input = used ? *used : local;
  {
    const StageTimer timer(times, SegmentStage::kFrontEnd);
    // The whole grid is not copied.
    input = window.size() == grid.cells.size() ? segmentation_input(grid, options) : segmentation_input(crop(grid, window), options);
  }
  return segment_input(input, options, cv::Mat(), times);
}

namespace {

// An image of the given size holding image at box and value everywhere else (uncrop()).
cv::Mat placed(const cv::Mat& image, const cv::Size& size, const cv::Rect& box, double value) {
  return image.empty() ? image : uncrop(image, size, box, value);
}

// The stages' images of the box, placed back into the whole grid.
void place_input(SegmentationInput& input, const OccupancyGrid& grid, const cv::Rect& box) {
  input.floor = placed(input.floor, grid.cells.size(), box, 0);
  cv::Mat labelled = grid.cells.clone();
  input.labelled.cells.copyTo(labelled(box));
  input.labelled = OccupancyGrid{labelled, grid.resolution, grid.origin};
  input.cleaned.floor = placed(input.cleaned.floor, grid.cells.size(), box, 0);
  input.cleaned.removed = placed(input.cleaned.removed, grid.cells.size(), box, kCellUntouched);
  input.cleaned.window += box.tl();
}

}  // namespace

Segmentation segment(const OccupancyGrid& grid, const SegmentOptions& options, SegmentationInput* used,
                     SegmentTimes* times) {
  SegmentationInput local;
  SegmentationInput& input = used ? *used : local;
  cv::Rect box;
  {
    const StageTimer timer(times, SegmentStage::kFrontEnd);
    validate(options);
    // SLAM maps are mostly unknown around the building (gmapping's default is 4000 x 4000 cells):
    // the stages run on the known cells' box only (segmentation_box validates the grid).
    box = segmentation_box(grid, options);
  }
  Segmentation segmentation = segment_window(grid, box, options, &input, times);
  if (box.size() == grid.cells.size()) return segmentation;
  const StageTimer timer(times, SegmentStage::kOutputs);
  segmentation.labels = placed(segmentation.labels, grid.cells.size(), box, 0);
  segmentation.origin = grid.origin;
  if (used) place_input(input, grid, box);
  return segmentation;
}

}  // namespace topocut
