#include "topocut/core/format.h"

#include <string>

#include <gtest/gtest.h>

namespace topocut {
namespace {

TEST(Format, PrintsLikePrintf) {
  EXPECT_EQ(format("%.3f ms, p95 %.1f %%", 1.23456, 99.95), "1.235 ms, p95 100.0 %");
  EXPECT_EQ(format("%d of %zu", 3, std::size_t{40}), "3 of 40");
  EXPECT_EQ(format("plain"), "plain");
}

TEST(Format, LongTextIsNotCut) {
  const std::string word(1000, 'x');
  const std::string out = format("<%s|%.2f>", word.c_str(), 2.5);
  EXPECT_EQ(out, "<" + word + "|2.50>");
}

}  // namespace
}  // namespace topocut
