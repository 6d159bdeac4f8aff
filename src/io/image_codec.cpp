#include "topocut/io/image_codec.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "io/codecs/codecs.h"
#include "topocut/core/error.h"

namespace topocut {
namespace {

enum class Writer { kPng, kJpeg, kPgm, kPpm, kPnm, kPbm, kBmp, kTiff };

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::optional<Writer> writer_for(const std::string& extension) {
  const std::string e = lower(extension);
  if (e == ".png") return Writer::kPng;
  if (e == ".jpg" || e == ".jpeg" || e == ".jpe") return Writer::kJpeg;
  if (e == ".pgm") return Writer::kPgm;
  if (e == ".ppm") return Writer::kPpm;
  if (e == ".pnm") return Writer::kPnm;
  if (e == ".pbm") return Writer::kPbm;
  if (e == ".bmp" || e == ".dib") return Writer::kBmp;
  if (e == ".tif" || e == ".tiff") return Writer::kTiff;
  return std::nullopt;
}

bool stores_depth(Writer writer, int depth) {
  switch (writer) {
    case Writer::kJpeg:
    case Writer::kBmp: return depth == CV_8U;
    default: return depth == CV_8U || depth == CV_16U;
  }
}

std::string encode_with(Writer writer, const cv::Mat& image) {
  switch (writer) {
    case Writer::kPng: return codecs::encode_png(image);
    case Writer::kJpeg: return codecs::encode_jpeg(image);
    case Writer::kPgm: return codecs::encode_netpbm(image, codecs::NetpbmKind::kPgm);
    case Writer::kPpm: return codecs::encode_netpbm(image, codecs::NetpbmKind::kPpm);
    case Writer::kPnm: return codecs::encode_netpbm(image, codecs::NetpbmKind::kAuto);
    case Writer::kPbm: return codecs::encode_netpbm(image, codecs::NetpbmKind::kPbm);
    case Writer::kBmp: return codecs::encode_bmp(image);
    case Writer::kTiff: return codecs::encode_tiff(image);
  }
  throw codecs::CodecError("unknown format");
}

}  // namespace

bool can_encode_image(const std::string& path) {
  return writer_for(std::filesystem::path(path).extension().string()).has_value();
}

std::string encode_image(const cv::Mat& image, const std::string& extension) {
  const std::optional<Writer> writer = writer_for(extension);
  const int channels = image.channels();
  if (!writer || image.empty() || !(channels == 1 || channels == 3 || channels == 4))
    throw Error("cannot encode an image of " + std::to_string(channels) + " channels as " + extension);
  cv::Mat pixels = image;
  if (!stores_depth(*writer, image.depth())) image.convertTo(pixels, CV_8U);
  try {
    return encode_with(*writer, pixels);
  } catch (const codecs::CodecError& e) {
    throw Error("cannot encode an image as " + extension + ": " + e.what());
  }
}

}  // namespace topocut
