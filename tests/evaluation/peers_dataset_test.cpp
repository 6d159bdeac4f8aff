// Matched rooms on the peers' published segmentations (read from TOPOCUT_SHARED_DIR, never copied
// into the project) against the figures datasets/README.md gives for them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "topocut/evaluation/dataset.h"
#include "topocut/evaluation/dataset_report.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;

const std::string kDatasets = std::string(TOPOCUT_SHARED_DIR "/datasets");

// The peer's labels scored against one annotator's sketches, as `topocut evaluate --labels` does.
VariantSummary score_peer(const std::string& peer, const std::string& annotator) {
  const std::vector<DatasetMap> maps = discover_dataset(kDatasets + "/sketches/" + annotator);
  DatasetRunOptions options;
  options.variants = {Variant::kPlain};
  const std::string labels = kDatasets + "/peers/sketches/" + peer;
  return summarize(run_dataset(maps, options, labels_segmenter(labels, options)), Variant::kPlain);
}

double rounded(double fraction, double unit) { return std::round(fraction / unit) * unit; }

TEST(PeersDataset, MatchedRoomsOfThePeersOnTheSketchesAreThePublishedAnchors) {
  if (!fs::is_directory(kDatasets + "/peers/sketches")) GTEST_SKIP() << "peers not found under " << kDatasets;
  const VariantSummary maoris_lex = score_peer("maoris", "lex");
  EXPECT_EQ(maoris_lex.succeeded(), 13);
  EXPECT_DOUBLE_EQ(rounded(100.0 * maoris_lex.f1_mean, 0.1), rounded(83.1, 0.1));
  EXPECT_DOUBLE_EQ(rounded(maoris_lex.segments_per_room, 0.01), rounded(0.78, 0.01));
  const VariantSummary voronoi_ezvin = score_peer("voronoi", "ezvin");
  EXPECT_EQ(voronoi_ezvin.succeeded(), 12);  // no result was published for sketch 20
  EXPECT_EQ(voronoi_ezvin.missing, 1);
  EXPECT_DOUBLE_EQ(rounded(100.0 * voronoi_ezvin.f1_mean, 0.1), rounded(44.9, 0.1));
}

}  // namespace
}  // namespace topocut
