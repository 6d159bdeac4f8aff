// explore and evaluate on hostile folders (issue 28): links that loop or lead nowhere, a folder
// that contains itself, FIFOs and folders named like images, empty files, 20,000 files. Every run
// ends within seconds: entries that are not regular files are skipped, files that cannot be read
// are FAILED rows of the table (one line each on stderr), and the exit status is 1 with one
// closing error line.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_maps.h"
#include "cli/cli_runner.h"

namespace topocut::testing {
namespace {

namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A folder with one good map and every kind of entry that is not one.
void fill_hostile(const TempDir& dir) {
  fs::copy_file(bundled("floorplan.png"), dir.file("good.png"));
  fs::create_symlink("loop.png", dir.file("loop.png"));
  fs::create_symlink("nowhere.png", dir.file("gone.png"));
  fs::create_directory(dir.file("folder.png"));
  ASSERT_EQ(::mkfifo(dir.file("fifo.png").c_str(), 0644), 0);
  fs::create_directory_symlink(".", dir.file("itself"));
  std::ofstream(dir.file("empty.png")).close();
}

TEST(HostileFolders, EvaluateMapsSkipsWhatIsNotAFileAndFailsWhatCannotBeRead) {
  const TempDir dir;
  fill_hostile(dir);
  const CliResult r = run_cli(dir, "evaluate", {"--maps", dir.path().string(), "--floor-repetitions", "0"}, 20);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.out.find("| good.png "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| empty.png | -"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FAILED: image '"), std::string::npos) << r.out;
  for (const char* skipped : {"loop.png", "gone.png", "folder.png", "fifo.png", "itself"})
    EXPECT_EQ(r.out.find(skipped), std::string::npos) << skipped << "\n" << r.out;
  EXPECT_NE(r.err.find("topocut evaluate: error: 1 of 2 maps failed"), std::string::npos) << r.err;
}

TEST(HostileFolders, EvaluateDatasetGivesEachUnreadableFileItsRow) {
  const TempDir dir;
  for (const char* name : {"a", "b", "c"}) fs::copy_file(bundled("floorplan.png"), dir.file(std::string(name) + ".png"));
  fs::create_symlink("a_gt_segmentation.png", dir.file("a_gt_segmentation.png"));  // a loop
  ASSERT_EQ(::mkfifo(dir.file("b_gt_segmentation.png").c_str(), 0644), 0);         // never opened for reading
  fs::create_directory(dir.file("c_gt_segmentation.png"));
  const CliResult r = run_cli(dir, "evaluate", {"--dataset", dir.path().string(), "--variant", "plain"}, 20);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(count(r.out, "FAILED"), 3) << r.out;
  EXPECT_NE(r.err.find("topocut evaluate: error: 3 of 3 images failed"), std::string::npos) << r.err;
}

// docs/limits.md: a million empty files would be a million FAILED rows; 20,000 take under a
// second in Release.
TEST(HostileFolders, TwentyThousandEmptyFilesAreTwentyThousandRows) {
  const TempDir dir;
  // The names built by appending: GCC 12 warns falsely (-Wrestrict) on "m" + std::to_string(...).
  for (int i = 0; i < 20000; ++i) std::ofstream(dir.file(std::string("m").append(std::to_string(100000 + i)).append(".png"))).close();
  fs::copy_file(bundled("floorplan.png"), dir.file("z.png"));
  const CliResult r = run_cli(dir, "evaluate", {"--maps", dir.path().string(), "--floor-repetitions", "0"}, 120);
  EXPECT_EQ(r.code, 1) << r.err.substr(0, 500);
  EXPECT_EQ(count(r.out, "FAILED: image"), 20000);
  EXPECT_NE(r.out.find("1 maps, 7 rooms"), std::string::npos);
  EXPECT_NE(r.err.find("topocut evaluate: error: 20000 of 20001 maps failed"), std::string::npos);
}

TEST(HostileFolders, ExploreRefusesAFolderALoopAndAFifoAsItsMap) {
  const TempDir dir;
  fill_hostile(dir);
  expect_clean_error(run_cli(dir, "explore", {dir.file("folder.png")}), "explore", "it is a directory");
  expect_clean_error(run_cli(dir, "explore", {dir.file("fifo.png")}), "explore", "not a regular file");
  const CliResult loop = run_cli(dir, "explore", {dir.file("loop.png")});
  expect_clean_error(loop, "explore", "loop.png");
  // The frames folder may not be a file or lead through a loop of links.
  expect_clean_error(run_cli(dir, "explore", {dir.file("good.png"), "--frames", dir.file("empty.png")}), "explore",
                     "frames folder");
  expect_clean_error(run_cli(dir, "explore", {dir.file("good.png"), "--frames", dir.file("loop.png")}), "explore",
                     "frames folder");
}

}  // namespace
}  // namespace topocut::testing
