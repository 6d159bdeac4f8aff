// Error messages are one terminal line whatever a bad file puts into them.
#include "topocut/core/error.h"

#include <string>

#include <gtest/gtest.h>

namespace topocut {
namespace {

TEST(OneLineMessage, KeepsAShortMessageAsItIs) {
  EXPECT_EQ(one_line_message("cannot read 'map.png': no such file"), "cannot read 'map.png': no such file");
}

TEST(OneLineMessage, TurnsLineBreaksAndControlCharactersIntoSpaces) {
  EXPECT_EQ(one_line_message("bad value\n\tin line 3\r\n"), "bad value in line 3");
}

TEST(OneLineMessage, KeepsTheEndsOfALongToken) {
  const std::string token = std::string(40, 'a') + std::string(10'000'000, 'b') + std::string(15, 'c');
  const std::string line = one_line_message("bad token '" + token + "' on line 2");
  EXPECT_LE(line.size(), 200u);
  // The word's first 40 characters ("'" and 39 a) and its last 15 ("cccc...'") survive.
  EXPECT_EQ(line, "bad token '" + std::string(39, 'a') + "..." + std::string(14, 'c') + "' on line 2");
}

TEST(OneLineMessage, CutsALongMessageToTheLimit) {
  std::string message;
  for (int i = 0; i < 100; ++i) message += "word" + std::to_string(i) + " ";
  const std::string line = one_line_message(message, 50);
  EXPECT_EQ(line.size(), 50u);
  EXPECT_EQ(line.substr(0, 12), "word0 word1 ");
  EXPECT_EQ(line.substr(47), "...");
}

TEST(OneLineMessage, NeverSplitsAUtf8Character) {
  // 30 two-byte characters: a cut at byte 40 or 15 from the end would land inside one if not moved.
  std::string word = "x";
  for (int i = 0; i < 30; ++i) word += "\xc3\xa9";  // é
  const std::string line = one_line_message(word);
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    if (line[i] == '.' && static_cast<unsigned char>(line[i + 1]) >= 0x80) {
      EXPECT_EQ(static_cast<unsigned char>(line[i + 1]) & 0xC0, 0xC0u) << "split character after the ellipsis";
    }
  }
  const std::size_t dots = line.find("...");
  ASSERT_NE(dots, std::string::npos);
  EXPECT_NE(static_cast<unsigned char>(line[dots - 1]), 0xC3u) << "a lead byte without its continuation";
}

}  // namespace
}  // namespace topocut
