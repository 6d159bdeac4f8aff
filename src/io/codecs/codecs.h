#pragma once
// The per-format decoders and encoders behind decode_image() and encode_image(). Each gives pixels in
// OpenCV's layout (what cv::imdecode with IMREAD_UNCHANGED gave: BGR(A) channel order, 16-bit samples
// kept, grey kept grey), since the rest of topocut works on cv::Mat in that layout. Each throws
// CodecError with a short reason; the public functions turn it into one Error line naming the file.
#include <stdexcept>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace topocut::codecs {

struct CodecError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

cv::Mat decode_png(std::string_view bytes);
cv::Mat decode_jpeg(std::string_view bytes);
cv::Mat decode_netpbm(std::string_view bytes);
cv::Mat decode_bmp(std::string_view bytes);
cv::Mat decode_tiff(std::string_view bytes);

// Encoders take an image of 1, 3 or 4 channels already in a depth the format supports.
std::string encode_png(const cv::Mat& image);
std::string encode_jpeg(const cv::Mat& image);
enum class NetpbmKind { kAuto, kPgm, kPpm, kPbm };
std::string encode_netpbm(const cv::Mat& image, NetpbmKind kind);
std::string encode_bmp(const cv::Mat& image);
std::string encode_tiff(const cv::Mat& image);

}  // namespace topocut::codecs
