// Regressions found by the hardening work (fuzzing and extreme maps) in the io module.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "topocut/core/error.h"
#include "topocut/io/map_loader.h"

namespace topocut {
namespace {

// A corrupt PNG made libpng print "libpng warning/error" lines on stderr before our Error, so the CLI
// printed three lines instead of one clear error line.
TEST(IoFuzzRegression, CorruptImagesThrowWithoutPrintingAnything) {
  const std::string corrupt_png("\x89PNG\r\n\x1a\n garbage", 17);
  // A JPEG 2000 codestream header with nothing after it: OpenJPEG logs "Stream too short".
  const std::string short_j2k("\xff\x4f\xff\x51\x00\x2f\x00\x00", 8);
  for (const std::string& bytes : {corrupt_png, short_j2k}) {
    cv::Mat grey, transparent;
    ::testing::internal::CaptureStderr();
    EXPECT_THROW(decode_map_image(bytes, "bad", grey, transparent), Error);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  }
}

TEST(IoFuzzRegression, StderrWorksAgainAfterDecoding) {
  cv::Mat grey, transparent;
  EXPECT_THROW(decode_map_image(std::string("\x89PNG\r\n\x1a\n x", 10), "bad", grey, transparent), Error);
  ::testing::internal::CaptureStderr();
  std::fputs("still here\n", stderr);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "still here\n");
}

}  // namespace
}  // namespace topocut
