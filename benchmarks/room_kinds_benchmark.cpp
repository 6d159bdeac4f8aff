// Room kinds benchmark: how well the kind room_kinds.h gives a room (corridor or room) agrees with
// people's room types. On r2v's homes (X.json names each drawn room's types) it scores the kind of
// people's own rooms (the classifier alone) and of topocut's rooms matched to people's rooms one-to-one
// (IoU > 0.5, matched_rooms.h); people's corridor is a room typed only "corridor". Plans are split in two
// halves by a hash of their name: the thresholds are swept on one half and scored on the other, beside
// the library's defaults on both. On the Bormann offices (no types) it counts the rooms called
// corridors per map, for people's rooms and topocut's, and with --pictures DIR writes overlays coloured
// by kind to look at. Options: --help.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "benchmark_machine.h"
#include "support/benchmark_main.h"
#include "topocut/core/clock.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/matched_rooms.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/overlay.h"
#include "topocut/segmentation/room_kinds.h"
#include "topocut/segmentation/segmenter.h"

namespace {

using namespace topocut;

constexpr double kNone = std::numeric_limits<double>::infinity();

// One room scored: its shape, whether people call it a corridor, and its plan's half (0 or 1).
struct Case {
  RoomShape shape;
  bool corridor = false;
  int half = 0;
};

// The rooms of one set: people's own, and topocut's matched to people's.
struct Cases {
  std::vector<Case> people, topocut;
  int plans = 0, unmatched_segments = 0;
};

// Counts of a kind against people's: corridor is the positive class.
struct Score {
  int tp = 0, fp = 0, fn = 0, tn = 0;
  int rooms() const { return tp + fp + fn + tn; }
  double precision() const { return tp + fp > 0 ? double(tp) / (tp + fp) : 0.0; }
  double recall() const { return tp + fn > 0 ? double(tp) / (tp + fn) : 0.0; }
  double f1() const { return tp > 0 ? 2.0 * tp / (2.0 * tp + fp + fn) : 0.0; }
  double accuracy() const { return rooms() > 0 ? double(tp + tn) / rooms() : 0.0; }
};

// half: 0 or 1 scores that half only, -1 every case.
Score score(const std::vector<Case>& cases, const RoomKindOptions& options, int half) {
  Score s;
  for (const Case& c : cases) {
    if (half >= 0 && c.half != half) continue;
    const bool said = room_kind(c.shape, options) == RoomKind::kCorridor;
    (said ? (c.corridor ? s.tp : s.fp) : (c.corridor ? s.fn : s.tn))++;
  }
  return s;
}

// The half a plan falls in: FNV-1a of its name (the same on every machine, unlike std::hash).
int half_of(const std::string& name) {
  std::uint32_t h = 2166136261u;
  for (const unsigned char c : name) h = (h ^ c) * 16777619u;
  return static_cast<int>(h & 1u);
}

// Room id (ground_truth_rooms() numbering: raster order of the first cell) -> people call it a
// corridor; X.json lists the rooms in that order, each with its types.
std::map<int, bool> corridors_of(const std::string& json_path) {
  std::ifstream in(json_path);
  if (!in) throw Error("cannot read " + json_path);
  const nlohmann::json plan = nlohmann::json::parse(in);
  std::map<int, bool> corridor;
  for (const nlohmann::json& room : plan.at("rooms")) {
    bool only_corridor = !room.at("labels").empty();
    for (const nlohmann::json& type : room.at("labels")) only_corridor = only_corridor && type == "corridor";
    corridor[room.at("id").get<int>()] = only_corridor;
  }
  return corridor;
}

// People's rooms with the map's free cells that lie in no room (the lines drawn across doors) given to
// the nearest room, so that rooms joined by a door touch, as topocut's rooms do at their cuts.
cv::Mat touching_rooms(const cv::Mat& rooms, const cv::Mat& free) {
  cv::Mat distance, nearest;
  cv::distanceTransform(rooms == 0, distance, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<int> room_of{0};  // DIST_LABEL_PIXEL numbers the room cells in raster order from 1
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c)
      if (rooms.at<int>(r, c) != 0) room_of.push_back(rooms.at<int>(r, c));
  cv::Mat out = rooms.clone();
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c)
      if (out.at<int>(r, c) == 0 && free.at<unsigned char>(r, c) != 0 && distance.at<float>(r, c) <= 3.0f)
        out.at<int>(r, c) = room_of[static_cast<std::size_t>(nearest.at<int>(r, c))];
  return out;
}

// Rooms of more than the evaluation's ignored size, by label.
std::map<int, int> counted_rooms(const cv::Mat& labels, const EvaluationOptions& evaluation) {
  std::map<int, int> cells;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (const int l = labels.at<int>(r, c); l > 0) ++cells[l];
  std::erase_if(cells, [&](const auto& entry) { return entry.second <= evaluation.max_ignored_pixels; });
  return cells;
}

struct Plan {
  OccupancyGrid grid;
  cv::Mat free, rooms;  // the map's free cells; people's rooms (ground_truth_rooms())
  Segmentation segmentation;
  double segment_ms = 0.0;  // CPU time of segment(), kinds included
};

Plan load_plan(const DatasetMap& map, const DatasetRunOptions& run) {
  Plan p;
  p.grid = load_map(map.plain, run.load);
  p.free = p.grid.cells == kFree;
  p.rooms = ground_truth_rooms(load_ground_truth(map.ground_truth), run.evaluation);
  if (p.rooms.size() != p.grid.cells.size()) throw Error(map.name + ": the ground truth and the map differ in size");
  const double start = thread_cpu_ms();
  p.segmentation = segment(p.grid, run.segment);
  p.segment_ms = thread_cpu_ms() - start;
  return p;
}

Cases r2v_cases(const std::string& folder, const DatasetRunOptions& run) {
  Cases cases;
  for (const DatasetMap& map : discover_dataset(folder)) {
    const Plan p = load_plan(map, run);
    const std::map<int, bool> corridor = corridors_of(folder + "/" + map.name + ".json");
    const int half = half_of(map.name);
    const std::map<int, int> counted = counted_rooms(p.rooms, run.evaluation);
    const std::vector<RoomShape> people = room_shapes(touching_rooms(p.rooms, p.free), p.grid.resolution, run.segment.kinds);
    for (const auto& [id, cells] : counted) {
      const auto type = corridor.find(id);
      if (type == corridor.end()) throw Error(map.name + ": room " + std::to_string(id) + " has no type");
      cases.people.push_back({people[static_cast<std::size_t>(id - 1)], type->second, half});
    }
    const RoomOutcomes outcomes = room_outcomes(p.segmentation.labels, p.rooms, p.free, run.evaluation);
    const std::vector<RoomShape> ours = room_shapes(p.segmentation.labels, p.grid.resolution, run.segment.kinds);
    for (const auto& [segment, room] : outcomes.segment_match) {
      if (room == 0) {
        ++cases.unmatched_segments;
        continue;
      }
      cases.topocut.push_back({ours[static_cast<std::size_t>(segment - 1)], corridor.at(room), half});
    }
    ++cases.plans;
    if (cases.plans % 100 == 0) std::cerr << "room_kinds_benchmark: " << cases.plans << " plans\n";
  }
  return cases;
}

// The thresholds swept on homes (RoomKindOptions' other fields as given: the hallway rule is for
// offices, which homes cannot tell; print_hallway() shows what it costs them).
std::vector<RoomKindOptions> sweep(const RoomKindOptions& base) {
  std::vector<RoomKindOptions> grid;
  for (int openings = 1; openings <= 4; ++openings)
    for (int e = 0; e <= 8; ++e)
      for (int w = 0; w <= 9; ++w) {
        RoomKindOptions o = base;
        o.openings = openings;
        o.elongation = 1.8 + 0.2 * e;
        o.width = 0.9 + 0.1 * w;
        grid.push_back(o);
      }
  return grid;
}

// The swept thresholds with the best corridor F1 on people's rooms of one half (the first on ties).
RoomKindOptions fitted(const std::vector<Case>& people, const RoomKindOptions& base, int half) {
  RoomKindOptions best = base;
  double best_f1 = -1.0;
  for (const RoomKindOptions& o : sweep(base)) {
    const double f1 = score(people, o, half).f1();
    if (f1 > best_f1 + 1e-12) std::tie(best, best_f1) = std::pair{o, f1};
  }
  return best;
}

std::string thresholds(const RoomKindOptions& o) {
  const std::string hallway = std::isinf(o.hallway_elongation) ? "none" : fixed(o.hallway_elongation, 0);
  return ">= " + std::to_string(o.openings) + " rooms, elongation >= " + fixed(o.elongation, 1) + ", width <= " +
         fixed(o.width, 1) + " m or elongation >= " + hallway;
}

std::vector<std::string> score_row(const std::string& name, const std::string& scored_on, const Score& s) {
  return {name,
          scored_on,
          std::to_string(s.rooms()),
          std::to_string(s.tp + s.fn),
          std::to_string(s.tp + s.fp),
          fixed(100 * s.precision(), 1),
          fixed(100 * s.recall(), 1),
          fixed(100 * s.f1(), 1),
          fixed(100 * s.accuracy(), 1)};
}

const std::vector<std::string> kScoreHeader{"thresholds", "scored on", "rooms", "people's corridors", "called corridor",
                                            "corridor precision %", "corridor recall %", "corridor F1 %", "accuracy %"};

void print_r2v(const Cases& cases, const RoomKindOptions& defaults) {
  const RoomKindOptions on_a = fitted(cases.people, defaults, 0), on_b = fitted(cases.people, defaults, 1);
  std::cout << "## r2v homes: " << cases.plans << " plans, halves A / B by name hash\n\n"
            << "fitted on A: " << thresholds(on_a) << "\nfitted on B: " << thresholds(on_b)
            << "\nfitted on all: " << thresholds(fitted(cases.people, defaults, -1))
            << "\ndefaults:    " << thresholds(defaults) << "\n\n";
  for (const auto& [title, set] : {std::pair{"people's rooms (the classifier alone)", &cases.people},
                                   std::pair{"topocut's rooms matched to people's (IoU > 0.5)", &cases.topocut}}) {
    std::vector<std::vector<std::string>> rows{kScoreHeader};
    rows.push_back(score_row("fitted on A", "B", score(*set, on_a, 1)));
    rows.push_back(score_row("fitted on B", "A", score(*set, on_b, 0)));
    rows.push_back(score_row("defaults", "A", score(*set, defaults, 0)));
    rows.push_back(score_row("defaults", "B", score(*set, defaults, 1)));
    rows.push_back(score_row("defaults", "all", score(*set, defaults, -1)));
    RoomKindOptions all_room = defaults;
    all_room.openings = std::numeric_limits<int>::max();
    rows.push_back(score_row("every room a room", "all", score(*set, all_room, -1)));
    std::cout << "### " << title << "\n\n" << markdown_table(rows) << "\n";
  }
  std::cout << "topocut's segments matching no room of people's (not scored): " << cases.unmatched_segments << "\n\n";
}

// What each condition of the defaults adds: the defaults with one condition dropped, on both sets.
void print_ablation(const Cases& cases, const RoomKindOptions& defaults) {
  std::vector<std::pair<std::string, RoomKindOptions>> variants{{"defaults", defaults}};
  RoomKindOptions o = defaults;
  o.openings = 0;
  variants.emplace_back("no openings condition", o);
  o = defaults;
  o.width = kNone;
  variants.emplace_back("no width condition (scale-free)", o);
  o = defaults;
  o.hallway_elongation = kNone;
  variants.emplace_back("no hallway rule", o);
  o = defaults;
  o.elongation = 0.0;
  variants.emplace_back("no elongation condition", o);
  std::vector<std::vector<std::string>> rows{
      {"variant", "people's rooms: F1 %", "precision %", "recall %", "topocut's rooms: F1 %", "precision %", "recall %"}};
  for (const auto& [name, options] : variants) {
    const Score p = score(cases.people, options, -1), t = score(cases.topocut, options, -1);
    rows.push_back({name, fixed(100 * p.f1(), 1), fixed(100 * p.precision(), 1), fixed(100 * p.recall(), 1), fixed(100 * t.f1(), 1),
                    fixed(100 * t.precision(), 1), fixed(100 * t.recall(), 1)});
  }
  std::cout << "### r2v, all plans: what each condition of the defaults adds\n\n" << markdown_table(rows) << "\n";
}

// CPU time (ms) of assign_room_kinds() on s, the median of 5 runs.
double kinds_time(const Segmentation& s, const RoomKindOptions& options) {
  std::vector<double> ms;
  for (int k = 0; k < 5; ++k) {
    Segmentation copy = s;
    const double start = thread_cpu_ms();
    assign_room_kinds(copy, options);
    ms.push_back(thread_cpu_ms() - start);
  }
  std::sort(ms.begin(), ms.end());
  return ms[2];
}

// Shapes of people's rooms and topocut's on the Bormann maps, for the hallway table.
struct OfficeShapes {
  std::vector<RoomShape> people, topocut;
};

// The hallway rule is for offices, whose hallways are wider than a home's corridor: r2v tells what a
// lower threshold costs in homes (rooms wrongly called corridors), the Bormann maps what it finds.
void print_hallway(const Cases& cases, const OfficeShapes& offices, const RoomKindOptions& defaults) {
  std::vector<std::vector<std::string>> rows{{"hallway elongation", "r2v people's: F1 %", "precision %", "topocut's: F1 %",
                                              "precision %", "Bormann corridors: people's rooms", "topocut's rooms"}};
  for (const double hallway : {4.0, 5.0, 6.0, 7.0, 8.0, 10.0, kNone}) {
    RoomKindOptions o = defaults;
    o.hallway_elongation = hallway;
    const Score p = score(cases.people, o, -1), t = score(cases.topocut, o, -1);
    auto corridors = [&o](const std::vector<RoomShape>& shapes) {
      return std::count_if(shapes.begin(), shapes.end(), [&o](const RoomShape& s) { return room_kind(s, o) == RoomKind::kCorridor; });
    };
    rows.push_back({std::isinf(hallway) ? "none" : fixed(hallway, 0) + (hallway == defaults.hallway_elongation ? " (default)" : ""),
                    fixed(100 * p.f1(), 1), fixed(100 * p.precision(), 1), fixed(100 * t.f1(), 1), fixed(100 * t.precision(), 1),
                    std::to_string(corridors(offices.people)), std::to_string(corridors(offices.topocut))});
  }
  std::cout << "### The hallway rule: homes against offices\n\n" << markdown_table(rows) << "\n";
}

// Rooms called corridors on every Bormann map (no types there): people's rooms and topocut's.
OfficeShapes print_bormann(const std::string& folder, const DatasetRunOptions& run, const std::string& pictures) {
  OfficeShapes shapes_of_all;
  std::vector<std::vector<std::string>> rows{{"map", "people's rooms", "called corridor", "their area m²", "topocut's rooms",
                                              "called corridor", "their area m²", "segment() ms", "kinds ms"}};
  std::vector<double> shares;
  if (!pictures.empty()) std::filesystem::create_directories(pictures);
  for (const DatasetMap& map : discover_dataset(folder)) {
    const Plan p = load_plan(map, run);
    Segmentation people;
    people.labels = touching_rooms(p.rooms, p.free);
    people.resolution = p.grid.resolution;
    const std::map<int, int> counted = counted_rooms(p.rooms, run.evaluation);
    const std::vector<RoomShape> shapes = room_shapes(people.labels, people.resolution, run.segment.kinds);
    const std::vector<RoomShape> ours_shapes = room_shapes(p.segmentation.labels, p.grid.resolution, run.segment.kinds);
    for (const Room& room : p.segmentation.rooms) shapes_of_all.topocut.push_back(ours_shapes[static_cast<std::size_t>(room.id - 1)]);
    int people_corridors = 0;
    double people_area = 0.0;
    for (const auto& [id, cells] : counted) {
      Room room;
      room.id = id;
      room.kind = room_kind(shapes[static_cast<std::size_t>(id - 1)], run.segment.kinds);
      shapes_of_all.people.push_back(shapes[static_cast<std::size_t>(id - 1)]);
      people.rooms.push_back(room);
      if (room.kind == RoomKind::kCorridor) {
        ++people_corridors;
        people_area += shapes[static_cast<std::size_t>(id - 1)].area;
      }
    }
    int ours = 0;
    double ours_area = 0.0;
    for (const Room& room : p.segmentation.rooms) {
      if (room.kind != RoomKind::kCorridor) continue;
      ++ours;
      ours_area += room.labelled_area;
    }
    const double kinds_ms = kinds_time(p.segmentation, run.segment.kinds);
    shares.push_back(kinds_ms / p.segment_ms);
    rows.push_back({map.name, std::to_string(counted.size()), std::to_string(people_corridors), fixed(people_area, 0),
                    std::to_string(p.segmentation.rooms.size()), std::to_string(ours), fixed(ours_area, 0), fixed(p.segment_ms, 1),
                    fixed(kinds_ms, 2)});
    if (pictures.empty()) continue;
    OverlayOptions overlay;
    overlay.colour_by_kind = true;
    overlay.draw_passages = false;
    write_overlay(pictures + "/" + map.name + "_kinds.png", p.grid, p.segmentation, overlay);
    people.origin = p.grid.origin;
    write_overlay(pictures + "/" + map.name + "_people_kinds.png", p.grid, people, overlay);
  }
  std::sort(shares.begin(), shares.end());
  std::cout << "## Bormann offices (no types): rooms called corridors per map\n\n" << markdown_table(rows)
            << "\nkinds' share of segment() (CPU time, median over the maps of 5 runs each): "
            << fixed(100 * shares[shares.size() / 2], 1) << " % (largest " << fixed(100 * shares.back(), 1) << " %)\n\n";
  return shapes_of_all;
}

struct KindsOptions {
  std::string shared = TOPOCUT_SHARED_DIR;
  std::string pictures;
  bool no_bormann = false;
};

int run(const KindsOptions& kinds, DatasetArguments& arguments) {
  const std::string datasets = kinds.shared + "/datasets";
  benchmarks::require_folder(datasets + "/r2v");
  DatasetRunOptions run = arguments.run;
  const RoomKindOptions& defaults = run.segment.kinds;
  const Cases cases = r2v_cases(datasets + "/r2v", run);
  print_r2v(cases, defaults);
  print_ablation(cases, defaults);
  if (!kinds.no_bormann && std::filesystem::is_directory(datasets + "/bormann"))
    print_hallway(cases, print_bormann(datasets + "/bormann", run, kinds.pictures), defaults);
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  KindsOptions kinds;
  topocut::DatasetArguments arguments;
  const Program program{
      .name = "room_kinds_benchmark",
      .title = "Room kinds benchmark",
      .about = "The kind of each room (corridor or room) against people's room types on r2v's homes, for people's\n"
               "own rooms and topocut's matched rooms, thresholds fitted on one half of the plans and scored on\n"
               "the other; rooms called corridors on each Bormann office map.\n",
      .options = {text("pictures", "DIR", kinds.pictures, "write the Bormann maps' overlays coloured by kind into DIR"),
                  flag("no-bormann", kinds.no_bormann, "r2v only"),
                  text("shared", "DIR", kinds.shared, "folder holding datasets/ (default " TOPOCUT_SHARED_DIR ")")},
      .dataset = &arguments,
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(kinds, arguments); });
}
