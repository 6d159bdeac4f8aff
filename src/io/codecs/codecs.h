#pragma once
// The per-format decoders and encoders behind decode_image() and encode_image(). Each gives pixels in
// OpenCV's layout (what cv::imdecode with IMREAD_UNCHANGED gave: BGR(A) channel order, 16-bit samples
// kept, grey kept grey), since the rest of topocut works on cv::Mat in that layout. Each throws
// CodecError with a short reason; the public functions turn it into one Error line naming the file.
//
// A decoder re-checks what the header check decided on the values it will itself use (a file may
// say two things, and the library reads the other one), before it allocates the image, and bounds
// its work as well as its size.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace topocut::codecs {

// A library's own failure (corrupt data); the message is its, for tests and debugging.
struct CodecError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A documented refusal of ours (a limit, conflicting header fields, a layout not read): the message
// is one the user can act on and goes into the error line.
struct CodecRefusal : CodecError {
  using CodecError::CodecError;
};

// The size the header check accepted; a decoder refuses to allocate any other.
struct DecodeBounds {
  std::uint64_t width = 0;
  std::uint64_t height = 0;
};

// Throws CodecRefusal unless the decoder's width and height are the ones bounds accepted.
void check_decoded_size(std::uint64_t width, std::uint64_t height, const DecodeBounds& bounds, const char* format);

// The scans of a progressive JPEG: each is a pass over the image's coefficients, so their number
// bounds the work of a decode (libtiff refuses more than 100 in its JPEG-in-TIFF decoder as well).
inline constexpr int kMaxJpegScans = 100;

cv::Mat decode_png(std::string_view bytes, const DecodeBounds& bounds);
// decode_png() but a colour PNG's channels in its own order (red first): no pass over the pixels to swap them.
cv::Mat decode_png_rgb(std::string_view bytes, const DecodeBounds& bounds);
cv::Mat decode_jpeg(std::string_view bytes, const DecodeBounds& bounds);
cv::Mat decode_netpbm(std::string_view bytes, const DecodeBounds& bounds);
cv::Mat decode_bmp(std::string_view bytes, const DecodeBounds& bounds);
cv::Mat decode_tiff(std::string_view bytes, const DecodeBounds& bounds);

// Encoders take an image of 1, 3 or 4 channels already in a depth the format supports.
std::string encode_png(const cv::Mat& image);
std::string encode_jpeg(const cv::Mat& image);
enum class NetpbmKind { kAuto, kPgm, kPpm, kPbm };
std::string encode_netpbm(const cv::Mat& image, NetpbmKind kind);
std::string encode_bmp(const cv::Mat& image);
std::string encode_tiff(const cv::Mat& image);

}  // namespace topocut::codecs
