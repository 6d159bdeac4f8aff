// Segmentation stage times: where the milliseconds of `topocut segment` go on the Bormann images,
// or with --maps DIR on a folder of maps without ground truth (the real maps: YAMLs and images).
// For every image it loads the map and runs segment() with its stage times (segment_stages.h), and
// prints the least CPU time of each stage over --repeat runs (process CPU time: on a shared, busy
// machine the least of a few runs is the steadiest estimate), next to the contour floor measured
// the same way (decode the PNG, threshold, cv::findContours), then each stage's time over the
// floor; the front end's parts (free space, cleaning, polygons) are timed again on their own. Used
// to decide what to optimise; the map suite gives every set's figures.
//
// With --quality it also scores every image against its ground truth (recall / precision, as
// `topocut evaluate`), so that option variants can be compared stage by stage.
//
// --unexplored N centres every image map (not YAMLs) in an N x N image of its corner's grey (a SLAM
// map's unexplored surroundings; gmapping's default map is 4000 x 4000 cells), written to a
// temporary folder.
//
// Options: --help. The segmenter's are `topocut evaluate`'s (the library's table); the numbers of
// DoorOptions and MergeOptions that table does not have yet are this program's own, applied after it.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/core/option_table.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/io/map_loader.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/segmenter.h"

#include "benchmark_machine.h"
#include "segment_stages.h"
#include "support/benchmark_main.h"

namespace {

using namespace topocut;
using benchmarks::least;
using benchmarks::StageTimes;

double median(std::vector<double> v) { return time_statistics(std::move(v)).median; }

// One image to time: a Bormann image (with its ground truth) or a map of a folder.
struct Job {
  std::string name, path, ground_truth;
  Variant variant = Variant::kPlain;
};

std::vector<Job> dataset_jobs(const std::string& dataset, const std::vector<std::string>& names, const std::vector<Variant>& variants) {
  benchmarks::require_folder(dataset);
  std::vector<Job> jobs;
  for (const DatasetMap& map : select_maps(discover_dataset(dataset), names)) {
    for (const Variant variant : variants)
      jobs.push_back({map.name + (variant == Variant::kPlain ? "" : " (f)"), map.image(variant), map.ground_truth, variant});
  }
  return jobs;
}

// The image of every job (not YAMLs) centred in a side x side image of its top-left pixel's value,
// written into folder; the jobs then read those.
void pad_images(std::vector<Job>& jobs, int side, const std::string& folder) {
  std::filesystem::create_directories(folder);
  for (Job& job : jobs) {
    if (is_yaml_path(job.path)) continue;
    const cv::Mat image = cv::imread(job.path, cv::IMREAD_UNCHANGED);
    if (image.empty() || image.cols > side || image.rows > side) throw Error("cannot pad '" + job.path + "'");
    const int top = (side - image.rows) / 2, left = (side - image.cols) / 2;
    cv::Mat padded;
    cv::copyMakeBorder(image, padded, top, side - image.rows - top, left, side - image.cols - left, cv::BORDER_CONSTANT,
                       image.channels() == 1 ? cv::Scalar(image.at<unsigned char>(0, 0)) : cv::Scalar::all(0));
    job.path = folder + "/" + std::filesystem::path(job.path).stem().string() + ".png";
    if (!cv::imwrite(job.path, padded)) throw Error("cannot write '" + job.path + "'");
  }
}

std::vector<Job> folder_jobs(const std::string& folder, const std::vector<std::string>& names) {
  std::vector<Job> jobs;
  for (const MapFile& map : discover_map_files(folder)) {
    if (names.empty() || std::find(names.begin(), names.end(), map.name) != names.end())
      jobs.push_back({map.name, map.path, "", Variant::kPlain});
  }
  if (jobs.empty()) throw Error("no map of '" + folder + "' is selected");
  return jobs;
}

// Edits of the segmenter's options given on the command line beyond the library's table.
using Edits = std::vector<std::function<void(SegmentOptions&)>>;

// An option setting the number field(options) refers to, recorded in edits.
template <typename Field>
benchmarks::Option extra(const char* name, const char* help, Edits& edits, Field field) {
  return {name, "X", help, [&edits, name, field](const std::string& value) {
            const double v = parse_option_number(value, std::string("--") + name);
            edits.push_back([field, v](SegmentOptions& o) { field(o) = v; });
          }};
}

// What to time and how, besides the segmenter's options.
struct StagesOptions {
  int repeat = 3;
  bool quality = false;
  std::string maps_folder;
  int unexplored = 0;
  Edits edits;
};

int run(const StagesOptions& stages_options, const DatasetArguments& arguments) {
  const int repeat = stages_options.repeat;
  const bool quality = stages_options.quality;
  const std::string& maps_folder = stages_options.maps_folder;
  const int unexplored = stages_options.unexplored;
  if (!arguments.csv.empty()) throw Error("--csv is not written here");
  const std::vector<std::string>& names = arguments.run.maps;
  SegmentOptions options = arguments.run.segment;
  for (const auto& edit : stages_options.edits) edit(options);
  const MapLoadOptions& load = arguments.run.load;
  std::vector<Job> jobs =
      maps_folder.empty() ? dataset_jobs(arguments.dataset, names, arguments.run.variants) : folder_jobs(maps_folder, names);
  const std::string padded_folder =
      (std::filesystem::temp_directory_path() / ("topocut_padded_" + std::to_string(::getpid()))).string();
  if (unexplored > 0) pad_images(jobs, unexplored, padded_folder);
  if (quality && !maps_folder.empty()) throw Error("--quality needs the Bormann dataset (no --maps)");

  const std::vector<std::string> columns = benchmarks::stage_names();
  std::vector<std::vector<std::string>> rows{{"image"}};
  for (const std::string& name : columns) rows.front().push_back(name);
  for (const char* column : {"vertices", "rooms", "total / floor", "recall", "precision"}) rows.front().push_back(column);
  std::vector<std::vector<std::string>> over{{"image"}};
  for (std::size_t k = 1; k < columns.size(); ++k) over.front().push_back(columns[k]);
  std::vector<std::vector<double>> ratios(columns.size() - 1);  // per column after the floor, per image
  std::vector<double> recall[2], precision[2];
  std::vector<double> all_total, all_floor;
  for (const Job& job : jobs) {
    StageTimes t;
    Segmentation last;
    for (int k = 0; k < repeat; ++k) {
      const Segmentation s = benchmarks::time_stages(job.path, load, options, t);
      if (k == 0) last = s;
    }
    const std::vector<std::pair<std::string, double>> stages = benchmarks::least_stage_ms(t);
    const double floor = stages.front().second, total = stages.back().second;
    all_total.push_back(total);
    all_floor.push_back(floor);
    rows.push_back({job.name});
    for (const auto& [stage, ms] : stages) rows.back().push_back(fixed(ms, 1));
    for (const std::string& cell : {std::to_string(t.vertices), std::to_string(t.rooms_found), fixed(total / floor, 2),
                                    std::string("-"), std::string("-")})
      rows.back().push_back(cell);
    over.push_back({job.name});
    for (std::size_t k = 1; k < stages.size(); ++k) {
      over.back().push_back(fixed(stages[k].second / floor, 2));
      ratios[k - 1].push_back(stages[k].second / floor);
    }
    if (quality) {
      const PrecisionRecall pr = evaluate_against_ground_truth(last.labels, load_ground_truth(job.ground_truth));
      const int v = job.variant == Variant::kPlain ? 0 : 1;
      recall[v].push_back(pr.recall);
      precision[v].push_back(pr.precision);
      rows.back()[rows.back().size() - 2] = fixed(100.0 * pr.recall, 1);
      rows.back().back() = fixed(100.0 * pr.precision, 1);
    }
    std::cerr << job.name << " " << fixed(total, 1) << " ms\n";
  }
  std::cout << "method: " << method_name(options) << "; peak RSS " << fixed(benchmarks::peak_rss_mb(), 0) << " MB\n";
  std::cout << "process CPU times in ms, least of " << repeat << " runs per image\n\n" << markdown_table(rows) << "\n";
  over.push_back({"median"});
  over.push_back({"max"});
  for (const std::vector<double>& r : ratios) {
    over[over.size() - 2].push_back(fixed(median(r), 2));
    over.back().push_back(fixed(*std::max_element(r.begin(), r.end()), 2));
  }
  std::cout << "each stage's time over the floor\n\n" << markdown_table(over) << "\n";
  std::cout << "median total " << fixed(median(all_total), 1) << " ms, median floor " << fixed(median(all_floor), 1)
            << " ms, median ratio " << fixed(median(ratios.back()), 2) << ", max total "
            << fixed(*std::max_element(all_total.begin(), all_total.end()), 1) << " ms\n";
  auto mean = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : 100.0 * std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  auto lowest = [](const std::vector<double>& v) { return v.empty() ? 0.0 : 100.0 * *std::min_element(v.begin(), v.end()); };
  if (quality) {
    std::cout << "plain recall " << fixed(mean(recall[0]), 2) << " precision " << fixed(mean(precision[0]), 2)
              << " | furnished recall " << fixed(mean(recall[1]), 2) << " precision " << fixed(mean(precision[1]), 2)
              << " | lowest recall " << fixed(std::min(lowest(recall[0]), lowest(recall[1])), 1) << " precision "
              << fixed(std::min(lowest(precision[0]), lowest(precision[1])), 1) << "\n";
  }
  if (unexplored > 0) std::filesystem::remove_all(padded_folder);
  return benchmarks::kDone;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  StagesOptions o;
  topocut::DatasetArguments arguments;
  Edits& e = o.edits;
  const Program program{
      .name = "segment_stages_benchmark",
      .title = "Segmentation stage times",
      .about = "The least CPU time of each stage of `topocut segment` over --repeat runs, per Bormann image (or per map\n"
               "of --maps DIR), beside the contour floor; --quality also scores each image against its ground truth.\n",
      .options = {count("repeat", o.repeat, 1, "runs per image, least time taken (default 3)"),
                  text("maps", "DIR", o.maps_folder, "time the maps of DIR (images and YAMLs) instead of the dataset"),
                  count("unexplored", o.unexplored, 1, "centre every image map in an N x N image of its corner's grey"),
                  flag("quality", o.quality, "also score each image against its ground truth (not with --maps)"),
                  extra("door-ratio", "merging: largest cut over the narrower side's width kept as a door", e,
                        [](SegmentOptions& s) -> double& { return s.merge.door_like.ratio; }),
                  extra("width-depth", "merging: the width-over-depth bound of a door", e,
                        [](SegmentOptions& s) -> double& { return s.merge.door_like.width_depth; }),
                  extra("min-room-width", "merging: narrowest room (m)", e,
                        [](SegmentOptions& s) -> double& { return s.merge.min_room_width; }),
                  extra("max-gap", "doors: widest gap (m) where a thin wall stops short", e,
                        [](SegmentOptions& s) -> double& { return s.doors.max_gap; }),
                  extra("gap-side", "doors: narrowest side (m) of a wall opening", e,
                        [](SegmentOptions& s) -> double& { return s.doors.min_side_width; }),
                  extra("wall-thickness", "doors: thickest wall (m) of a wall opening", e,
                        [](SegmentOptions& s) -> double& { return s.doors.max_wall_thickness; }),
                  extra("gap-wall", "doors: shortest wall (m) of a wall opening", e,
                        [](SegmentOptions& s) -> double& { return s.doors.min_wall_length; }),
                  extra("door-side-ratio", "doors: largest door width over the side's width", e,
                        [](SegmentOptions& s) -> double& { return s.doors.door_like.ratio; }),
                  extra("door-depth", "doors: the width-over-depth bound of a door", e,
                        [](SegmentOptions& s) -> double& { return s.doors.door_like.width_depth; }),
                  extra("door-turn", "doors: least turn (radians) at a door's ends", e,
                        [](SegmentOptions& s) -> double& { return s.doors.min_turn; }),
                  extra("simplify", "outline simplification tolerance (cells)", e,
                        [](SegmentOptions& s) -> double& { return s.simplify; })},
      .dataset = &arguments,
      .tune_allocator = true};
  return benchmark_main(argc, argv, program, [&] { return run(o, arguments); });
}
