// `topocut decompose` as a user runs it: the built binary, its exit codes, its JSON and its errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "topocut/core/option_table.h"
#include "topocut/decomposition/decompose.h"

namespace {

namespace fs = std::filesystem;

using topocut::testing::CliResult;
using topocut::testing::run_cli_line;
using topocut::testing::file_text;

class DecomposeCli : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  CliResult run(const std::string& args) { return run_cli_line(dir_, "decompose " + args); }

  // Runs with bad input: non-zero exit, nothing on stdout, exactly one error line naming `fragment`.
  void expect_error(const std::string& args, const std::string& fragment) {
    const CliResult o = run(args);
    EXPECT_NE(o.code, 0) << args;
    EXPECT_TRUE(o.out.empty()) << o.out;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_NE(o.err.find("error"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << o.err;
  }

  topocut::testing::TempDir temp_;
  const fs::path dir_ = temp_.path();
};

// §9.3 of the spec: a 10x10 room with a 4x4 obstacle, given clockwise (orientation is free).
const char* kSquareWithHole =
    R"({"outer": [[0,0],[0,10],[10,10],[10,0]], "holes": [[[3,3],[7,3],[7,7],[3,7]]]})";

TEST_F(DecomposeCli, PrintsPiecesAndCuts) {
  const fs::path in = write("room.json", kSquareWithHole);
  const CliResult o = run(in.string() + " --tau 4");
  ASSERT_EQ(o.code, 0) << o.err;
  const auto doc = nlohmann::json::parse(o.out);
  ASSERT_EQ(doc["pieces"].size(), 2u);
  double total = 0;
  for (const auto& piece : doc["pieces"]) {
    EXPECT_DOUBLE_EQ(piece["area"].get<double>(), 42.0);
    EXPECT_EQ(piece["outer"].size(), 6u);
    EXPECT_TRUE(piece["holes"].empty());
    total += piece["area"].get<double>();
  }
  EXPECT_DOUBLE_EQ(total, 84.0);
  ASSERT_EQ(doc["cuts"].size(), 2u);
  std::set<std::vector<double>> cuts;
  for (const auto& c : doc["cuts"]) {
    std::vector<double> v{c[0][0], c[0][1], c[1][0], c[1][1]};
    if (std::make_pair(v[2], v[3]) < std::make_pair(v[0], v[1])) v = {v[2], v[3], v[0], v[1]};
    cuts.insert(v);
  }
  EXPECT_EQ(cuts, (std::set<std::vector<double>>{{0, 0, 3, 3}, {7, 7, 10, 10}}));
}

TEST_F(DecomposeCli, LargeTauAbsorbsTheHoleAndWritesAFile) {
  const fs::path in = write("room.json", kSquareWithHole);
  const fs::path out = dir_ / "result.json";
  const CliResult o = run(in.string() + " --tau 6 -o " + out.string());
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_TRUE(o.out.empty());
  const auto doc = nlohmann::json::parse(file_text(out));
  ASSERT_EQ(doc["pieces"].size(), 1u);
  EXPECT_DOUBLE_EQ(doc["pieces"][0]["area"].get<double>(), 100.0);
  EXPECT_TRUE(doc["cuts"].empty());
  EXPECT_EQ(doc["absorbed_holes"].size(), 1u);
}

// --concavity is the concavity bound in metres in every other command (segment_option_rows()); here
// the measure has its own name, so that one name never means two things.
TEST_F(DecomposeCli, TheConcavityMeasureHasItsOwnName) {
  const fs::path in = write("l.json", R"({"outer": [[0,0],[10,0],[10,4],[4,4],[4,10],[0,10]]})");
  const CliResult help = run("--help");
  EXPECT_NE(help.out.find("\n  --concavity-measure straight|hierarchical (=straight)"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("\n  --concavity "), std::string::npos) << help.out;
  const CliResult old = run(in.string() + " --tau 2 --concavity hierarchical");
  EXPECT_EQ(old.code, 2);
  const CliResult bad = run(in.string() + " --tau 2 --concavity-measure curved");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--concavity-measure must be one of 'straight', 'hierarchical', got 'curved'"), std::string::npos) << bad.err;
}

TEST_F(DecomposeCli, ReferenceOptionsAreAccepted) {
  const fs::path in = write("l.json", R"({"outer": [[0,0],[10,0],[10,4],[4,4],[4,10],[0,10]]})");
  const CliResult o = run(in.string() + " --tau 2 --selection reference --concavity-measure hierarchical --candidates reference"
                                      " --pocket-polygons reference --hull-chain-distance line --skinny all");
  ASSERT_EQ(o.code, 0) << o.err;
  const auto doc = nlohmann::json::parse(o.out);
  EXPECT_EQ(doc["pieces"].size(), 2u);
  EXPECT_EQ(doc["cuts"].size(), 1u);
}

TEST_F(DecomposeCli, HelpExitsZero) {
  const CliResult o = run("--help");
  EXPECT_EQ(o.code, 0);
  EXPECT_NE(o.out.find("--tau"), std::string::npos);
}

TEST_F(DecomposeCli, RejectsSelfIntersectingRing) {
  expect_error(write("bow.json", R"({"outer": [[0,0],[10,10],[10,0],[0,10]]})").string() + " --tau 1",
               "intersects itself");
}

TEST_F(DecomposeCli, RejectsTooFewVertices) {
  expect_error(write("two.json", R"({"outer": [[0,0],[1,1]]})").string() + " --tau 1", "fewer than 3");
}

TEST_F(DecomposeCli, RejectsInfiniteAndNaNCoordinates) {
  expect_error(write("inf.json", R"({"outer": [[0,0],[1e999,0],[0,1]]})").string() + " --tau 1", "JSON");
  expect_error(write("nan.json", R"({"outer": [[0,0],[NaN,0],[0,1]]})").string() + " --tau 1", "JSON");
}

TEST_F(DecomposeCli, RejectsHoleOutsideOuterRing) {
  expect_error(write("out.json", R"({"outer": [[0,0],[10,0],[10,10],[0,10]], "holes": [[[20,20],[21,20],[21,21]]]})")
                       .string() +
                   " --tau 1",
               "not inside the outer ring");
}

TEST_F(DecomposeCli, RejectsNonPositiveTau) {
  const std::string in = write("room.json", kSquareWithHole).string();
  expect_error(in + " --tau 0", "--tau");
  expect_error(in + " --tau -3", "--tau");
}

// Without --tau the struct's default holds, as in Python's decompose(): one default for both.
TEST_F(DecomposeCli, TauDefaultsToTheStructsAsInPython) {
  const std::string in = write("room.json", kSquareWithHole).string();
  const CliResult bare = run(in);
  ASSERT_EQ(bare.code, 0) << bare.err;
  const CliResult given = run(in + " --tau " + topocut::shortest_number(topocut::DecompositionOptions{}.tau));
  EXPECT_EQ(bare.out, given.out);
}

TEST_F(DecomposeCli, RejectsMalformedJson) {
  expect_error(write("bad.json", R"({"outer": [[0,0],[1,0],)").string() + " --tau 1", "not valid JSON");
  expect_error(write("arr.json", R"([[0,0],[1,0],[0,1]])").string() + " --tau 1", "\"outer\"");
  expect_error(write("str.json", R"({"outer": [[0,0],["1",0],[0,1]]})").string() + " --tau 1", "two numbers");
  expect_error(write("holes.json", R"({"outer": [[0,0],[1,0],[0,1]], "holes": 3})").string() + " --tau 1", "holes");
}

TEST_F(DecomposeCli, RejectsMissingFile) {
  expect_error((dir_ / "missing.json").string() + " --tau 1", "missing.json");
}

TEST_F(DecomposeCli, RejectsUnknownChoice) {
  const std::string in = write("room.json", kSquareWithHole).string();
  expect_error(in + " --tau 1 --selection best", "--selection");
}

}  // namespace

namespace {

// Results on stdout are an output: a full disk or a closed stdout is an error, not exit 0.
TEST_F(DecomposeCli, AStdoutThatCannotBeWrittenIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const fs::path input = write("room.json", kSquareWithHole);
  const fs::path err = dir_ / "stderr.txt";
  for (const std::string redirect : {" >/dev/full", " >&-"}) {
    SCOPED_TRACE(redirect);
    const std::string command = std::string(TOPOCUT_CLI " decompose ") + input.string() + " --tau 1" + redirect + " 2>" + err.string();
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
    const std::string message = file_text(err);
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    EXPECT_NE(message.find("cannot write to standard output"), std::string::npos) << message;
  }
  const int help = std::system((std::string(TOPOCUT_CLI " --help >/dev/full 2>/dev/null")).c_str());
  EXPECT_EQ(WEXITSTATUS(help), 1);
}

}  // namespace
