// The outputs of a run: checked before the work, staged, committed together, never destroying an
// input, a device or a file a planted symlink points to.
#include "topocut/io/output_files.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/temp_dir.h"
#include "topocut/core/error.h"
#include "topocut/io/atomic_file.h"

namespace topocut {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The names in the folder, so a test sees any temporary file left behind.
std::vector<std::string> names_in(const TempDir& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir.path())) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string error_of(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  try {
    check_outputs(outputs, inputs);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CheckOutputs, RefusesAnInputUnderAnyName) {
  TempDir dir;
  const std::string map = dir.write("map.png", "pixels");
  fs::create_hard_link(map, dir.file("hard.png"));
  fs::create_symlink(map, dir.file("link.png"));
  EXPECT_NE(error_of({map}, {map}).find("both an input and an output"), std::string::npos);
  EXPECT_NE(error_of({dir.file("hard.png")}, {map}).find("both an input and an output"), std::string::npos);
  EXPECT_NE(error_of({map}, {dir.file("link.png")}).find("both an input and an output"), std::string::npos);
  EXPECT_EQ(error_of({dir.file("other.png")}, {map}), "");
}

TEST(CheckOutputs, RefusesTwoOutputsOnOneFile) {
  TempDir dir;
  const std::string a = dir.file("a.json");
  const std::string same = (dir.path() / "." / "a.json").string();
  EXPECT_NE(error_of({a, same}, {}).find("two outputs name the same file"), std::string::npos);
  dir.write("b.json", "old");
  EXPECT_NE(error_of({dir.file("b.json"), (dir.path() / "." / "b.json").string()}, {}).find("two outputs name the same file"),
            std::string::npos);
  EXPECT_EQ(error_of({a, dir.file("b.json")}, {}), "");
}

TEST(CheckOutputs, RefusesFifosAndDirectoriesButWritesCharacterDevices) {
  TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe").c_str(), 0600), 0);
  EXPECT_NE(error_of({dir.file("pipe")}, {}).find("not a regular file"), std::string::npos);
  EXPECT_NE(error_of({dir.path().string()}, {}).find("directory"), std::string::npos);
  EXPECT_EQ(error_of({"/dev/null", "/dev/null"}, {}), "");
}

TEST(WriteFileAtomically, WritesDevicesDirectlyAndReportsTheirErrors) {
  write_file_atomically("/dev/null", "nothing");
  struct stat info {};
  ASSERT_EQ(::stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  if (fs::exists("/dev/full")) {
    EXPECT_THROW(write_file_atomically("/dev/full", "x"), Error);
  }
}

TEST(WriteFileAtomically, ReplacesASymlinkInsteadOfWritingThroughIt) {
  TempDir dir;
  const std::string victim = dir.write("victim.txt", "keep me");
  fs::create_symlink(victim, dir.file("out.txt"));
  write_file_atomically(dir.file("out.txt"), "new");
  EXPECT_EQ(slurp(victim), "keep me");
  EXPECT_FALSE(fs::is_symlink(dir.file("out.txt")));
  EXPECT_EQ(slurp(dir.file("out.txt")), "new");
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"out.txt", "victim.txt"}));
}

TEST(OutputRun, CommitsAllFilesTogether) {
  TempDir dir;
  dir.write("a.txt", "old a");
  {
    OutputRun run;
    write_file_atomically(dir.file("a.txt"), "new a");
    write_file_atomically(dir.file("b.txt"), "new b");
    EXPECT_EQ(slurp(dir.file("a.txt")), "old a");
    EXPECT_FALSE(fs::exists(dir.file("b.txt")));
    run.commit();
  }
  EXPECT_EQ(slurp(dir.file("a.txt")), "new a");
  EXPECT_EQ(slurp(dir.file("b.txt")), "new b");
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.txt", "b.txt"}));
}

TEST(OutputRun, AFailedRunLeavesEveryFileAsItWas) {
  TempDir dir;
  dir.write("a.txt", "old a");
  try {
    OutputRun run;
    write_file_atomically(dir.file("a.txt"), "new a");
    write_file_atomically(dir.file("b.txt"), "new b");
    throw Error("the third output failed");
  } catch (const Error&) {
  }
  EXPECT_EQ(slurp(dir.file("a.txt")), "old a");
  EXPECT_EQ(names_in(dir), (std::vector<std::string>{"a.txt"}));
}

TEST(OutputRun, KeepsTheModeOfTheFileItReplaces) {
  TempDir dir;
  const std::string path = dir.write("a.txt", "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file_atomically(path, "new");
  EXPECT_EQ(fs::status(path).permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// A run killed while it holds staged files leaves neither them nor a partial target behind.
TEST(OutputRunDeathTest, ATerminatedRunLeavesNoTemporaryFile) {
  TempDir dir;
  EXPECT_EXIT(
      {
        OutputRun run;
        write_file_atomically(dir.file("a.txt"), std::string(1 << 20, 'x'));
        std::raise(SIGTERM);
      },
      ::testing::KilledBySignal(SIGTERM), "");
  EXPECT_TRUE(names_in(dir).empty());
}

}  // namespace
}  // namespace topocut
