#pragma once
// Decoding input images within bounds: only the formats a map comes in (PNG, PGM/PPM/PBM, JPEG, BMP,
// TIFF), recognised by their magic bytes, and only up to a pixel limit read from the header before
// anything is decoded, so that no other codec ever sees a map and a small file declaring a huge image
// ends in one clear error instead of gigabytes of memory.
#include <cstdint>
#include <string>
#include <string_view>

#include <opencv2/core.hpp>

namespace topocut {

// The pixel limit of every input image (map, a YAML's image, ground truth, label image).
struct ImageLimits {
  double max_megapixels = 100.0;  // default: the largest map measured (docs/limits.md); range below
};
inline constexpr double kMaxMegapixelsCeiling = 1000.0;  // OpenCV refuses images above 2^30 pixels

// The command-line option that sets ImageLimits::max_megapixels in every command and program.
inline constexpr const char* kMaxMegapixelsOption = "max-megapixels";
// Its help line, with the default and the allowed range.
std::string max_megapixels_help();

enum class ImageFormat { kPng, kNetpbm, kJpeg, kBmp, kTiff };

struct ImageHeader {
  ImageFormat format = ImageFormat::kPng;
  std::uint64_t width = 0;
  std::uint64_t height = 0;
};

// The size an input image must have where another input fixes it (a label image or a ground truth
// of a known map): checked against the header, before anything is decoded. of names what fixes it,
// e.g. "the map".
struct ExpectedSize {
  std::uint64_t width = 0, height = 0;
  std::string of;
};

// Throws Error naming the allowed range unless 0 < max_megapixels <= kMaxMegapixelsCeiling.
void validate(const ImageLimits& limits);

// The format and size the image's header declares. Throws Error naming source if the bytes are not
// one of the accepted formats or the header is truncated or declares an empty image.
ImageHeader read_image_header(std::string_view bytes, const std::string& source);

// Throws Error naming source, the limit and how to change it if header exceeds limits, and naming
// both sizes if expected is given and header's differs.
void check_image_size(const ImageHeader& header, const ImageLimits& limits, const std::string& source,
                      const ExpectedSize* expected = nullptr);

// The order of a colour image's channels from decode_image(): blue, green, red (and alpha), as
// cv::imdecode gave them, or whichever order its decoder gives cheapest (a PNG's own red, green,
// blue: libpng then swaps no pixel), for a caller that reads only what the order does not change,
// such as the channels' sum.
enum class ColourOrder { kBgr, kAny };

// The pixels after read_image_header() and check_image_size(), as cv::imdecode(IMREAD_UNCHANGED)
// gave them (grey, BGR or BGRA; 8 or 16 bits; see image_codec.h) but for the colour order asked;
// nothing is printed. Throws Error naming source if it is refused or does not decode.
cv::Mat decode_image(std::string_view bytes, const std::string& source, const ImageLimits& limits,
                     const ExpectedSize* expected = nullptr, ColourOrder order = ColourOrder::kBgr);

// The byte limit of an image file under limits: 8 bytes a pixel (16-bit RGBA, uncompressed) plus 1 MiB.
std::uint64_t max_image_file_bytes(const ImageLimits& limits);

// read_input_file() within max_image_file_bytes(), then decode_image(); `what` names the input
// ("map image", "ground truth", ...) in errors.
cv::Mat read_image(const std::string& path, const std::string& what, const ImageLimits& limits,
                   const ExpectedSize* expected = nullptr);

// The size path's header declares (nothing is decoded), within limits; `what` names it in errors.
ImageHeader read_image_size(const std::string& path, const std::string& what, const ImageLimits& limits);

}  // namespace topocut
