// No silent defaults on the command line: what a new user types first (a bare command, a typo, a
// map image without its YAML, a run that writes nothing) is answered with what to do.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"
#include "io/temp_dir.h"
#include "io/test_images.h"

namespace {

using topocut::testing::bundled;
using topocut::testing::CliResult;
using topocut::testing::run_cli;
using topocut::testing::TempDir;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::size_t lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

TEST(DefaultsCli, BareCommandsSayWhatToGive) {
  TempDir dir;
  for (const auto& [command, operand] : std::vector<std::pair<std::string, std::string>>{
           {"segment", "no MAP given: topocut segment MAP [options]"}, {"explore", "no MAP given"},
           {"lines", "no SCAN given"}, {"walls", "no LOG given"}}) {
    const CliResult r = run_cli(dir, command, {});
    EXPECT_EQ(r.code, 2) << command << ": " << r.err;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_TRUE(has(r.err, operand)) << r.err;
    EXPECT_FALSE(has(r.err, "is required")) << r.err;
  }
}

TEST(DefaultsCli, BareEvaluateExplainsTheDataset) {
  TempDir dir;
  const CliResult r = run_cli(dir, "evaluate", {});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_TRUE(has(r.err, "no dataset given: --dataset DIR")) << r.err;
  EXPECT_TRUE(has(r.err, "--dataset maps")) << r.err;
  EXPECT_FALSE(has(r.err, "shared")) << r.err;
}

TEST(DefaultsCli, TheBundledMapsAreADataset) {
  TempDir dir;
  const CliResult r = run_cli(dir, "evaluate", {"--dataset", std::string(TOPOCUT_SOURCE_DIR "/maps")});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* map : {"floorplan", "corridor_l", "furnished"}) EXPECT_TRUE(has(r.out, map)) << r.out;
}

TEST(DefaultsCli, MisspeltCommandsGetTheNameMeant) {
  TempDir dir;
  const CliResult r = run_cli(dir, "segmnet", {bundled("floorplan.yaml")});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "topocut: error: unknown command 'segmnet' (did you mean 'segment'?) (see 'topocut --help')\n");
  const CliResult far = run_cli(dir, "paint", {});
  EXPECT_EQ(far.err, "topocut: error: unknown command 'paint' (see 'topocut --help')\n");
}

TEST(DefaultsCli, AnImagesAssumedResolutionIsAnnounced) {
  TempDir dir;
  // The bundled map's image without its YAML, as a PGM (map_server's format).
  const std::string pgm = dir.file("floorplan.pgm");
  ASSERT_TRUE(topocut::testing::write_test_image(pgm, topocut::testing::read_test_image(bundled("floorplan.png"))));
  const CliResult assumed = run_cli(dir, "segment", {pgm, "--out-json", dir.file("rooms.json")});
  ASSERT_EQ(assumed.code, 0) << assumed.err;
  EXPECT_TRUE(has(assumed.out, "note: an image holds no scale: its cells were taken as 0.05 m (the default); give "
                               "--resolution M")) << assumed.out;
  const CliResult given = run_cli(dir, "segment", {pgm, "--resolution", "0.05", "--out-json", dir.file("rooms.json")});
  ASSERT_EQ(given.code, 0) << given.err;
  EXPECT_FALSE(has(given.out, "holds no scale")) << given.out;
  const CliResult yaml = run_cli(dir, "segment", {bundled("floorplan.yaml"), "--out-json", dir.file("rooms.json")});
  EXPECT_FALSE(has(yaml.out, "holds no scale")) << yaml.out;
}

TEST(DefaultsCli, ARunWithoutOutputsSaysHowToAskForOne) {
  TempDir dir;
  const CliResult bare = run_cli(dir, "segment", {bundled("floorplan.yaml")});
  ASSERT_EQ(bare.code, 0) << bare.err;
  EXPECT_TRUE(has(bare.out, "note: nothing written; ask for outputs: --out-json FILE")) << bare.out;
  for (const std::vector<std::string>& asked : {std::vector<std::string>{"--out-json", dir.file("rooms.json")},
                                                std::vector<std::string>{"--at", "4.4,6.9"}}) {
    std::vector<std::string> args = {bundled("floorplan.yaml")};
    args.insert(args.end(), asked.begin(), asked.end());
    const CliResult r = run_cli(dir, "segment", args);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(has(r.out, "nothing written")) << r.out;
  }
}

}  // namespace
