// Map suite benchmark: one set of segmenter options on every kind of map at once (DESIGN.md, "Beyond
// Bormann"): the 20 Bormann maps (plain and furnished), the residential plans of r2v, the hand-drawn
// sketches scored against each of their two annotators, the raw SLAM maps registered onto Bormann's
// ground truth, robot-made maps of the r2v and Bormann plans (topocut simulate-map), and the real robot
// maps without ground truth (thin, speck and open rooms). Prints one table per set and a summary with
// the targets, so an idea is judged on all sets together;
// below topocut's row of a set, the peers' published results on it (MAORIS, DuDe, Voronoi) and, on the
// sketches, the other annotator's rooms, all scored by the same code. With --ablation, the table of the
// rule list instead: every rule switched off in turn. Options: --help.
//
// Times are CPU time of the thread that segments (thread_cpu_ms(), OpenCV on one thread), so that a
// busy machine and --threads 2 leave them alone; the table "Where the time goes" splits each image's
// time into loading and segment()'s stages (segment_times.h), over the image's contour floor.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <unistd.h>

#include <opencv2/imgproc.hpp>

#include "benchmark_machine.h"
#include "support/benchmark_main.h"
#include "topocut/core/clock.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_options.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/robot_made_dataset.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/segmentation/segmentation_rules.h"

namespace {

using namespace topocut;
using topocut::benchmarks::peak_rss_mb;

// Another segmentation of a set's plain images, scored beside topocut's.
struct Peer {
  std::string name;
  ImageSegmenter segmenter;
  std::vector<ImageResult> results;
};

// What one image cost (ms): loading the map, segment()'s stages, and its contour floor.
struct ImageTimes {
  std::string name;
  Variant variant = Variant::kPlain;
  double load = 0.0, floor = 0.0;
  SegmentTimes stages;
  double total() const { return load + stages.total(); }
};

// A set scored against ground truth.
struct ScoredSet {
  std::string name, folder;
  std::vector<Variant> variants;
  std::vector<std::string> targets;  // one per variant, as issue 25 states them
  std::vector<Peer> peers;           // scored on the plain variant
  std::vector<ImageResult> results;
  std::map<std::string, ImageTimes> times;  // by image path, the images that succeeded
};

// The published results of MAORIS, DuDe and Voronoi in peers_folder (label images named after the maps).
std::vector<Peer> published_peers(const std::string& peers_folder) {
  std::vector<Peer> peers;
  for (const auto& [name, folder] : {std::pair{"MAORIS", "maoris"}, {"DuDe", "dude"}, {"Voronoi", "voronoi"}}) {
    const std::string path = peers_folder + "/" + folder;
    if (!std::filesystem::is_directory(path)) continue;
    peers.push_back({name, labels_segmenter(path, DatasetRunOptions{}), {}});
  }
  return peers;
}

// One annotator's rooms of each sketch as a segmentation (read from reference_folder).
Peer annotator(const std::string& name, const std::string& reference_folder) {
  return {name, [reference_folder](const std::string& image_path) {
            const std::string path =
                reference_folder + "/" + std::filesystem::path(image_path).stem().string() + "_gt_segmentation.png";
            if (!std::filesystem::exists(path)) throw MissingSegmentation("no rooms " + path);
            Segmentation rooms;
            rooms.labels = ground_truth_rooms(load_ground_truth(path));
            return rooms;
          },
          {}};
}

// For every cell, the ground-truth room nearest to it (0 if there is no room).
cv::Mat nearest_room(const cv::Mat& rooms) {
  cv::Mat distance, nearest;
  cv::distanceTransform(rooms == 0, distance, nearest, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  std::vector<int> room_of{0};  // DIST_LABEL_PIXEL numbers the room cells in raster order from 1
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c)
      if (rooms.at<int>(r, c) != 0) room_of.push_back(rooms.at<int>(r, c));
  cv::Mat room(rooms.size(), CV_32SC1, cv::Scalar(0));
  if (room_of.size() == 1) return room;
  for (int r = 0; r < rooms.rows; ++r)
    for (int c = 0; c < rooms.cols; ++c) room.at<int>(r, c) = room_of[static_cast<std::size_t>(nearest.at<int>(r, c))];
  return room;
}

// A diagnostic segmenter: every segment of segmenter's result relabelled with the ground-truth room
// it overlaps most (a segment in no room: the room nearest to it), as a merging that knew people's
// rooms would join them. With --no-merge it tells how well the pieces score once joined by people's
// rooms, whatever the merging criterion: what the cuts allow (not a proven optimum of the means).
ImageSegmenter oracle_merged(ImageSegmenter segmenter) {
  return [segmenter](const std::string& path) {
    Segmentation s = segmenter(path);
    const cv::Mat rooms = ground_truth_rooms(load_ground_truth(find_ground_truth(path)));
    if (rooms.size() != s.labels.size()) throw Error(path + ": the ground truth and the map differ in size");
    const cv::Mat nearest = nearest_room(rooms);
    std::map<int, std::map<int, int>> overlap, near;  // segment -> room -> cells in it / nearest to it
    for (int r = 0; r < rooms.rows; ++r) {
      for (int c = 0; c < rooms.cols; ++c) {
        const int label = s.labels.at<int>(r, c);
        if (label == 0) continue;
        ++overlap[label][rooms.at<int>(r, c)];
        ++near[label][nearest.at<int>(r, c)];
      }
    }
    auto most = [](const std::map<int, int>& cells_by_room) {
      int best = 0, cells = 0;
      for (const auto& [room, n] : cells_by_room)
        if (room != 0 && n > cells) std::tie(best, cells) = std::pair{room, n};
      return best;
    };
    std::map<int, int> joined;  // segment -> room
    for (const auto& [label, by_room] : overlap) {
      const int room = most(by_room);
      joined[label] = room != 0 ? room : most(near[label]);
    }
    for (int r = 0; r < rooms.rows; ++r)
      for (int c = 0; c < rooms.cols; ++c)
        if (int& label = s.labels.at<int>(r, c); label != 0) label = joined.at(label);
    return s;
  };
}

// The library's pipeline (load_map, then segment()) with each image's load and stage times kept in times.
ImageSegmenter timed_segmenter(const DatasetRunOptions& options, std::map<std::string, ImageTimes>& times) {
  return [load = options.load, segment_options = options.segment, &times](const std::string& image_path) {
    ImageTimes t;
    t.name = std::filesystem::path(image_path).stem().string();
    const double start = thread_cpu_ms();
    const OccupancyGrid grid = load_map(image_path, load);
    t.load = thread_cpu_ms() - start;
    Segmentation s = segment(grid, segment_options, nullptr, &t.stages);
    times[image_path] = t;
    return s;
  };
}

void score_set(ScoredSet& set, const DatasetRunOptions& base, int floor_repetitions, bool oracle_merge) {
  DatasetRunOptions run = base;
  run.variants = set.variants;
  run.progress = {};
  const std::vector<DatasetMap> maps = discover_dataset(set.folder);
  const ImageSegmenter segmenter = timed_segmenter(run, set.times);
  set.results = run_dataset(maps, run, oracle_merge ? oracle_merged(segmenter) : segmenter);
  run.variants = {Variant::kPlain};
  for (Peer& peer : set.peers) peer.results = run_dataset(maps, run, peer.segmenter);
  for (const ImageResult& r : set.results) {
    const DatasetMap& map = *std::find_if(maps.begin(), maps.end(), [&](const DatasetMap& m) { return m.name == r.map; });
    const auto times = set.times.find(map.image(r.variant));
    if (times == set.times.end()) continue;
    if (!r.ok || floor_repetitions <= 0) {
      set.times.erase(times);
      continue;
    }
    times->second.variant = r.variant;
    times->second.floor = contour_floor_ms(map.image(r.variant), run.load.free_min, floor_repetitions, thread_cpu_ms);
  }
}

// The images of a set's variant that have times.
std::vector<ImageTimes> times_of(const ScoredSet& set, Variant variant) {
  std::vector<ImageTimes> times;
  for (const auto& [path, t] : set.times)
    if (t.variant == variant) times.push_back(t);
  return times;
}

// Lowest recall and precision over the images of a set.
std::pair<double, double> lowest(const std::vector<ImageResult>& results, Variant variant) {
  double recall = 1.0, precision = 1.0;
  for (const ImageResult& r : results) {
    if (!r.ok || r.variant != variant) continue;
    recall = std::min(recall, r.recall);
    precision = std::min(precision, r.precision);
  }
  return {recall, precision};
}

// The cells of a summary row shared by topocut and the peers: set, method, maps, R / P, F1 / PQ,
// segments per room, P inside / far (percent; means over the maps that have a result).
std::vector<std::string> summary_cells(const std::string& set, const std::string& method, const VariantSummary& s) {
  const std::string maps = s.succeeded() == s.images ? std::to_string(s.images)
                                                     : std::to_string(s.succeeded()) + " of " + std::to_string(s.images);
  if (s.succeeded() == 0) return {set, method, maps, "-", "-", "-", "-"};
  return {set, method, maps, fixed(100 * s.recall_mean, 1) + " / " + fixed(100 * s.precision_mean, 1),
          fixed(100 * s.f1_mean, 1) + " / " + fixed(100 * s.pq_mean, 1), fixed(s.segments_per_room, 2),
          fixed(100 * s.precision_inside_mean, 1) + " / " + fixed(100 * s.far_share_mean, 1)};
}

// "office_g furnished 175 ms": the image that took longest (CPU time, load + segment).
std::string slowest(const ScoredSet& set) {
  const ImageTimes* worst = nullptr;
  for (const auto& [path, t] : set.times)
    if (worst == nullptr || t.total() > worst->total()) worst = &t;
  return worst == nullptr ? "-" : worst->name + " " + fixed(worst->total(), 0) + " ms";
}

int count_missing(const std::vector<ScoredSet>& sets) {
  int missing = 0;
  for (const ScoredSet& set : sets)
    for (const Peer& peer : set.peers)
      for (const ImageResult& r : peer.results) missing += r.missing;
  return missing;
}

// "robot-made homes (3 seeds): F1 70.1 against 79.5 on the same plans clean (-9.4)": each robot-made set
// beside the clean set of its plans.
std::string robot_made_gap(const std::vector<ScoredSet>& scored) {
  std::string text;
  for (const ScoredSet& robot : scored) {
    if (robot.name.rfind("robot-made", 0) != 0) continue;
    const std::string plans = robot.name.find("homes") != std::string::npos ? "homes (r2v)" : "Bormann";
    const auto clean = std::find_if(scored.begin(), scored.end(), [&](const ScoredSet& s) { return s.name == plans; });
    if (clean == scored.end()) continue;
    const double f1 = 100 * summarize(robot.results, Variant::kPlain).f1_mean;
    const double f1_clean = 100 * summarize(clean->results, Variant::kPlain).f1_mean;
    text += robot.name + ": F1 " + fixed(f1, 1) + " against " + fixed(f1_clean, 1) + " on the same plans clean (" +
            (f1 >= f1_clean ? "+" : "") + fixed(f1 - f1_clean, 1) + ")\n";
  }
  return text;
}

// Each image's total (load + segment) over its floor.
std::vector<double> total_ratios(const std::vector<ImageTimes>& times) {
  std::vector<double> ratios;
  for (const ImageTimes& t : times)
    if (t.floor > 0.0) ratios.push_back(t.total() / t.floor);
  return ratios;
}

std::string ratio_text(const std::vector<ImageTimes>& times) {
  const std::vector<double> ratios = total_ratios(times);
  if (ratios.empty()) return "-";
  const TimeStatistics s = time_statistics(ratios);
  return fixed(s.median, 1) + " / " + fixed(s.max, 1);
}

// Robot-made maps of a set of plans: seeds maps of each plan, made into robot_maps/folder before scoring.
struct RobotMadeSet {
  std::string name, plans, folder;
  int seeds = 1;
};

std::vector<RobotMadeSet> robot_made_sets(const std::string& datasets, const std::string& robot_maps) {
  return {{"robot-made homes (3 seeds)", datasets + "/r2v", robot_maps + "/r2v", 3},
          {"robot-made offices", datasets + "/bormann", robot_maps + "/bormann", 1}};
}

// Makes the robot-made maps of set unless its folder already holds them all (the same seeds give the same
// maps, so a folder kept from an earlier run with the same simulator is reused).
void make_robot_maps(const RobotMadeSet& set) {
  const std::vector<DatasetMap> plans = discover_dataset(set.plans);
  if (std::filesystem::is_directory(set.folder) &&
      discover_dataset(set.folder).size() == plans.size() * static_cast<std::size_t>(set.seeds))
    return;
  RobotMadeDatasetOptions options;
  options.seeds = set.seeds;
  const RobotMadeDataset made = make_robot_made_dataset(plans, set.folder, options);
  if (!made.failed.empty()) throw Error(set.name + ": " + made.failed.front());
}

// The header of the table "Where the time goes".
std::vector<std::string> stage_header() {
  std::vector<std::string> header{"set", "images", "floor ms", "load"};
  for (std::size_t k = 0; k < kSegmentStages; ++k) header.push_back(stage_name(static_cast<SegmentStage>(k)));
  for (const char* column : {"segment", "total", "total max", "slowest ms"}) header.push_back(column);
  return header;
}

// One row of "Where the time goes": the median over the images of each stage's time over the image's
// floor, of segment() and of the total (load + segment); the largest total over the floor and the
// slowest image's total in ms.
std::vector<std::string> stage_row(const std::string& set, const std::vector<ImageTimes>& times) {
  std::vector<std::string> row{set, std::to_string(times.size())};
  if (times.empty()) {
    row.resize(stage_header().size(), "-");
    return row;
  }
  auto median_over = [&](const std::function<double(const ImageTimes&)>& part) {
    std::vector<double> values;
    for (const ImageTimes& t : times) values.push_back(part(t));
    return time_statistics(values).median;
  };
  row.push_back(fixed(median_over([](const ImageTimes& t) { return t.floor; }), 1));
  row.push_back(fixed(median_over([](const ImageTimes& t) { return t.load / t.floor; }), 2));
  for (std::size_t k = 0; k < kSegmentStages; ++k)
    row.push_back(fixed(median_over([k](const ImageTimes& t) { return t.stages.ms[k] / t.floor; }), 2));
  row.push_back(fixed(median_over([](const ImageTimes& t) { return t.stages.total() / t.floor; }), 2));
  const TimeStatistics total = time_statistics(total_ratios(times));
  row.push_back(fixed(total.median, 2));
  row.push_back(fixed(total.max, 2));
  double slowest = 0.0;
  for (const ImageTimes& t : times) slowest = std::max(slowest, t.total());
  row.push_back(fixed(slowest, 1));
  return row;
}

// Per image: the floor, loading and every stage in ms (--details).
std::string stage_details(const std::vector<ImageTimes>& times) {
  std::vector<std::vector<std::string>> rows{{"image", "variant", "floor ms", "load ms"}};
  for (std::size_t k = 0; k < kSegmentStages; ++k) rows.front().push_back(stage_name(static_cast<SegmentStage>(k)) + " ms");
  rows.front().push_back("total ms");
  rows.front().push_back("total / floor");
  for (const ImageTimes& t : times) {
    std::vector<std::string> row{t.name, to_string(t.variant), fixed(t.floor, 1), fixed(t.load, 1)};
    for (const double ms : t.stages.ms) row.push_back(fixed(ms, 1));
    row.push_back(fixed(t.total(), 1));
    row.push_back(t.floor > 0.0 ? fixed(t.total() / t.floor, 2) : "-");
    rows.push_back(row);
  }
  return markdown_table(rows);
}

// The real maps' times as those of the scored images.
std::vector<ImageTimes> times_of(const std::vector<MapDefectResult>& real) {
  std::vector<ImageTimes> times;
  for (const MapDefectResult& r : real) {
    if (!r.ok || r.floor_ms <= 0.0) continue;
    ImageTimes t;
    t.name = r.map;
    t.load = r.load_ms;
    t.floor = r.floor_ms;
    t.stages = r.stages;
    times.push_back(t);
  }
  return times;
}

// The sets scored against ground truth, with their targets and (with_peers) the rows to compare with.
std::vector<ScoredSet> scored_sets(const std::string& datasets, const std::string& robot_maps, bool with_peers) {
  const std::string lex = datasets + "/sketches/lex", ezvin = datasets + "/sketches/ezvin";
  std::vector<Peer> sketch_peers = with_peers ? published_peers(datasets + "/peers/sketches") : std::vector<Peer>{};
  std::vector<ScoredSet> scored{
      {"Bormann", datasets + "/bormann", {Variant::kPlain, Variant::kFurnished},
       {"F1 ≥ 95, R ≥ 98.5, P ≥ 97.5", "R ≥ 92.5, P ≥ 97.0"}, with_peers ? published_peers(datasets + "/peers/bormann") : std::vector<Peer>{}, {}, {}},
      {"sketches (lex)", lex, {Variant::kPlain}, {"F1 ≥ 84, R ≥ 92, P ≥ 88"}, sketch_peers, {}, {}},
      {"sketches (ezvin)", ezvin, {Variant::kPlain}, {"F1 ≥ 70, R ≥ 92, P ≥ 85"}, sketch_peers, {}, {}},
      {"raw maps with people's rooms", datasets + "/real_maps_gt", {Variant::kPlain}, {"R ≥ 95, P inside ≥ 95"}, {}, {},
       {}},
      {"homes (r2v)", datasets + "/r2v", {Variant::kPlain}, {"F1 ≥ 75"}, {}, {}, {}},
  };
  for (const RobotMadeSet& robot : robot_made_sets(datasets, robot_maps))
    scored.push_back({robot.name, robot.folder, {Variant::kPlain}, {robot.seeds > 1 ? "F1 within 6 of the plans clean" : ""}, {}, {}, {}});
  if (with_peers) {
    scored[1].peers.push_back(annotator("ezvin's rooms", ezvin));
    scored[2].peers.push_back(annotator("lex's rooms", lex));
  }
  return scored;
}

// The job that segments the real maps (no ground truth) with run's options into real.
std::function<void()> real_maps_job(const std::string& datasets, const DatasetRunOptions& run, int floor_repetitions,
                                    std::vector<MapDefectResult>& real) {
  MapFolderOptions options;
  options.segment = run.segment;
  options.load = run.load;
  options.floor_repetitions = floor_repetitions;
  options.clock = thread_cpu_ms;
  return [datasets, options, &real] { real = run_map_files(discover_map_files(datasets + "/real_maps"), options); };
}

// Runs jobs on threads threads; the messages of the jobs that threw.
std::vector<std::string> run_jobs(const std::vector<std::function<void()>>& jobs, int threads) {
  std::mutex mutex;
  std::vector<std::string> errors;
  std::size_t next = 0;
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (;;) {
        std::size_t job = 0;
        {
          const std::lock_guard<std::mutex> lock(mutex);
          if (next == jobs.size()) return;
          job = next++;
        }
        try {
          jobs[job]();
        } catch (const std::exception& e) {
          const std::lock_guard<std::mutex> lock(mutex);
          errors.push_back(e.what());
        }
      }
    });
  }
  for (std::thread& t : pool) t.join();
  return errors;
}

// The options of a run (besides the segmenter's).
struct SuiteOptions {
  bool details = false, oracle_merge = false, ablation = false;
  int floor_repetitions = 5, threads = 1;
  std::string shared = TOPOCUT_SHARED_DIR;
  std::string robot_maps;  // where the robot-made maps are made (empty: a temporary folder, removed after)
};

// The folder for the robot-made maps: the one asked for, or a new temporary one removed when the run ends.
class RobotMapsFolder {
 public:
  explicit RobotMapsFolder(const std::string& asked) : path_(asked) {
    if (!path_.empty()) return;
    path_ = (std::filesystem::temp_directory_path() / ("topocut_map_suite_" + std::to_string(::getpid()))).string();
    temporary_ = true;
  }
  ~RobotMapsFolder() {
    std::error_code ignored;
    if (temporary_) std::filesystem::remove_all(path_, ignored);
  }
  RobotMapsFolder(const RobotMapsFolder&) = delete;
  RobotMapsFolder& operator=(const RobotMapsFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool temporary_ = false;
};

// Makes every robot-made set's maps, threads at a time; the sets that failed are reported as errors.
std::vector<std::string> make_all_robot_maps(const std::string& datasets, const std::string& robot_maps, int threads) {
  std::vector<std::function<void()>> jobs;
  for (const RobotMadeSet& set : robot_made_sets(datasets, robot_maps)) jobs.push_back([set] { make_robot_maps(set); });
  return run_jobs(jobs, threads);
}

int run(const SuiteOptions& suite, const DatasetArguments& arguments) {
  const bool details = suite.details, oracle_merge = suite.oracle_merge;
  const int floor_repetitions = suite.floor_repetitions, threads = suite.threads;
  const std::string datasets = suite.shared + "/datasets";
  benchmarks::require_folder(datasets);
  const RobotMapsFolder robot_maps(suite.robot_maps);
  std::vector<std::string> errors = make_all_robot_maps(datasets, robot_maps.path(), threads);

  std::vector<ScoredSet> scored = scored_sets(datasets, robot_maps.path(), true);
  std::vector<MapDefectResult> real;
  // Times are the segmenting thread's CPU time: OpenCV's own workers would escape it.
  cv::setNumThreads(1);

  std::vector<std::function<void()>> jobs;
  for (ScoredSet& set : scored) jobs.push_back([&, floor_repetitions] { score_set(set, arguments.run, floor_repetitions, oracle_merge); });
  jobs.push_back(real_maps_job(datasets, arguments.run, floor_repetitions, real));
  for (const std::string& e : run_jobs(jobs, threads)) errors.push_back(e);
  for (const std::string& e : errors) std::cerr << "map_suite_benchmark: " << e << "\n";

  std::cout << "threads used: " << threads << "\nmethod: " << method_name(arguments.run.segment) << "\n\n";
  if (details) {
    for (const ScoredSet& set : scored) {
      std::cout << "## " << set.name << "\n\n" << format_results_table(set.results) << "\n";
      for (const Peer& peer : set.peers)
        std::cout << "### " << set.name << ": " << peer.name << "\n\n" << format_results_table(peer.results) << "\n";
      if (floor_repetitions > 0) {
        std::vector<ImageTimes> times;
        for (const Variant variant : set.variants)
          for (const ImageTimes& t : times_of(set, variant)) times.push_back(t);
        std::cout << "### " << set.name << ": times (CPU ms)\n\n" << stage_details(times) << "\n";
      }
    }
    std::cout << "## real maps (no ground truth)\n\n";
  }
  std::cout << format_defects_table(real) << "\n";

  std::vector<std::vector<std::string>> rows{{"set", "method", "maps", "R / P %", "F1 / PQ %", "seg / room",
                                              "P inside % / far %", "lowest R / P %", "target",
                                              "ms / floor (median / max)"}};
  int failed = 0;
  for (const ScoredSet& set : scored) {
    for (std::size_t v = 0; v < set.variants.size(); ++v) {
      const Variant variant = set.variants[v];
      const VariantSummary s = summarize(set.results, variant);
      failed += s.failed;
      const auto [low_r, low_p] = lowest(set.results, variant);
      const std::string name = set.variants.size() > 1 ? set.name + " " + to_string(variant) : set.name;
      std::vector<std::string> row = summary_cells(name, "topocut", s);
      row.push_back(fixed(100 * low_r, 1) + " / " + fixed(100 * low_p, 1));
      row.push_back(set.targets[v]);
      row.push_back(ratio_text(times_of(set, variant)));
      rows.push_back(row);
      if (variant != Variant::kPlain) continue;
      for (const Peer& peer : set.peers) {
        const VariantSummary p = summarize(peer.results, variant);
        failed += p.failed;  // a peer's missing images are no failure: it published fewer
        rows.push_back(summary_cells("", peer.name, p));
      }
    }
  }
  const RoomDefects total = total_defects(real);
  for (const MapDefectResult& r : real) failed += r.ok ? 0 : 1;
  rows.push_back({"real maps: thin + speck + open rooms", "topocut", std::to_string(real.size()),
                  std::to_string(total.thin) + " + " + std::to_string(total.specks) + " + " + std::to_string(total.open) +
                      " of " + std::to_string(total.rooms) + " (" + fixed(100.0 * flagged_share(total), 1) + " %)",
                  "", "", "", "", "≤ 2 % of rooms", ratio_text(times_of(real))});
  const double unseen_share = total.rooms > 0 ? 100.0 * total.unseen / total.rooms : 0.0;
  rows.push_back({"real maps: rooms bounded mostly by never-seen cells", "topocut", std::to_string(real.size()),
                  std::to_string(total.unseen) + " of " + std::to_string(total.rooms) + " (" + fixed(unseen_share, 1) + " %)",
                  "", "", "", "", "≤ 5 % of rooms", ""});
  std::cout << markdown_table(rows) << "\nfailures: " << failed << "; peak RSS " << fixed(peak_rss_mb(), 0) << " MB\n";
  std::cout << robot_made_gap(scored) << "\n";
  if (!total.open_judged) std::cout << "open rooms are not judged on maps without occupied cells (see the table above)\n";
  if (floor_repetitions > 0) {
    std::vector<std::vector<std::string>> stages{stage_header()};
    for (const ScoredSet& set : scored) {
      std::vector<ImageTimes> all;
      for (const Variant variant : set.variants) {
        const std::vector<ImageTimes> times = times_of(set, variant);
        stages.push_back(stage_row(set.variants.size() > 1 ? set.name + " " + to_string(variant) : set.name, times));
        all.insert(all.end(), times.begin(), times.end());
      }
      if (set.variants.size() > 1) stages.push_back(stage_row(set.name + ", all images", all));
    }
    stages.push_back(stage_row("real maps", times_of(real)));
    std::cout << "\nWhere the time goes: CPU time of the segmenting thread over the image's contour floor (decode,\n"
                 "threshold, findContours), median over the images (the stages' medians need not add up); segment =\n"
                 "segment(), total = load + segment; total max over the floor; the slowest image's total in ms.\n\n"
              << markdown_table(stages) << "\n";
    std::cout << "slowest Bormann image: " << slowest(scored.front()) << " (target ≤ 150 ms)\n";
  }
  const int missing_peers = count_missing(scored);
  if (missing_peers > 0)
    std::cout << missing_peers << " peer images are missing (published for fewer maps); their means say over how many maps they run\n";
  return failed > 0 || !errors.empty() ? benchmarks::kFailed : benchmarks::kDone;
}


// The ablation generated from the rule list (segmentation_rules.h): the suite with the given options,
// then once with each rule that is on switched off. One row per run: matched F1 on every scored set
// (the means over its maps) and the share of flagged rooms on the real maps.
int run_ablation(const SuiteOptions& suite, const DatasetArguments& arguments) {
  const std::string datasets = suite.shared + "/datasets";
  benchmarks::require_folder(datasets);
  std::vector<std::pair<std::string, SegmentOptions>> runs{{"(every rule on)", arguments.run.segment}};
  for (const SegmentationRule& rule : segmentation_rules()) {
    if (!rule.turn_off || !rule.is_on(arguments.run.segment)) continue;
    SegmentOptions off = arguments.run.segment;
    rule.turn_off(off);
    runs.emplace_back("--no-" + rule.name, off);
  }
  const RobotMapsFolder robot_maps(suite.robot_maps);
  for (const std::string& e : make_all_robot_maps(datasets, robot_maps.path(), suite.threads)) {
    std::cerr << "map_suite_benchmark: " << e << "\n";
    return benchmarks::kFailed;
  }
  std::vector<std::string> header{"run"};
  for (const ScoredSet& set : scored_sets(datasets, robot_maps.path(), false))
    for (const Variant variant : set.variants)
      header.push_back((set.variants.size() > 1 ? set.name + " " + to_string(variant) : set.name) + " F1");
  header.push_back("real maps flagged %");
  std::vector<std::vector<std::string>> rows{header};
  int failed = 0;
  for (const auto& [name, options] : runs) {
    DatasetRunOptions run = arguments.run;
    run.segment = options;
    std::vector<ScoredSet> scored = scored_sets(datasets, robot_maps.path(), false);
    std::vector<MapDefectResult> real;
    std::vector<std::function<void()>> jobs;
    for (ScoredSet& set : scored) jobs.push_back([&set, &run] { score_set(set, run, 0, false); });
    jobs.push_back(real_maps_job(datasets, run, 0, real));
    for (const std::string& e : run_jobs(jobs, suite.threads)) std::cerr << "map_suite_benchmark: " << name << ": " << e << "\n";
    std::vector<std::string> row{name};
    for (const ScoredSet& set : scored) {
      for (const Variant variant : set.variants) {
        const VariantSummary v = summarize(set.results, variant);
        failed += v.failed;
        row.push_back(fixed(100 * v.f1_mean, 1));
      }
    }
    for (const MapDefectResult& r : real) failed += r.ok ? 0 : 1;
    row.push_back(fixed(100.0 * flagged_share(total_defects(real)), 1));
    rows.push_back(row);
    std::cerr << "map_suite_benchmark: " << name << " done\n";
  }
  std::cout << "threads used: " << suite.threads << "\nmethod: " << method_name(arguments.run.segment) << "\n\n"
            << markdown_table(rows) << "\nfailures: " << failed << "\n";
  return failed > 0 ? benchmarks::kFailed : benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  SuiteOptions suite;
  topocut::DatasetArguments arguments;
  const Program program{
      .name = "map_suite_benchmark",
      .title = "Map suite benchmark",
      .about = "One set of segmenter options on every kind of map at once: Bormann (plain, furnished), r2v's homes,\n"
               "the sketches against both annotators, raw maps registered onto people's rooms, robot-made maps of\n"
               "the r2v and Bormann plans (made first, topocut simulate-map), real maps without ground truth; with\n"
               "the peers' published results and the targets.\n",
      .options = {flag("details", suite.details, "also print the per-image tables"),
                  flag("ablation", suite.ablation,
                       "the ablation instead: the suite once as given and once with each rule of the rule list "
                       "switched off (matched F1 per set, real maps' flagged rooms)"),
                  flag("oracle-merge", suite.oracle_merge,
                       "diagnostic: join segments by the ground-truth room they overlap most (with --no-merge: the pieces "
                       "joined by people's rooms)"),
                  {"floor-repetitions", "N", "contour floor repetitions per image (default 5; 0: no times)",
                   [&suite](const std::string& value) {
                     suite.floor_repetitions = whole_number("--floor-repetitions", value, 0, 1000);
                   }},
                  count("threads", suite.threads, 1, "sets on N threads (default 1; times are each thread's CPU time)"),
                  text("robot-maps", "DIR", suite.robot_maps,
                       "make the robot-made maps in DIR and keep them for the next run (default: a temporary folder)"),
                  text("shared", "DIR", suite.shared, "folder holding datasets/ (default " TOPOCUT_SHARED_DIR ")")},
      .dataset = &arguments,
      .tune_allocator = true};
  return benchmark_main(argc, argv, program,
                        [&] { return suite.ablation ? run_ablation(suite, arguments) : run(suite, arguments); });
}
