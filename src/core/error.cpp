#include "topocut/core/error.h"

namespace topocut {

namespace {

constexpr std::size_t kLongWord = 60;
constexpr std::size_t kHead = 40;
constexpr std::size_t kTail = 15;
const std::string kEllipsis = "...";

// Moves a cut position back to the start of a UTF-8 character, so no character is split.
std::size_t character_start(const std::string& text, std::size_t position) {
  while (position > 0 && position < text.size() && (static_cast<unsigned char>(text[position]) & 0xC0) == 0x80) --position;
  return position;
}

std::string shortened_word(const std::string& word) {
  if (word.size() <= kLongWord) return word;
  return word.substr(0, character_start(word, kHead)) + kEllipsis + word.substr(character_start(word, word.size() - kTail));
}

}  // namespace

std::string one_line_message(const std::string& message, std::size_t max_length) {
  std::string text;
  std::string word;
  for (char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f || c == ' ') {
      text += shortened_word(word);
      word.clear();
      if (text.empty() || text.back() != ' ') text += ' ';
    } else {
      word += c;
    }
  }
  text += shortened_word(word);
  while (!text.empty() && text.back() == ' ') text.pop_back();
  if (text.size() > max_length) {
    const std::size_t keep = max_length > kEllipsis.size() ? max_length - kEllipsis.size() : 0;
    text = text.substr(0, character_start(text, keep)) + kEllipsis;
  }
  return text;
}

}  // namespace topocut
