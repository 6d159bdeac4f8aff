// `topocut evaluate` as a user runs it: the built binary, its exit codes, stdout, stderr and CSV.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/imgproc.hpp>

#include "cli/cli_runner.h"
#include "io/test_images.h"

namespace {

namespace fs = std::filesystem;

using topocut::testing::CliResult;
using topocut::testing::file_text;
using topocut::testing::memory_limit;
using topocut::testing::run_cli_line;

class EvaluateCli : public ::testing::Test {
 protected:

  // Runs `topocut evaluate <args>` (args already shell-quoted as needed).
  CliResult evaluate(const std::string& args) const { return run_cli_line(dir_, "evaluate " + args); }

  // A two-map dataset: "closed" has two rooms behind a full wall, "open" has the same rooms joined
  // by a door that the ground truth closes. Furnished = plain but for a 20 px table in room A.
  fs::path make_dataset() const {
    const fs::path data = dir_ / "data";
    fs::create_directories(data);
    cv::Mat closed(60, 120, CV_8UC1, cv::Scalar(0));
    closed(cv::Rect(4, 4, 60, 40)).setTo(255);   // room A, 2400 px (6 m² at 0.05 m/px)
    closed(cv::Rect(70, 4, 40, 40)).setTo(255);  // room B, 1600 px
    cv::Mat open = closed.clone();
    open(cv::Rect(64, 20, 6, 8)).setTo(255);     // door, 48 px
    const auto furnish = [](cv::Mat image) {
      image(cv::Rect(10, 10, 10, 8)).setTo(0);  // table, 80 px
      return image;
    };
    for (const auto& [name, map] : {std::pair<std::string, cv::Mat>{"closed", closed}, {"open", open}}) {
      EXPECT_TRUE(topocut::testing::write_test_image((data / (name + ".png")).string(), map));
      EXPECT_TRUE(topocut::testing::write_test_image((data / (name + "_furnitures.png")).string(), furnish(map.clone())));
      EXPECT_TRUE(topocut::testing::write_test_image((data / (name + "_gt_segmentation.png")).string(), closed));
    }
    return data;
  }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

// The comma-separated fields of a CSV line without quoted fields.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  for (const char c : line) {
    if (c == ',') fields.emplace_back();
    else fields.back() += c;
  }
  return fields;
}

// fields[begin, end) joined by commas.
std::string join(const std::vector<std::string>& fields, std::size_t begin, std::size_t end) {
  std::string text;
  for (std::size_t i = begin; i < end; ++i) text += (i > begin ? "," : "") + fields[i];
  return text;
}

std::size_t count_lines(const std::string& text) {
  std::size_t lines = 0;
  for (const char c : text) lines += c == '\n';
  return lines;
}

TEST_F(EvaluateCli, HelpListsEveryOption) {
  const CliResult run = evaluate("--help");
  EXPECT_EQ(run.code, 0);
  EXPECT_NE(run.out.find("Usage: topocut evaluate"), std::string::npos) << run.out;
  for (const char* option : {"--dataset", "--variant", "--csv", "--concavity", "--trivial", "--map", "--labels", "--maps"}) {
    EXPECT_NE(run.out.find(option), std::string::npos) << option;
  }
  EXPECT_TRUE(run.err.empty()) << run.err;
}

TEST_F(EvaluateCli, MissingDatasetFolderIsOneClearError) {
  const CliResult run = evaluate("--dataset '" + (dir_ / "nowhere").string() + "'");
  EXPECT_NE(run.code, 0);
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("does not exist"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

TEST_F(EvaluateCli, DatasetFolderWithoutMapsIsOneClearError) {
  std::ofstream(dir_ / "readme.txt") << "no maps here\n";
  const CliResult run = evaluate("--dataset '" + dir_.string() + "'");
  EXPECT_NE(run.code, 0);
  EXPECT_EQ(count_lines(run.err), 1u) << run.err;
  EXPECT_NE(run.err.find("holds no map"), std::string::npos) << run.err;
}

TEST_F(EvaluateCli, UnknownVariantIsAUsageError) {
  const CliResult run = evaluate("--dataset '" + make_dataset().string() + "' --variant sofa");
  EXPECT_EQ(run.code, 2);
  EXPECT_NE(run.err.find("variant 'sofa'"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

TEST_F(EvaluateCli, BadConcavityAndUnknownMapAreErrors) {
  const std::string data = make_dataset().string();
  const CliResult concavity = evaluate("--dataset '" + data + "' --concavity -3");
  EXPECT_EQ(concavity.code, 2);
  EXPECT_NE(concavity.err.find("--concavity"), std::string::npos) << concavity.err;
  const CliResult map = evaluate("--dataset '" + data + "' --map kitchen");
  EXPECT_NE(map.code, 0);
  EXPECT_NE(map.err.find("no map 'kitchen'"), std::string::npos) << map.err;
}

TEST_F(EvaluateCli, UnwritableCsvIsRefusedBeforeAnyWork) {
  const CliResult run = evaluate("--dataset '" + make_dataset().string() + "' --trivial --csv '" +
                           (dir_ / "no_such_folder" / "out.csv").string() + "'");
  EXPECT_NE(run.code, 0);
  EXPECT_EQ(run.err.find("[1/"), std::string::npos) << "work started: " << run.err;
}

TEST_F(EvaluateCli, TrivialBaselineOnASyntheticDatasetWritesTableSummaryAndCsv) {
  const fs::path csv = dir_ / "results.csv";
  const CliResult run = evaluate("--dataset '" + make_dataset().string() + "' --trivial --csv '" + csv.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("trivial"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("| closed"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("[4/4]"), std::string::npos) << run.err;

  // Hand-computed: closed plain is perfect; the table in room A leaves 2320 of 2400 px, so closed
  // furnished has recall (2320 / 2400 + 1) / 2; open is one segment A + door + B = 4048 px (3968
  // furnished) whose best room is A.
  EXPECT_EQ(file_text(csv).substr(0, file_text(csv).find('\n')),
            "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,"
            "segments_per_room,precision_inside,far_share,status");
  std::istringstream lines(file_text(csv));
  std::string line;
  std::getline(lines, line);
  std::vector<std::string> rows, matched;
  while (std::getline(lines, line)) {
    const std::vector<std::string> fields = csv_fields(line);
    ASSERT_EQ(fields.size(), 16u) << line;
    rows.push_back(join(fields, 0, 6));       // up to precision
    matched.push_back(join(fields, 7, 16));   // after time_ms
  }
  ASSERT_EQ(rows.size(), 4u);
  // Matched rooms: closed is perfect; open's one segment matches A (IoU 2400 / 4048 > 0.5), so TP 1,
  // FP 0, FN 1. Inside annotated space it keeps A and B (4000 px), so its precision there is 2400 / 4000.
  EXPECT_EQ(matched[0], "2,2,2,1.000000,1.000000,1.000000,1.000000,0.000000,ok");
  char text[160];
  std::snprintf(text, sizeof text, "1,1,2,%.6f,%.6f,0.500000,%.6f,0.000000,ok", 1.0 / 1.5, 2400.0 / 4048.0 / 1.5,
                2400.0 / 4000.0);
  EXPECT_EQ(matched[2], text);
  EXPECT_EQ(rows[0], "closed,plain,2,2,1.000000,1.000000");
  char expected[128];
  std::snprintf(expected, sizeof expected, "closed,furnished,2,2,%.6f,1.000000", (2320.0 / 2400.0 + 1.0) / 2.0);
  EXPECT_EQ(rows[1], expected);
  std::snprintf(expected, sizeof expected, "open,plain,1,2,1.000000,%.6f", 2400.0 / 4048.0);
  EXPECT_EQ(rows[2], expected);
  std::snprintf(expected, sizeof expected, "open,furnished,1,2,%.6f,%.6f", (2320.0 / 2400.0 + 1.0) / 2.0,
                2320.0 / 3968.0);
  EXPECT_EQ(rows[3], expected);
}

TEST_F(EvaluateCli, VariantAndMapSelectionRestrictTheRun) {
  const fs::path csv = dir_ / "results.csv";
  const CliResult run = evaluate("--dataset '" + make_dataset().string() +
                           "' --trivial --variant furnished --map open --csv '" + csv.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  const std::string text = file_text(csv);
  EXPECT_EQ(count_lines(text), 2u) << text;
  EXPECT_NE(text.find("open,furnished,"), std::string::npos) << text;
}

TEST_F(EvaluateCli, AFailingImageIsAFailureRowAndANonZeroExit) {
  const fs::path data = make_dataset();
  fs::remove(data / "open_furnitures.png");
  const fs::path csv = dir_ / "results.csv";
  const CliResult run = evaluate("--dataset '" + data.string() + "' --trivial --csv '" + csv.string() + "'");
  EXPECT_EQ(run.code, 1);
  EXPECT_NE(run.out.find("FAILED"), std::string::npos) << run.out;
  EXPECT_NE(run.err.find("1 of 4 images failed"), std::string::npos) << run.err;
  EXPECT_NE(file_text(csv).find("open,furnished,,,,,"), std::string::npos) << file_text(csv);
}

}  // namespace

namespace {

TEST_F(EvaluateCli, AFolderWithoutFurnishedImagesJustWorks) {
  const fs::path data = make_dataset();
  for (const char* name : {"closed", "open"}) fs::remove(data / (std::string(name) + "_furnitures.png"));
  const CliResult run = evaluate("--dataset '" + data.string() + "' --csv '" + (dir_ / "r.csv").string() + "'");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(run.out.find("FAILED"), std::string::npos) << run.out;
  EXPECT_EQ(count_lines(file_text(dir_ / "r.csv")), 3u);  // header + two plain images
  // Asked for explicitly, the missing variant still fails (the user asked for it).
  EXPECT_NE(evaluate("--dataset '" + data.string() + "' --variant furnished").code, 0);
}

TEST_F(EvaluateCli, MapsWithoutGroundTruthGiveTheirDefects) {
  const fs::path maps = dir_ / "maps";
  fs::create_directories(maps);
  cv::Mat map(80, 120, CV_8UC1, cv::Scalar(205));  // map_server palette: 205 unknown
  cv::rectangle(map, cv::Rect(9, 9, 102, 62), cv::Scalar(0), cv::FILLED);
  map(cv::Rect(10, 10, 100, 60)).setTo(254);
  ASSERT_TRUE(topocut::testing::write_test_image((maps / "home.pgm").string(), map));
  ASSERT_TRUE(topocut::testing::write_test_image((maps / "lab.png").string(), map));
  std::ofstream(maps / "home.yaml") << "image: home.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
  const fs::path csv = dir_ / "d.csv";
  const CliResult run = evaluate("--maps '" + maps.string() + "' --floor-repetitions 1 --csv '" + csv.string() + "'");
  EXPECT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("home.yaml"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("lab.png"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("2 maps, 2 rooms: 0 thin, 0 specks, 0 open"), std::string::npos) << run.out;
  const std::string table = file_text(csv);
  EXPECT_EQ(table.substr(0, table.find('\n')), "map,width,height,rooms,thin,specks,open,time_ms,floor_ms");
  EXPECT_EQ(count_lines(table), 3u);
  const CliResult missing = evaluate("--maps '" + (dir_ / "nowhere").string() + "'");
  EXPECT_NE(missing.code, 0);
  EXPECT_EQ(count_lines(missing.err), 1u) << missing.err;
}

// Another tool's rooms of the synthetic dataset: closed.png a grey label image (A = 5, B = 9, A also
// painted over the wall around it), open.png one colour over A, the door and B, closed_furnitures.png
// 16-bit (A = 700, B = 800), none for open_furnitures.png.
fs::path make_labels(const fs::path& dir) {
  const fs::path labels = dir / "labels";
  fs::create_directories(labels);
  cv::Mat grey(60, 120, CV_8UC1, cv::Scalar(0));
  grey(cv::Rect(2, 2, 64, 44)).setTo(5);
  grey(cv::Rect(70, 4, 40, 40)).setTo(9);
  EXPECT_TRUE(topocut::testing::write_test_image((labels / "closed.png").string(), grey));
  cv::Mat colour(60, 120, CV_8UC3, cv::Scalar(0, 0, 0));
  colour(cv::Rect(4, 4, 106, 40)).setTo(cv::Scalar(30, 200, 10));
  EXPECT_TRUE(topocut::testing::write_test_image((labels / "open.png").string(), colour));
  cv::Mat wide(60, 120, CV_16UC1, cv::Scalar(0));
  wide(cv::Rect(4, 4, 60, 40)).setTo(700);
  wide(cv::Rect(70, 4, 40, 40)).setTo(800);
  EXPECT_TRUE(topocut::testing::write_test_image((labels / "closed_furnitures.png").string(), wide));
  return labels;
}

TEST_F(EvaluateCli, LabelImagesOfAnotherToolAreScoredAndMissingOnesListed) {
  const fs::path data = make_dataset();
  const fs::path labels = make_labels(dir_);
  const fs::path csv = dir_ / "peer.csv";
  const CliResult run = evaluate("--dataset '" + data.string() + "' --labels '" + labels.string() + "' --csv '" +
                                 csv.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("The furnished figures are over 1 of 2 images (1 missing)."), std::string::npos) << run.out;
  std::istringstream lines(file_text(csv));
  std::string line;
  std::getline(lines, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(lines, line)) rows.push_back(csv_fields(line));
  ASSERT_EQ(rows.size(), 4u);
  // closed plain: the paint over the wall is not free, so A and B are exact.
  EXPECT_EQ(join(rows[0], 0, 6), "closed,plain,2,2,1.000000,1.000000");
  EXPECT_EQ(join(rows[0], 7, 16), "2,2,2,1.000000,1.000000,1.000000,1.000000,0.000000,ok");
  // closed furnished (16-bit): the table is not free in the furnished map: recall loses it, F1 does not.
  char text[160];
  std::snprintf(text, sizeof text, "closed,furnished,2,2,%.6f,1.000000", (2320.0 / 2400.0 + 1.0) / 2.0);
  EXPECT_EQ(join(rows[1], 0, 6), text);
  EXPECT_EQ(rows[1][10], "1.000000");
  // open plain (colour): one region over A, the door and B, as the trivial segmenter's.
  std::snprintf(text, sizeof text, "open,plain,1,2,1.000000,%.6f", 2400.0 / 4048.0);
  EXPECT_EQ(join(rows[2], 0, 6), text);
  std::snprintf(text, sizeof text, "%.6f", 1.0 / 1.5);
  EXPECT_EQ(rows[2][10], text);
  EXPECT_EQ(join(rows[3], 0, 3) + "|" + rows[3][15], "open,furnished,|missing");
}

TEST_F(EvaluateCli, BadLabelImagesAndFoldersAreOneErrorLine) {
  const fs::path data = make_dataset();
  const fs::path labels = make_labels(dir_);
  std::ofstream(labels / "open.png", std::ios::trunc) << "not a PNG";
  const CliResult bad_image = evaluate("--dataset '" + data.string() + "' --labels '" + labels.string() + "'");
  EXPECT_EQ(bad_image.code, 1);
  EXPECT_NE(bad_image.out.find("FAILED"), std::string::npos) << bad_image.out;
  EXPECT_NE(bad_image.err.find("1 of 4 images failed"), std::string::npos) << bad_image.err;

  const CliResult no_folder = evaluate("--dataset '" + data.string() + "' --labels '" + (dir_ / "none").string() + "'");
  EXPECT_EQ(no_folder.code, 1);
  EXPECT_EQ(count_lines(no_folder.err), 1u) << no_folder.err;
  EXPECT_NE(no_folder.err.find("does not exist"), std::string::npos) << no_folder.err;
  EXPECT_TRUE(no_folder.out.empty()) << no_folder.out;

  fs::create_directories(dir_ / "empty");
  const CliResult empty = evaluate("--dataset '" + data.string() + "' --labels '" + (dir_ / "empty").string() + "'");
  EXPECT_EQ(empty.code, 1);
  EXPECT_EQ(count_lines(empty.err), 1u) << empty.err;

  const CliResult nothing_asked = evaluate("--dataset '" + data.string() + "' --labels '" + labels.string() +
                                           "' --variant furnished --map open");
  EXPECT_EQ(nothing_asked.code, 1);
  EXPECT_NE(nothing_asked.err.find("holds no label image"), std::string::npos) << nothing_asked.err;

  EXPECT_EQ(evaluate("--maps '" + data.string() + "' --labels '" + labels.string() + "'").code, 2);
  EXPECT_EQ(evaluate("--dataset '" + data.string() + "' --labels '" + labels.string() + "' --mode incremental").code, 2);
}

}  // namespace

namespace {

int pixels_of(const cv::Mat& picture, const cv::Vec3b& colour) {
  int n = 0;
  for (int r = 0; r < picture.rows; ++r)
    for (int c = 0; c < picture.cols; ++c) n += picture.at<cv::Vec3b>(r, c) == colour;
  return n;
}

const cv::Vec3b kMissedRed(40, 40, 220), kMergedOrange(0, 140, 255);  // BGR, as comparison_pictures draws them

// The trivial segmenter on the synthetic dataset: on "closed" its two segments match the two rooms;
// on "open" its one segment (A, the door and B) matches A (IoU 2400 / 4048), misses B and merges both.
TEST_F(EvaluateCli, ReportDrawsEveryImageAndMarksMissesAndMerges) {
  const fs::path data = make_dataset();
  const fs::path report = dir_ / "report";  // made by the command
  const CliResult run = evaluate("--dataset '" + data.string() + "' --trivial --variant plain --report '" + report.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("wrote report: " + (report / "index.html").string()), std::string::npos) << run.out;
  const std::string page = file_text((report / "index.html").string());
  for (const char* text : {"<!DOCTYPE html>", "F1 / PQ %", "segments per room", "<th>PQ %</th>", "closed (plain)", "open (plain)",
                           "src=\"open_plain_truth.png\"", "src=\"open_plain_rooms.png\"", "src=\"closed_plain_truth.png\"",
                           "2 rooms, 1 matched, 1 missed; segmentation: 1 segments, 1 merging rooms",
                           "2 rooms, 2 matched, 0 missed; segmentation: 2 segments, 0 merging rooms"})
    EXPECT_NE(page.find(text), std::string::npos) << text;
  EXPECT_FALSE(fs::exists(report / "open_furnished_truth.png"));  // only the variant that was run
  using topocut::testing::Pixels;
  const cv::Mat open_truth = topocut::testing::read_test_image((report / "open_plain_truth.png").string(), Pixels::kColour);
  const cv::Mat open_rooms = topocut::testing::read_test_image((report / "open_plain_rooms.png").string(), Pixels::kColour);
  const cv::Mat closed_truth = topocut::testing::read_test_image((report / "closed_plain_truth.png").string(), Pixels::kColour);
  const cv::Mat closed_rooms = topocut::testing::read_test_image((report / "closed_plain_rooms.png").string(), Pixels::kColour);
  ASSERT_EQ(open_truth.size(), cv::Size(480, 240));  // 120 x 60 px scaled 4 x
  EXPECT_EQ(open_rooms.size(), open_truth.size());
  // Room B (columns 70..109) is missed: red only there; the merging segment is orange.
  EXPECT_GT(pixels_of(open_truth(cv::Rect(4 * 70, 0, 4 * 40, 240)), kMissedRed), 1000);
  EXPECT_EQ(pixels_of(open_truth(cv::Rect(0, 0, 4 * 64, 240)), kMissedRed), 0);
  EXPECT_GT(pixels_of(open_rooms, kMergedOrange), 1000);
  EXPECT_EQ(pixels_of(closed_truth, kMissedRed) + pixels_of(closed_rooms, kMergedOrange), 0);
  // A matched pair has one colour: room A in the truth, the segment over it (between its stripes).
  const cv::Point in_a(4 * 30 + 2, 4 * 24);  // (x + y) % 10 == 8: between the stripes
  EXPECT_EQ(open_truth.at<cv::Vec3b>(in_a), open_rooms.at<cv::Vec3b>(in_a));
  EXPECT_EQ(closed_truth.at<cv::Vec3b>(in_a), closed_rooms.at<cv::Vec3b>(in_a));
  EXPECT_NE(closed_truth.at<cv::Vec3b>(in_a), closed_truth.at<cv::Vec3b>(cv::Point(4 * 90 + 2, 4 * 24)));
}

TEST_F(EvaluateCli, ReportIsRefusedWhereItCannotBeDrawn) {
  const fs::path data = make_dataset();
  std::ofstream(dir_ / "file") << "x";
  const CliResult on_file = evaluate("--dataset '" + data.string() + "' --report '" + (dir_ / "file").string() + "'");
  EXPECT_EQ(on_file.code, 1);
  EXPECT_NE(on_file.err.find("is a file, not a folder"), std::string::npos) << on_file.err;
  const CliResult maps = evaluate("--maps '" + data.string() + "' --report '" + (dir_ / "r").string() + "'");
  EXPECT_EQ(maps.code, 2);
  EXPECT_NE(maps.err.find("--report"), std::string::npos) << maps.err;
  // The report never overwrites an input: in the dataset's own folder, a map named closed_plain_truth
  // has the image the picture of map closed would replace.
  fs::copy_file(data / "closed.png", data / "closed_plain_truth.png");
  fs::copy_file(data / "closed_gt_segmentation.png", data / "closed_plain_truth_gt_segmentation.png");
  const std::string before = file_text((data / "closed_plain_truth.png").string());
  const CliResult over_input = evaluate("--dataset '" + data.string() + "' --variant plain --report '" + data.string() + "'");
  EXPECT_EQ(over_input.code, 1);
  EXPECT_NE(over_input.err.find("_truth.png' is both an input and an output"), std::string::npos) << over_input.err;
  EXPECT_EQ(file_text((data / "closed_plain_truth.png").string()), before);
  EXPECT_FALSE(fs::exists(data / "index.html"));
}

// The page as a browser shows it: headless Chromium loads the report inside a page of the test's
// own (an iframe, file access allowed) and counts the pictures that decoded. Skipped without
// Chromium (Debian's chromium; bash .ci/setup.sh test installs it).
std::string chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string line = std::string("command -v ") + name + " 2>/dev/null";
    FILE* pipe = popen(line.c_str(), "r");
    char path[512] = {0};
    const bool found = pipe && fgets(path, sizeof path, pipe) != nullptr;
    if (pipe) pclose(pipe);
    if (found) return std::string(path, strcspn(path, "\n"));
  }
  return "";
}

// "loaded N of M": the report's images that Chromium decoded (complete, non-zero width).
std::string images_loaded_in_chromium(const std::string& browser, const fs::path& page, const fs::path& work) {
  const fs::path probe = work / "probe.html";
  std::ofstream(probe) << "<!DOCTYPE html><html><body><iframe id=\"r\" src=\"file://" << page.string() << "\"></iframe><script>\n"
                       << "document.getElementById('r').addEventListener('load', () => {\n"
                       << "  const images = [...document.getElementById('r').contentDocument.images];\n"
                       << "  const loaded = images.filter(i => i.complete && i.naturalWidth > 0).length;\n"
                       << "  const p = document.createElement('p');\n"
                       << "  p.id = 'result';\n"
                       << "  p.textContent = `loaded ${loaded} of ${images.length}`;\n"
                       << "  document.body.appendChild(p);\n"
                       << "});\n</script></body></html>\n";
  const std::string line = "timeout -s KILL 60 " + topocut::testing::shell_quoted(browser) +
                           " --headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=10000"
                           " --user-data-dir=" + topocut::testing::shell_quoted((work / "profile").string()) +
                           " --dump-dom " + topocut::testing::shell_quoted("file://" + probe.string()) + " 2>/dev/null";
  FILE* pipe = popen(line.c_str(), "r");
  std::string dom;
  char buffer[4096];
  while (pipe && fgets(buffer, sizeof buffer, pipe)) dom += buffer;
  if (pipe) pclose(pipe);
  const std::string marker = "<p id=\"result\">";
  const std::size_t at = dom.find(marker);
  if (at == std::string::npos) return "no result: " + dom.substr(0, 300);
  return dom.substr(at + marker.size(), dom.find('<', at + marker.size()) - at - marker.size());
}

TEST_F(EvaluateCli, ReportPageLoadsEveryImageInChromium) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium): the report page is not opened";
  const fs::path data = make_dataset();
  const fs::path report = dir_ / "report";
  const CliResult run = evaluate("--dataset '" + data.string() + "' --report '" + report.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(images_loaded_in_chromium(browser, report / "index.html", dir_), "loaded 8 of 8");  // 2 maps x 2 variants x 2
  // The check sees a broken picture.
  fs::remove(report / "open_furnished_rooms.png");
  EXPECT_EQ(images_loaded_in_chromium(browser, report / "index.html", dir_), "loaded 7 of 8");
}

}  // namespace

namespace {

// The bytes of a PNG whose header now declares width x height (the CRC no longer matches, which does
// not matter: the size must be refused before any decoder reads on).
std::string png_declaring(const fs::path& path, std::uint32_t width, std::uint32_t height) {
  std::string bytes = file_text(path.string());
  for (int i = 0; i < 4; ++i) {
    bytes[16 + i] = static_cast<char>(width >> (24 - 8 * i));
    bytes[20 + i] = static_cast<char>(height >> (24 - 8 * i));
  }
  return bytes;
}

TEST_F(EvaluateCli, ALabelImageOfTheWrongSizeIsRefusedByItsHeader) {
  // 10000 x 10000 declared (100 megapixels, within the pixel limit) for a 120 x 60 map: it took 7.5 s
  // and 2.3 GB to decode before "wrong size"; its header is enough.
  const fs::path data = make_dataset();
  const fs::path labels = make_labels(dir_);
  std::ofstream(labels / "open.png", std::ios::binary | std::ios::trunc) << png_declaring(labels / "closed.png", 10000, 10000);
  const CliResult run = run_cli_line(dir_, "evaluate --dataset '" + data.string() + "' --labels '" + labels.string() +
                                               "' --variant plain", 5, memory_limit(1000000));
  EXPECT_EQ(run.code, 1) << run.err;
  EXPECT_NE(run.out.find("is 10000 x 10000 pixels but the map is 120 x 60"), std::string::npos) << run.out;
  // So is a ground truth that does not fit its map.
  std::ofstream(data / "closed_gt_segmentation.png", std::ios::binary | std::ios::trunc)
      << png_declaring(data / "open_gt_segmentation.png", 10000, 10000);
  const CliResult truth = run_cli_line(dir_, "evaluate --dataset '" + data.string() + "' --trivial --variant plain", 5,
                                       memory_limit(1000000));
  EXPECT_EQ(truth.code, 1) << truth.err;
  EXPECT_NE(truth.out.find("closed_gt_segmentation.png' is 10000 x 10000 pixels but the map is 120 x 60"), std::string::npos)
      << truth.out;
}

TEST_F(EvaluateCli, TheCsvMayLieInTheReportFolderTheRunMakes) {
  const fs::path data = make_dataset();
  const fs::path report = dir_ / "new_report";
  const CliResult run = evaluate("--dataset '" + data.string() + "' --trivial --variant plain --report '" + report.string() +
                                 "' --csv '" + (report / "results.csv").string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(fs::is_regular_file(report / "index.html"));
  EXPECT_EQ(count_lines(file_text((report / "results.csv").string())), 3u);  // header and two maps
}

TEST_F(EvaluateCli, MapNamesAreEscapedOnTheTerminalAndQuotedInTheCsv) {
  // A map's name is its file's: an escape sequence or a line break in it reaches no terminal, and a
  // name a spreadsheet would run as a formula is quoted as text.
  const fs::path data = make_dataset();
  for (const std::string name : {"=cmd|' -C calc'!A0", "red\x1b[31mroom\rX"}) {
    fs::copy_file(data / "closed.png", data / (name + ".png"));
    fs::copy_file(data / "closed_gt_segmentation.png", data / (name + "_gt_segmentation.png"));
  }
  const fs::path csv = dir_ / "r.csv";
  const CliResult run = evaluate("--dataset '" + data.string() + "' --trivial --variant plain --csv '" + csv.string() + "'");
  ASSERT_EQ(run.code, 0) << run.err;
  for (const std::string& text : {run.out, run.err}) {
    EXPECT_EQ(text.find('\x1b'), std::string::npos) << text;
    EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  }
  EXPECT_NE(run.out.find("red\\x1B[31mroom\\x0DX"), std::string::npos) << run.out;
  const std::string rows = file_text(csv.string());
  EXPECT_NE(rows.find("\n\"'=cmd|' -C calc'!A0\",plain,"), std::string::npos) << rows;
  EXPECT_EQ(rows.find("\n=cmd"), std::string::npos) << rows;
}

}  // namespace
