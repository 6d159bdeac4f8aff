// topocut evaluate: segments every image of a Bormann-format dataset (or reads another tool's label
// images of it) and scores it against the ground truth (precision/recall as Bormann et al., ICRA 2016,
// define them; matched rooms; precision inside annotated space).
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/command.h"
#include "topocut/core/format.h"
#include "cli/library_options.h"
#include "topocut/core/error.h"
#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_options.h"
#include "topocut/evaluation/dataset_report.h"
#include "topocut/evaluation/html_report.h"
#include "topocut/evaluation/room_defects.h"
#include "topocut/evaluation/incremental_dataset.h"
#include "topocut/evaluation/incremental_dataset_report.h"
#include "topocut/io/atomic_file.h"
#include "topocut/io/map_loader.h"
#include "topocut/io/output_files.h"

namespace topocut::cli {
namespace {

const char* const kDatasetHelp =
    "Bormann-format dataset folder (required unless --maps): for each map X, X.png (plain), X_furnitures.png "
    "(furnished) and X_gt_segmentation.png (ground truth); the bundled maps: --dataset maps";

// What a bare `topocut evaluate` needs to be told.
const char* const kNoDataset =
    "no dataset given: --dataset DIR (X.png, X_gt_segmentation.png per map X; the bundled maps: --dataset "
    "maps), or --maps DIR for maps without ground truth";

// The row of dataset_options() whose help the command writes its own.
const std::string kDatasetOptionName = "dataset";

// What evaluate does besides the dataset's options: the mode, the folders read instead of segmenting,
// the report written.
struct EvaluateRequest {
  std::string mode = "batch";
  std::string labels, maps, report;
  MapFolderOptions folder = [] {
    MapFolderOptions o;
    o.floor_repetitions = 3;  // a command's run is short: a few repetitions give the floor's median
    return o;
  }();
};

const std::vector<ChoiceRow<EvaluateRequest>>& mode_rows() {
  static const std::vector<ChoiceRow<EvaluateRequest>> rows = {choice_row<EvaluateRequest, std::string>(
      "mode", &EvaluateRequest::mode, {{"batch", "batch"}, {"incremental", "incremental"}},
      "batch, or incremental: a simulated robot (360° laser, 5 m) explores each image and every update of its map is segmented incrementally")};
  return rows;
}

const std::vector<TextRow<EvaluateRequest>>& folder_rows() {
  using R = EvaluateRequest;
  static const std::vector<TextRow<R>> rows = {
      path_row("labels", "DIR", TextKind::kInput, &R::labels,
               "score the label images in DIR instead of segmenting: X.png for map X (X_furnitures.png for its furnished image), one grey or 16-bit value a region (0 none) or one colour a region (black none), restricted to the map's free pixels; a map without its image is reported as missing"),
      path_row("maps", "DIR", TextKind::kInput, &R::maps,
               "maps without ground truth (every YAML, else image at --resolution, in DIR): count per map the rooms, the thin rooms (>= 1 m², less than half survives an opening with a 0.6 m disc: ray fans, slivers, strips), the speck rooms (0.1 to 1 m²) and the open rooms (>= 1 m², more than half of their outline against walls or never-seen cells runs into never-seen cells; unknown cells within 0.15 m of a wall count as wall; not judged on a map without occupied cells), time the whole segmentation and compare it with the map's contour floor"),
      path_row("report", "DIR", TextKind::kOutput, &R::report,
               "write DIR/index.html (created if missing): the summary and per-image tables and, per image, the ground truth's rooms beside the segmentation (DIR/MAP_VARIANT_truth.png, _rooms.png), matched pairs in one colour, missed rooms hatched red, segments that merged rooms orange")};
  return rows;
}

// The dataset's own options (evaluation's table, which the dataset benchmarks parse too), then
// the segmentation and map-loading flags every command shares.
po::options_description described_options() {
  po::options_description described("Evaluation");
  for (const DatasetOption& option : dataset_options()) {
    if (option.name == kDatasetOptionName) {  // the library's default folder is the benchmarks' (a checkout's ../shared)
      described.add_options()(option.name.c_str(), po::value<std::string>()->value_name("DIR"), kDatasetHelp);
    } else if (option.value_name.empty()) {
      described.add_options()(option.name.c_str(), po::bool_switch(), option.help.c_str());
    } else if (option.repeatable) {
      described.add_options()(option.name.c_str(),
                              po::value<std::vector<std::string>>()->multitoken()->composing()->value_name(
                                  option.value_name),
                              option.help.c_str());
    } else {
      described.add_options()(option.name.c_str(), po::value<std::string>()->value_name(option.value_name),
                              option.help.c_str());
    }
  }
  const DatasetArguments defaults;
  add_segment_options(described, defaults.segment);
  add_map_load_options(described, defaults.run.load);
  return described;
}

DatasetArguments to_arguments(const po::variables_map& vm) {
  DatasetArguments arguments;
  check_usage([&] {
    for (const DatasetOption& option : dataset_options()) {
      if (!vm.count(option.name)) continue;
      if (option.value_name.empty()) {
        if (vm[option.name].as<bool>()) apply_dataset_option(arguments, option.name, "");
      } else if (option.repeatable) {
        for (const std::string& value : vm[option.name].as<std::vector<std::string>>()) {
          apply_dataset_option(arguments, option.name, value);
        }
      } else {
        apply_dataset_option(arguments, option.name, vm[option.name].as<std::string>());
      }
    }
  });
  arguments.segment = read_segment_settings(vm, arguments.segment);
  check_usage([&] { arguments.run.segment = to_segment_options(arguments.segment); });
  arguments.run.load = read_map_load_options(vm, arguments.run.load);
  return arguments;
}

// 1 with one error line when some runs failed. The table and the CSV are complete reports that show
// the failed rows, so they are kept (an exception would discard the outputs).
int failure_exit_code(std::size_t failed, std::size_t total, const char* what) {
  if (failed == 0) return 0;
  std::cerr << "topocut evaluate: error: " << failed << " of " << total << " " << what << " failed (see FAILED in the table)\n";
  return 1;
}

// --mode incremental: a simulated robot explores every image (exploration module) and each
// update of its map is segmented incrementally; the final maps are scored, updates timed.
// comparison holds the batch comparison's rows (batch_comparison_rows()).
int run_incremental(const DatasetArguments& arguments, const std::vector<DatasetMap>& maps,
                    const ExplorationRunOptions& comparison) {
  IncrementalDatasetOptions options;
  options.run = arguments.run;
  options.exploration.compare_batch = comparison.compare_batch;
  options.exploration.batch_every = comparison.batch_every;
  const std::vector<IncrementalImageResult> results = run_incremental_dataset(maps, options);
  const std::string method = method_name(arguments.run.segment) + ", incremental";
  std::cout << "Dataset " << terminal_text(arguments.dataset) << ", " << maps.size() << " maps, method: " << terminal_text(method) << "\n\n"
            << format_incremental_report(results, method) << std::flush;
  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, incremental_results_csv(results));
  std::size_t failed = 0;
  for (const IncrementalImageResult& result : results) failed += result.incremental.ok ? 0 : 1;
  return failure_exit_code(failed, results.size(), "images");
}

// Every file a dataset run may read, so that the CSV is never one of them.
std::vector<std::string> dataset_files(const std::vector<DatasetMap>& maps) {
  std::vector<std::string> files;
  for (const DatasetMap& map : maps) files.insert(files.end(), {map.plain, map.furnished, map.ground_truth});
  return files;
}

// The label images --labels may read, so that the CSV is never one of them.
std::vector<std::string> label_files(const std::vector<DatasetMap>& maps, const std::string& folder) {
  std::vector<std::string> files;
  for (const DatasetMap& map : maps) {
    for (const std::string& image : {map.plain, map.furnished})
      files.push_back((std::filesystem::path(folder) / (std::filesystem::path(image).stem().string() + ".png")).string());
  }
  return files;
}

// The report's folder: created if missing (the pictures are written into it as images are scored).
void prepare_report_folder(const std::string& folder) {
  std::error_code error;
  if (std::filesystem::exists(folder, error) && !std::filesystem::is_directory(folder, error))
    throw Error("the report folder '" + folder + "' is a file, not a folder");
  std::filesystem::create_directories(folder, error);
  if (error) throw Error("cannot make the report folder '" + folder + "': " + error.message());
}

// --maps DIR: maps without ground truth, judged by the rooms no person would draw.
int run_defects(const DatasetArguments& arguments, const std::string& folder, MapFolderOptions options) {
  options.segment = arguments.run.segment;
  options.load = arguments.run.load;
  options.progress = [](const std::string& line) { progress(line); };
  const std::vector<MapFile> files = discover_map_files(folder);
  if (!arguments.csv.empty()) {
    std::vector<std::string> inputs;
    for (const MapFile& file : files) {
      const std::vector<std::string> read = map_files(file.path);
      inputs.insert(inputs.end(), read.begin(), read.end());
    }
    check_outputs({arguments.csv}, inputs);
  }
  const std::vector<MapDefectResult> results = run_map_files(files, options);
  std::cout << "Maps " << terminal_text(folder) << ", method: " << method_name(arguments.run.segment) << "\n\n"
            << format_defects_table(results) << std::flush;
  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, defects_csv(results));
  std::size_t failed = 0;
  for (const MapDefectResult& result : results) failed += result.ok ? 0 : 1;
  return failure_exit_code(failed, results.size(), "maps");
}

int run(const std::vector<std::string>& args) {
  EvaluateRequest request;
  po::options_description described = described_options();
  add_choice_rows(described, mode_rows(), request);
  add_text_rows(described, folder_rows());
  po::options_description folder_options("With --maps");
  add_option_rows(folder_options, map_folder_option_rows(), request.folder);
  described.add(folder_options);
  po::options_description comparison_options("With --mode incremental");
  add_option_rows(comparison_options, batch_comparison_rows<ExplorationRunOptions>(), ExplorationRunOptions{});
  described.add(comparison_options);
  const auto vm = parse_options(
      "topocut evaluate --dataset DIR [--variant plain|furnished|all] [--csv FILE] [--concavity M]\n"
      "                        [--trivial] [--map NAME ...] [--mode batch|incremental [--compare-batch]]\n"
      "       topocut evaluate --dataset DIR --labels DIR [--variant V] [--map NAME ...] [--csv FILE]\n"
      "       topocut evaluate --maps DIR [--resolution M] [--csv FILE] [segmenter options]",
      "Segments every map of a Bormann-format dataset folder (for each map X: X.png plain,\n"
      "X_furnitures.png furnished, X_gt_segmentation.png ground truth; 0.05 m/px) and scores it\n"
      "against the ground truth as Bormann et al. (ICRA 2016) define it: ground-truth pixels > 250\n"
      "are free and split into rooms by 8-connected flood fill; rooms and segments of <= 100 px are\n"
      "ignored; precision = mean over segments S of max_R |S ∩ R| / |S|, recall = mean over rooms R\n"
      "of max_S |S ∩ R| / |R| (unlabelled pixels are not recalled).\n\n"
      "Matched rooms count under- and over-segmentation alike: over the map's free pixels (regions of\n"
      "<= 100 free px ignored), a segment and a room match when their IoU exceeds 0.5 (one-to-one);\n"
      "F1 = TP / (TP + (FP + FN) / 2), PQ = sum of the matches' IoU / (TP + (FP + FN) / 2), with FP the\n"
      "unmatched segments and FN the unmatched rooms; segments per room = segments / rooms (pooled over\n"
      "maps in the summary). 'P inside' is the precision with every segment clipped to the ground\n"
      "truth's rooms, 'far' the share of labelled pixels more than 0.5 m from every room: for maps\n"
      "registered onto another map's ground truth, whose free cells the annotators did not all cover.\n\n"
      "Prints a per-image table (rooms found and ground-truth rooms, both counting regions > 100 px;\n"
      "recall; precision; F1; PQ; segments per room; P inside; far; milliseconds for loading and\n"
      "segmenting the image) and a summary per variant with mean ± std over maps. --csv writes\n"
      "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,\n"
      "segments_per_room,precision_inside,far_share,status (fractions; a failed or missing image\n"
      "leaves its fields empty). Progress goes to stderr. Exits with 1 if any image failed (listed as\n"
      "FAILED in the table).\n\n"
      "--labels DIR scores segmentations made by any tool instead (see --labels below): images that\n"
      "DIR lacks are listed as missing, and the summary says over how many maps its means run.\n\n"
      "--mode incremental explores every image instead (topocut explore) and scores the final\n"
      "explored map, incremental and batch; it adds per-update times (process CPU time: median, p95,\n"
      "max) and the CSV columns updates,update_median_ms,update_p95_ms,update_max_ms,\n"
      "batch_update_median_ms (the last with --compare-batch).\n\n"
      "--report DIR writes the same tables as a web page with pictures of every image (see --report below).\n\n"
      "--maps DIR judges maps without ground truth by their defects (see --maps below); its CSV is\n"
      "map,width,height,rooms,thin,specks,open,time_ms,floor_ms. A folder without furnished (or plain)\n"
      "images is evaluated with the variants it has unless --variant is given.",
      described, po::positional_options_description(), args);
  if (!vm) return 0;
  DatasetArguments arguments = to_arguments(*vm);
  read_choice_rows(*vm, mode_rows(), request);
  read_text_rows(*vm, folder_rows(), request);
  read_option_rows(*vm, map_folder_option_rows(), request.folder);
  const std::string& mode = request.mode;
  ExplorationRunOptions comparison;
  read_option_rows(*vm, batch_comparison_rows<ExplorationRunOptions>(), comparison);
  const std::string& report = request.report;
  // Checked early, before the dataset is read; with --report the CSV may lie in the report's folder,
  // which is made below and checked with it there.
  if (!arguments.csv.empty() && report.empty()) check_outputs({arguments.csv}, {});
  if (!report.empty() && (mode != "batch" || !request.maps.empty()))
    throw UsageError("--report draws images scored against a ground truth in batch mode (not --mode incremental or --maps)");
  if (!request.maps.empty()) {
    if (mode != "batch") throw UsageError("--maps takes no --mode (maps without ground truth are segmented in batch)");
    if (!request.labels.empty()) throw UsageError("--labels needs a dataset with ground truth, not --maps");
    return run_defects(arguments, request.maps, request.folder);
  }

  if (!vm->count(kDatasetOptionName)) throw UsageError(kNoDataset);
  const std::string& labels = request.labels;
  if (!labels.empty() && mode != "batch") throw UsageError("--labels takes no --mode (the label images are read, not computed)");
  const std::vector<DatasetMap> maps = select_maps(discover_dataset(arguments.dataset), arguments.run.maps);
  if (!arguments.variant_given) {
    arguments.run.variants = labels.empty() ? present_variants(maps) : labelled_variants(maps, labels);
    if (arguments.run.variants.empty()) throw Error("the dataset folder has no map image (neither X.png nor X_furnitures.png)");
  }
  std::optional<HtmlReport> html;
  if (!arguments.csv.empty() || !report.empty()) {
    std::vector<std::string> inputs = dataset_files(maps);
    if (!labels.empty()) {
      const std::vector<std::string> read = label_files(maps, labels);
      inputs.insert(inputs.end(), read.begin(), read.end());
    }
    std::vector<std::string> outputs;
    if (!arguments.csv.empty()) outputs.push_back(arguments.csv);
    if (!report.empty()) {
      prepare_report_folder(report);
      const std::vector<std::string> files = HtmlReport::files(report, maps, arguments.run.variants);
      outputs.insert(outputs.end(), files.begin(), files.end());
      html.emplace(report, arguments.run.evaluation);
      arguments.run.scored = [&html](const ImageResult& result, const cv::Mat& segments, const cv::Mat& rooms,
                                     const OccupancyGrid& grid) { html->add(result, segments, rooms, grid); };
    }
    check_outputs(outputs, inputs);
  }
  arguments.run.progress = [](const std::string& line) { progress(line); };
  if (mode == "incremental") return run_incremental(arguments, maps, comparison);
  const std::vector<ImageResult> results = run_dataset(
      maps, arguments.run, labels.empty() ? batch_segmenter(arguments.run) : labels_segmenter(labels, arguments.run));

  const std::string method = labels.empty() ? method_name(arguments.run.segment) : "labels in " + labels;
  std::cout << "Dataset " << terminal_text(arguments.dataset) << ", " << maps.size() << " maps, method: " << terminal_text(method) << "\n\n"
            << format_results_table(results) << "\n"
            << format_summary(results, method) << std::flush;
  if (!arguments.csv.empty()) write_file_atomically(arguments.csv, results_csv(results));
  if (html) {
    html->finish(results, "topocut evaluate: " + arguments.dataset, method);
    std::cout << "wrote report: " << terminal_text((std::filesystem::path(report) / "index.html").string()) << "\n";
  }

  std::size_t failed = 0, missing = 0;
  for (const ImageResult& result : results) {
    failed += result.ok || result.missing ? 0 : 1;
    missing += result.missing ? 1 : 0;
  }
  if (missing == results.size()) {
    std::cerr << "topocut evaluate: error: " << labels << " holds no label image of the selected maps and variants\n";
    return 1;
  }
  return failure_exit_code(failed, results.size(), "images");
}

const bool registered = register_command({"evaluate", "score segmentations of a dataset against its ground truth", &run});

}  // namespace
}  // namespace topocut::cli
