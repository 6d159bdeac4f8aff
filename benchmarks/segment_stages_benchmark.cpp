// Segmentation stage times: where the milliseconds of `topocut segment` go on the Bormann images,
// or with --maps DIR on a folder of maps without ground truth (the real maps: YAMLs and images).
// For every image it runs the batch pipeline stage by stage (the same calls segment() makes,
// segment_stages.h) and prints the least CPU time of each stage over --repeat runs (process CPU
// time: on a shared, busy machine the least of a few runs is the steadiest estimate), next to the
// contour floor measured the same way (decode the PNG, threshold, cv::findContours), then each
// stage's time over the floor. Used to decide what to optimise; the dataset benchmark gives the
// end-to-end wall-clock figures.
//
// With --quality it also scores every image against its ground truth (recall / precision, as
// `topocut evaluate`), so that option variants can be compared stage by stage.
//
// --unexplored N centres every image map (not YAMLs) in an N x N image of its corner's grey (a SLAM
// map's unexplored surroundings; gmapping's default map is 4000 x 4000 cells), written to a
// temporary folder; --no-crop runs the stages on the whole grid instead of segmentation_box(), as
// segment() did before it cropped.
//
// Options: kUsage below (printed by --help).
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "topocut/core/allocator.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/precision_recall.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/io/map_loader.h"
#include "topocut/map/rasterize.h"
#include "topocut/segmentation/segmenter.h"

#include "benchmark_machine.h"
#include "segment_stages.h"

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

std::vector<Job> dataset_jobs(const std::vector<std::string>& names, const std::vector<Variant>& variants) {
  std::vector<Job> jobs;
  for (const DatasetMap& map : select_maps(discover_dataset(std::string(TOPOCUT_SHARED_DIR) + "/datasets/bormann"), names)) {
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

constexpr const char* kUsage =
    "Usage: segment_stages_benchmark [--repeat N] [--maps DIR] [--map NAME ...] [--variant plain|furnished|all]\n"
    "         [--unexplored N] [--no-crop] [--quality]\n"
    "         [--concavity M] [--parity] [--no-merge] [--door-ratio R] [--width-depth M] [--min-room-area M2]\n"
    "         [--min-room-width M] [--no-cover] [--min-hole-area M2] [--no-gaps] [--max-gap M] [--gap-side M]\n"
    "         [--wall-thickness M] [--gap-wall M] [--no-doors] [--door-max M] [--door-side-ratio R]\n"
    "         [--door-depth M] [--door-turn RAD] [--simplify CELLS]\n"
    "The least CPU time of each stage of `topocut segment` over --repeat runs, per Bormann image (or per\n"
    "map of --maps DIR), beside the contour floor; --quality also scores each image against its ground truth.\n";

int run(const std::vector<std::string>& args) {
  int repeat = 3;
  std::vector<std::string> names;
  std::vector<Variant> variants{Variant::kPlain, Variant::kFurnished};
  SegmentOptions options;
  bool quality = false;
  std::string maps_folder;
  int unexplored = 0;
  bool no_crop = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw Error(a + " needs a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "--repeat") {
      repeat = std::max(1, std::stoi(value()));
    } else if (a == "--unexplored") {
      unexplored = std::stoi(value());
    } else if (a == "--no-crop") {
      no_crop = true;
    } else if (a == "--maps") {
      maps_folder = value();
    } else if (a == "--map") {
      names.push_back(value());
      while (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) names.push_back(args[++i]);
    } else if (a == "--variant") {
      const std::string v = value();
      variants = v == "all" ? std::vector<Variant>{Variant::kPlain, Variant::kFurnished}
                            : std::vector<Variant>{parse_variant(v)};
    } else if (a == "--concavity") {
      options.concavity = std::stod(value());
    } else if (a == "--parity") {
      options = parity_segment_options(options.concavity);
    } else if (a == "--quality") {
      quality = true;
    } else if (a == "--no-merge") {
      options.merge.enabled = false;
    } else if (a == "--door-ratio") {
      options.merge.door_ratio = std::stod(value());
    } else if (a == "--width-depth") {
      options.merge.width_depth = std::stod(value());
    } else if (a == "--min-room-area") {
      options.merge.min_room_area = std::stod(value());
    } else if (a == "--min-room-width") {
      options.merge.min_room_width = std::stod(value());
    } else if (a == "--no-cover") {
      options.labels.cover_absorbed_obstacles = false;
    } else if (a == "--min-hole-area") {
      options.contours.min_hole_area = std::stod(value());
    } else if (a == "--no-gaps") {
      options.doors.extend_walls = false;
    } else if (a == "--max-gap") {
      options.doors.max_gap = std::stod(value());
    } else if (a == "--gap-side") {
      options.doors.min_side_width = std::stod(value());
    } else if (a == "--wall-thickness") {
      options.doors.max_wall_thickness = std::stod(value());
    } else if (a == "--gap-wall") {
      options.doors.min_wall_length = std::stod(value());
    } else if (a == "--no-doors") {
      options.doors.enabled = false;
    } else if (a == "--door-max") {
      options.doors.max_width = std::stod(value());
    } else if (a == "--door-side-ratio") {
      options.doors.door_ratio = std::stod(value());
    } else if (a == "--door-depth") {
      options.doors.width_depth = std::stod(value());
    } else if (a == "--door-turn") {
      options.doors.min_turn = std::stod(value());
    } else if (a == "--simplify") {
      options.simplify = std::stod(value());
    } else {
      throw Error("unknown argument '" + a + "'");
    }
  }
  const MapLoadOptions load;
  std::vector<Job> jobs = maps_folder.empty() ? dataset_jobs(names, variants) : folder_jobs(maps_folder, names);
  const std::string padded_folder =
      (std::filesystem::temp_directory_path() / ("topocut_padded_" + std::to_string(::getpid()))).string();
  if (unexplored > 0) pad_images(jobs, unexplored, padded_folder);
  if (quality && !maps_folder.empty()) throw Error("--quality needs the Bormann dataset (no --maps)");

  std::vector<std::vector<std::string>> rows{{"image", "floor", "load", "free", "clean", "polygons", "vertices",
                                              "decompose", "pieces", "merge", "labels", "rooms", "total",
                                              "total / floor", "recall", "precision"}};
  std::vector<std::vector<std::string>> over{{"image"}};
  std::vector<std::vector<double>> ratios;  // per stage after the floor, per image
  std::vector<double> recall[2], precision[2];
  std::vector<double> all_total, all_floor;
  for (const Job& job : jobs) {
    StageTimes t;
    Segmentation last;
    for (int k = 0; k < repeat; ++k) {
      const Segmentation s = benchmarks::time_stages(job.path, load, options, no_crop, t);
      if (k == 0) last = s;
    }
    const std::vector<std::pair<std::string, double>> stages = benchmarks::least_stage_ms(t);
    const double floor = stages.front().second, total = stages.back().second;
    all_total.push_back(total);
    all_floor.push_back(floor);
    auto ms = [&](const char* name) {
      for (const auto& [stage, value] : stages)
        if (stage == name) return fixed(value, 1);
      return std::string("-");
    };
    rows.push_back({job.name, ms("floor"), ms("load"), ms("free"), ms("clean"), ms("polygons"), std::to_string(t.vertices),
                    ms("decompose"), std::to_string(t.pieces), ms("merge"), ms("labels"), std::to_string(t.rooms_found),
                    ms("total"), fixed(total / floor, 2), "-", "-"});
    ratios.resize(stages.size() - 1);
    over.push_back({job.name});
    for (std::size_t k = 1; k < stages.size(); ++k) {
      if (over.size() == 2) over.front().push_back(stages[k].first);
      over.back().push_back(fixed(stages[k].second / floor, 2));
      ratios[k - 1].push_back(stages[k].second / floor);
    }
    if (quality) {
      const PrecisionRecall pr = evaluate_against_ground_truth(last.labels, load_ground_truth(job.ground_truth));
      const int v = job.variant == Variant::kPlain ? 0 : 1;
      recall[v].push_back(pr.recall);
      precision[v].push_back(pr.precision);
      rows.back()[14] = fixed(100.0 * pr.recall, 1);
      rows.back()[15] = fixed(100.0 * pr.precision, 1);
    }
    std::cerr << rows.back()[0] << " " << rows.back()[12] << " ms\n";
  }
  double load_average[3] = {0, 0, 0};
  getloadavg(load_average, 3);
  std::cout << "machine: " << benchmarks::cpu_model() << ", " << std::thread::hardware_concurrency()
            << " hardware threads, load average " << fixed(load_average[0], 1) << "; peak RSS "
            << fixed(benchmarks::peak_rss_mb(), 0) << " MB\n";
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
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  topocut::keep_freed_memory_for_reuse();
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "segment_stages_benchmark: error: " << e.what() << "\n";
    return 1;
  }
}
