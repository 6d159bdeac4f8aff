#include "topocut/evaluation/dataset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <opencv2/imgproc.hpp>

#include "topocut/core/error.h"
#include "topocut/evaluation/dataset_report.h"
#include "io/test_images.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

// Room geometry of the synthetic maps (40 x 60 px images, obstacle everywhere else).
const cv::Rect kRoomA(2, 2, 25, 20);   // 500 px
const cv::Rect kDoor(27, 10, 3, 4);    // 12 px between A and B
const cv::Rect kRoomB(30, 2, 20, 20);  // 400 px
const cv::Rect kFurniture(5, 5, 5, 4); // 20 px inside A

cv::Mat blank() { return cv::Mat(40, 60, CV_8UC1, cv::Scalar(0)); }

// A stand-in for the trivial segmenter that needs nothing but OpenCV: free pixels (> 250) split
// into 8-connected components, each one room.
Segmentation components_segmenter(const std::string& path) {
  const cv::Mat image = fs::exists(path) ? topocut::testing::read_test_image(path, topocut::testing::Pixels::kGrey) : cv::Mat();
  if (image.empty()) throw Error("cannot read '" + path + "'");
  Segmentation segmentation;
  cv::connectedComponents(image > 250, segmentation.labels, 8, CV_32S);
  return segmentation;
}

// A Bormann-format folder with four maps whose scores are known by hand:
//   alpha: two closed rooms; plain is perfect, furnished has a 20 px table in A.
//   beta:  two rooms joined by a 12 px door that the ground truth closes with a separator;
//          furnished = plain.
//   delta: one room; its furnished image has the wrong size (fails).
//   gamma: one room; its plain image is missing (fails).
// plus files that are not maps (no ground truth): epsilon.png and notes.txt.
class SyntheticDataset : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("topocut_dataset_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);

    cv::Mat two_rooms = blank();
    two_rooms(kRoomA).setTo(255);
    two_rooms(kRoomB).setTo(255);
    write("alpha_gt_segmentation.png", two_rooms);
    write("alpha.png", two_rooms);
    cv::Mat furnished = two_rooms.clone();
    furnished(kFurniture).setTo(0);
    write("alpha_furnitures.png", furnished);

    write("beta_gt_segmentation.png", two_rooms);
    cv::Mat with_door = two_rooms.clone();
    with_door(kDoor).setTo(255);
    write("beta.png", with_door);
    write("beta_furnitures.png", with_door);

    cv::Mat one_room = blank();
    one_room(kRoomA).setTo(255);
    write("delta_gt_segmentation.png", one_room);
    write("delta.png", one_room);
    write("delta_furnitures.png", one_room(cv::Rect(0, 0, 50, 30)).clone());

    write("gamma_gt_segmentation.png", one_room);
    write("gamma_furnitures.png", one_room);

    write("epsilon.png", one_room);
    std::ofstream(dir_ / "notes.txt") << "not a map\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const cv::Mat& image) {
    ASSERT_TRUE(topocut::testing::write_test_image((dir_ / name).string(), image)) << name;
  }
  std::string folder() const { return dir_.string(); }

  fs::path dir_;
};

TEST_F(SyntheticDataset, DiscoversEveryMapWithAGroundTruth) {
  const std::vector<DatasetMap> maps = discover_dataset(folder());
  ASSERT_EQ(maps.size(), 4u);
  EXPECT_EQ(maps[0].name, "alpha");
  EXPECT_EQ(maps[1].name, "beta");
  EXPECT_EQ(maps[2].name, "delta");
  EXPECT_EQ(maps[3].name, "gamma");
  EXPECT_EQ(fs::path(maps[0].plain).filename(), "alpha.png");
  EXPECT_EQ(fs::path(maps[0].furnished).filename(), "alpha_furnitures.png");
  EXPECT_EQ(fs::path(maps[0].ground_truth).filename(), "alpha_gt_segmentation.png");
  EXPECT_EQ(maps[0].image(Variant::kFurnished), maps[0].furnished);
}

TEST_F(SyntheticDataset, SelectsMapsByNameAndRejectsUnknownNames) {
  const std::vector<DatasetMap> maps = discover_dataset(folder());
  const std::vector<DatasetMap> selected = select_maps(maps, {"gamma", "alpha"});
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(selected[0].name, "gamma");
  EXPECT_EQ(selected[1].name, "alpha");
  EXPECT_EQ(select_maps(maps, {}).size(), 4u);
  EXPECT_THROW(select_maps(maps, {"epsilon"}), Error);
}

TEST_F(SyntheticDataset, ScoresEveryImageAndReportsFailuresAsRows) {
  std::vector<std::string> progress;
  DatasetRunOptions options;
  options.progress = [&](const std::string& line) { progress.push_back(line); };
  const std::vector<ImageResult> results = run_dataset(discover_dataset(folder()), options, components_segmenter);

  ASSERT_EQ(results.size(), 8u);
  EXPECT_EQ(progress.size(), 8u);
  EXPECT_NE(progress.front().find("[1/8] alpha plain"), std::string::npos) << progress.front();

  const auto& alpha_plain = results[0];
  EXPECT_EQ(alpha_plain.map, "alpha");
  EXPECT_EQ(alpha_plain.variant, Variant::kPlain);
  ASSERT_TRUE(alpha_plain.ok) << alpha_plain.error;
  EXPECT_EQ(alpha_plain.rooms, 2);
  EXPECT_EQ(alpha_plain.gt_rooms, 2);
  EXPECT_DOUBLE_EQ(alpha_plain.recall, 1.0);
  EXPECT_DOUBLE_EQ(alpha_plain.precision, 1.0);
  EXPECT_GE(alpha_plain.time_ms, 0.0);

  const auto& alpha_furnished = results[1];
  ASSERT_TRUE(alpha_furnished.ok) << alpha_furnished.error;
  EXPECT_EQ(alpha_furnished.variant, Variant::kFurnished);
  EXPECT_DOUBLE_EQ(alpha_furnished.recall, (480.0 / 500.0 + 1.0) / 2.0);
  EXPECT_DOUBLE_EQ(alpha_furnished.precision, 1.0);

  EXPECT_EQ(alpha_plain.matched.matches, 2);
  EXPECT_DOUBLE_EQ(alpha_plain.matched.f1, 1.0);
  // The table is not free in the furnished map, so room A counts its 480 free pixels: a perfect match.
  EXPECT_EQ(alpha_furnished.matched.matches, 2);
  EXPECT_DOUBLE_EQ(alpha_furnished.matched.pq, 1.0);

  // One component: A + door + B = 912 px, best room A (500 px).
  for (int i : {2, 3}) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    EXPECT_EQ(results[i].rooms, 1);
    EXPECT_EQ(results[i].gt_rooms, 2);
    EXPECT_DOUBLE_EQ(results[i].precision, 500.0 / 912.0);
    EXPECT_DOUBLE_EQ(results[i].recall, 1.0);
    // It still matches A (IoU 500 / 912 > 0.5): TP 1, FP 0, FN 1 (room B).
    EXPECT_EQ(results[i].matched.matches, 1);
    EXPECT_DOUBLE_EQ(results[i].matched.f1, 1.0 / 1.5);
    EXPECT_DOUBLE_EQ(results[i].matched.pq, 500.0 / 912.0 / 1.5);
    EXPECT_DOUBLE_EQ(results[i].matched.segments_per_room, 0.5);
    EXPECT_DOUBLE_EQ(results[i].precision_inside, 500.0 / 900.0);  // the 12 door pixels are in no room
    EXPECT_DOUBLE_EQ(results[i].far_share, 0.0);
  }

  EXPECT_TRUE(results[4].ok) << results[4].error;
  EXPECT_FALSE(results[5].ok);  // delta furnished: wrong size
  EXPECT_NE(results[5].error.find("ground truth"), std::string::npos) << results[5].error;
  EXPECT_FALSE(results[6].ok);  // gamma plain: missing
  EXPECT_NE(results[6].error.find("gamma.png"), std::string::npos) << results[6].error;
  EXPECT_TRUE(results[7].ok) << results[7].error;
  EXPECT_NE(progress[6].find("FAILED"), std::string::npos);

  const VariantSummary plain = summarize(results, Variant::kPlain);
  EXPECT_EQ(plain.images, 4);
  EXPECT_EQ(plain.failed, 1);
  EXPECT_DOUBLE_EQ(plain.recall_mean, 1.0);
  EXPECT_DOUBLE_EQ(plain.recall_std, 0.0);
  const double beta_precision = 500.0 / 912.0;
  const double mean_precision = (2.0 + beta_precision) / 3.0;
  EXPECT_DOUBLE_EQ(plain.precision_mean, mean_precision);
  const double d1 = 1.0 - mean_precision, d2 = beta_precision - mean_precision;
  EXPECT_NEAR(plain.precision_std, std::sqrt((2 * d1 * d1 + d2 * d2) / 3.0), 1e-12);

  EXPECT_DOUBLE_EQ(plain.f1_mean, (2.0 + 1.0 / 1.5) / 3.0);
  EXPECT_DOUBLE_EQ(plain.segments_per_room, (2.0 + 1.0 + 1.0) / (2.0 + 2.0 + 1.0));  // pooled over the maps

  const VariantSummary furnished = summarize(results, Variant::kFurnished);
  EXPECT_EQ(furnished.failed, 1);
  EXPECT_DOUBLE_EQ(furnished.recall_mean, (0.98 + 1.0 + 1.0) / 3.0);
}

// Another tool's segmentations, as label images named after the maps:
//   alpha.png: 8-bit grey, A = 3 spilling two pixels over the walls around it, B = 7;
//   beta.png: colour, A red, B green, the door black; gamma_furnitures.png: 16-bit, A = 1000;
//   none for delta.
TEST_F(SyntheticDataset, ScoresLabelImagesOfAnotherToolAndReportsMissingOnes) {
  fs::create_directories(dir_ / "labels");
  cv::Mat grey = blank();
  grey(cv::Rect(kRoomA.x - 2, kRoomA.y - 2, kRoomA.width + 2, kRoomA.height + 4)).setTo(3);
  grey(kRoomB).setTo(7);
  write("labels/alpha.png", grey);
  cv::Mat colour(blank().size(), CV_8UC3, cv::Scalar(0, 0, 0));
  colour(kRoomA).setTo(cv::Scalar(0, 0, 255));
  colour(kRoomB).setTo(cv::Scalar(0, 255, 0));
  write("labels/beta.png", colour);
  cv::Mat wide(blank().size(), CV_16UC1, cv::Scalar(0));
  wide(kRoomA).setTo(1000);
  write("labels/gamma_furnitures.png", wide);
  const std::string labels = (dir_ / "labels").string();

  const std::vector<DatasetMap> maps = discover_dataset(folder());
  DatasetRunOptions options;
  options.variants = labelled_variants(maps, labels);
  ASSERT_EQ(options.variants, (std::vector<Variant>{Variant::kPlain, Variant::kFurnished}));
  const std::vector<ImageResult> results = run_dataset(maps, options, labels_segmenter(labels, options));
  ASSERT_EQ(results.size(), 8u);
  for (int i : {0, 2}) {  // alpha and beta plain: perfect once restricted to the free pixels
    ASSERT_TRUE(results[i].ok) << results[i].error;
    EXPECT_DOUBLE_EQ(results[i].recall, 1.0);
    EXPECT_DOUBLE_EQ(results[i].precision, 1.0);
    EXPECT_DOUBLE_EQ(results[i].matched.f1, 1.0);
  }
  for (int i : {1, 3, 4, 5, 6}) {  // no label image
    EXPECT_FALSE(results[i].ok);
    EXPECT_TRUE(results[i].missing) << results[i].error;
  }
  ASSERT_TRUE(results[7].ok) << results[7].error;  // gamma furnished
  EXPECT_DOUBLE_EQ(results[7].matched.f1, 1.0);

  const VariantSummary plain = summarize(results, Variant::kPlain);
  EXPECT_EQ(plain.missing, 2);
  EXPECT_EQ(plain.failed, 0);
  EXPECT_EQ(plain.succeeded(), 2);
  const std::string summary = format_summary(results, "peer");
  EXPECT_NE(summary.find("The plain figures are over 2 of 4 images (2 missing)."), std::string::npos) << summary;
  EXPECT_NE(format_results_table(results).find("missing"), std::string::npos);
  EXPECT_NE(results_csv(results).find("delta,plain,,,,,,,,,,,,,,missing\n"), std::string::npos) << results_csv(results);
}

TEST_F(SyntheticDataset, BadLabelImagesFailTheirMapAndBadFoldersAreAnError) {
  fs::create_directories(dir_ / "labels");
  write("labels/alpha.png", cv::Mat(10, 10, CV_8UC1, cv::Scalar(1)));  // the map is 60 x 40
  std::ofstream(dir_ / "labels" / "beta.png") << "not a PNG";
  const std::string labels = (dir_ / "labels").string();
  DatasetRunOptions options;
  options.variants = {Variant::kPlain};
  const std::vector<ImageResult> results =
      run_dataset(select_maps(discover_dataset(folder()), {"alpha", "beta"}), options, labels_segmenter(labels, options));
  ASSERT_EQ(results.size(), 2u);
  EXPECT_FALSE(results[0].ok);
  EXPECT_FALSE(results[0].missing);
  EXPECT_NE(results[0].error.find("is 10 x 10 pixels but the map is 60 x 40"), std::string::npos) << results[0].error;
  EXPECT_FALSE(results[1].ok);
  EXPECT_FALSE(results[1].missing);
  EXPECT_NE(results[1].error.find("beta.png"), std::string::npos) << results[1].error;

  EXPECT_THROW(labels_segmenter((dir_ / "no_such_folder").string(), options), Error);
  fs::create_directories(dir_ / "empty");
  EXPECT_THROW(labelled_variants(discover_dataset(folder()), (dir_ / "empty").string()), Error);
}

TEST_F(SyntheticDataset, RunsOnlyTheRequestedVariants) {
  DatasetRunOptions options;
  options.variants = {Variant::kFurnished};
  const std::vector<ImageResult> results =
      run_dataset(select_maps(discover_dataset(folder()), {"alpha"}), options, components_segmenter);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].variant, Variant::kFurnished);
}

TEST_F(SyntheticDataset, ABadGroundTruthFailsBothVariantsOfItsMap) {
  std::ofstream(dir_ / "zeta_gt_segmentation.png") << "garbage";
  const std::vector<ImageResult> results =
      run_dataset(select_maps(discover_dataset(folder()), {"zeta", "alpha"}), {}, components_segmenter);
  ASSERT_EQ(results.size(), 4u);
  EXPECT_FALSE(results[0].ok);
  EXPECT_FALSE(results[1].ok);
  EXPECT_NE(results[0].error.find("zeta_gt_segmentation.png"), std::string::npos) << results[0].error;
  EXPECT_TRUE(results[2].ok);
  EXPECT_TRUE(results[3].ok);
}

TEST_F(SyntheticDataset, ASegmenterThatThrowsAnythingGivesAFailureRow) {
  const auto throwing = [](const std::string&) -> Segmentation { throw std::runtime_error("boom"); };
  const std::vector<ImageResult> results =
      run_dataset(select_maps(discover_dataset(folder()), {"alpha"}), {}, throwing);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_FALSE(results[0].ok);
  EXPECT_EQ(results[0].error, "boom");
}

TEST(Dataset, BadFoldersAreOneClearError) {
  const fs::path missing = fs::temp_directory_path() / ("topocut_no_such_dataset_" + std::to_string(::getpid()));
  try {
    discover_dataset(missing.string());
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
  const fs::path empty = fs::temp_directory_path() / ("topocut_empty_dataset_" + std::to_string(::getpid()));
  fs::create_directories(empty);
  std::ofstream(empty / "map.png") << "x";
  try {
    discover_dataset(empty.string());
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("holds no map"), std::string::npos) << e.what();
  }
  EXPECT_THROW(discover_dataset((empty / "map.png").string()), Error);
  fs::remove_all(empty);
}

TEST(Dataset, VariantNamesRoundTrip) {
  EXPECT_EQ(parse_variant(to_string(Variant::kPlain)), Variant::kPlain);
  EXPECT_EQ(parse_variant(to_string(Variant::kFurnished)), Variant::kFurnished);
  EXPECT_THROW(parse_variant("furnitures"), Error);
}

ImageResult ok_result(const std::string& map, Variant variant, double recall, double precision, double ms) {
  ImageResult r;
  r.map = map;
  r.variant = variant;
  r.ok = true;
  r.rooms = 3;
  r.gt_rooms = 4;
  r.recall = recall;
  r.precision = precision;
  r.time_ms = ms;
  return r;
}

TEST(DatasetReport, CsvHasExactlyTheAgreedColumns) {
  ImageResult failed;
  failed.map = "b,c";
  failed.variant = Variant::kFurnished;
  failed.error = "broken";
  ImageResult ok = ok_result("a", Variant::kPlain, 0.5, 0.25, 12.5);
  ok.matched.matches = 2;
  ok.matched.segments = 3;
  ok.matched.rooms = 5;
  ok.matched.f1 = 0.5;
  ok.matched.pq = 0.375;
  ok.matched.segments_per_room = 0.6;
  ok.precision_inside = 0.75;
  ok.far_share = 0.125;
  const std::string csv = results_csv({ok, failed});
  EXPECT_EQ(csv,
            "map,variant,rooms,gt_rooms,recall,precision,time_ms,matches,free_segments,free_rooms,f1,pq,"
            "segments_per_room,precision_inside,far_share,status\n"
            "a,plain,3,4,0.500000,0.250000,12.500,2,3,5,0.500000,0.375000,0.600000,0.750000,0.125000,ok\n"
            "\"b,c\",furnished,,,,,,,,,,,,,,failed\n");
}

TEST(DatasetReport, SummaryShowsMeanAndStdInPercentAndCountsFailures) {
  ImageResult failed;
  failed.map = "c";
  failed.variant = Variant::kFurnished;
  failed.error = "broken";
  const std::vector<ImageResult> results{ok_result("a", Variant::kPlain, 0.9, 0.8, 10.0),
                                         ok_result("b", Variant::kPlain, 0.7, 1.0, 30.0),
                                         ok_result("a", Variant::kFurnished, 0.5, 0.5, 20.0), failed};
  const std::string summary = format_summary(results, "method X");
  EXPECT_NE(summary.find("method X"), std::string::npos) << summary;
  EXPECT_NE(summary.find("80.0 ± 10.0 / 90.0 ± 10.0"), std::string::npos) << summary;
  EXPECT_NE(summary.find("50.0 ± 0.0 / 50.0 ± 0.0"), std::string::npos) << summary;
  EXPECT_NE(summary.find("20.0 / 20.0 / 30.0"), std::string::npos) << summary;  // plain: 10 and 30 ms
  EXPECT_NE(summary.find("The furnished figures are over 1 of 2 images (1 failed)."), std::string::npos) << summary;

  const std::string table = format_results_table(results);
  EXPECT_NE(table.find("FAILED: broken"), std::string::npos) << table;
  EXPECT_NE(table.find("| a "), std::string::npos) << table;
  EXPECT_NE(table.find("90.0"), std::string::npos) << table;
}

TEST(DatasetReport, SummaryHasARowPerVariantThatWasRun) {
  ImageResult failed;
  failed.variant = Variant::kFurnished;
  const std::string summary = format_summary({ok_result("a", Variant::kPlain, 1.0, 1.0, 1.0), failed}, "m");
  EXPECT_NE(summary.find("| m      | plain "), std::string::npos) << summary;
  EXPECT_NE(summary.find("| m      | furnished | 0    | -"), std::string::npos) << summary;
  EXPECT_EQ(format_summary({ok_result("a", Variant::kPlain, 1.0, 1.0, 1.0)}, "m").find("furnished"), std::string::npos);
}

TEST(DatasetReport, MarkdownTablePadsColumnsByCharacters) {
  EXPECT_EQ(markdown_table({{"a", "bb"}, {"1 ± 2", "x"}}),
            "| a     | bb  |\n"
            "|-------|-----|\n"
            "| 1 ± 2 | x   |\n");
}

}  // namespace
}  // namespace topocut
