#pragma once
// Shared helpers of the libFuzzer targets (not a target itself: CMake globs only fuzz/*.cpp).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace topocut::fuzz {

// Reads bytes from the front of the fuzzer's input; runs dry by returning zeros.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t next() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool empty() const { return pos_ >= size_; }
  std::size_t remaining() const { return size_ - pos_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// A property the library promises does not hold: report it the way libFuzzer reports a crash.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "topocut fuzz property violated: %s\n", what.c_str());
  std::abort();
}

}  // namespace topocut::fuzz
