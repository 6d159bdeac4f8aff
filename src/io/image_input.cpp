#include "topocut/io/image_input.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <new>
#include <optional>
#include <sstream>
#include <vector>

#include "io/codecs/codecs.h"
#include "topocut/core/error.h"
#include "topocut/core/input_file.h"

namespace topocut {

namespace {

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// Bounds-checked reads of the header bytes.
class HeaderBytes {
 public:
  explicit HeaderBytes(std::string_view bytes) : bytes_(bytes) {}
  bool has(std::size_t offset, std::size_t n) const { return offset <= bytes_.size() && n <= bytes_.size() - offset; }
  std::uint8_t at(std::size_t i) const { return static_cast<std::uint8_t>(bytes_[i]); }
  std::uint32_t big(std::size_t offset, int n) const {
    std::uint32_t v = 0;
    for (int i = 0; i < n; ++i) v = (v << 8) | at(offset + i);
    return v;
  }
  std::uint32_t little(std::size_t offset, int n) const {
    std::uint32_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = (v << 8) | at(offset + i);
    return v;
  }
  std::string_view view() const { return bytes_; }

 private:
  std::string_view bytes_;
};

using Size = std::optional<std::pair<std::uint64_t, std::uint64_t>>;  // width, height

struct DuplicateTag {
  std::uint32_t tag;
};

Size png_size(const HeaderBytes& b) {
  // Signature (8), then the IHDR chunk: length (4), "IHDR", width (4), height (4), big-endian.
  if (!b.has(0, 24) || b.view().substr(12, 4) != "IHDR") return std::nullopt;
  return std::pair<std::uint64_t, std::uint64_t>{b.big(16, 4), b.big(20, 4)};
}

// Netpbm: magic, then width and height as decimal text, separated by white space and # comments.
Size netpbm_size(const HeaderBytes& b) {
  const std::string_view s = b.view();
  std::size_t i = 2;
  std::uint64_t values[2] = {0, 0};
  for (std::uint64_t& value : values) {
    while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == '#')) {
      if (s[i] == '#') {
        while (i < s.size() && s[i] != '\n' && s[i] != '\r') ++i;
      } else {
        ++i;
      }
    }
    const std::size_t start = i;
    while (i < s.size() && i - start < 12 && std::isdigit(static_cast<unsigned char>(s[i]))) value = value * 10 + (s[i++] - '0');
    if (i == start || i - start >= 12) return std::nullopt;
  }
  return std::pair<std::uint64_t, std::uint64_t>{values[0], values[1]};
}

// JPEG: segments after SOI until a start-of-frame marker (C0..CF except DHT C4, JPG C8, DAC CC).
Size jpeg_size(const HeaderBytes& b) {
  std::size_t i = 2;
  while (b.has(i, 4)) {
    if (b.at(i) != 0xFF) return std::nullopt;
    const std::uint8_t marker = b.at(i + 1);
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
      i += 2;
      continue;
    }
    const std::uint32_t length = b.big(i + 2, 2);
    if (length < 2) return std::nullopt;
    if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
      if (!b.has(i + 4, 5)) return std::nullopt;
      return std::pair<std::uint64_t, std::uint64_t>{b.big(i + 7, 2), b.big(i + 5, 2)};
    }
    if (marker == 0xDA || marker == 0xD9) return std::nullopt;  // scan data or end before any frame
    i += 2 + length;
  }
  return std::nullopt;
}

Size bmp_size(const HeaderBytes& b) {
  if (!b.has(14, 4)) return std::nullopt;
  const std::uint32_t dib = b.little(14, 4);
  if (dib == 12) {  // OS/2 BITMAPCOREHEADER: 16-bit sizes
    if (!b.has(18, 4)) return std::nullopt;
    return std::pair<std::uint64_t, std::uint64_t>{b.little(18, 2), b.little(20, 2)};
  }
  if (!b.has(18, 8)) return std::nullopt;
  const auto width = static_cast<std::int32_t>(b.little(18, 4));
  const auto height = static_cast<std::int32_t>(b.little(22, 4));  // negative: rows stored top-down
  if (width <= 0) return std::nullopt;
  return std::pair<std::uint64_t, std::uint64_t>{static_cast<std::uint64_t>(width),
                                                 static_cast<std::uint64_t>(std::abs(static_cast<std::int64_t>(height)))};
}

// Classic TIFF: the first image file directory's ImageWidth (256) and ImageLength (257). A tag given
// twice is refused: libtiff keeps the first copy, so a second one would be a size nobody checked.
Size tiff_size(const HeaderBytes& b) {
  const bool little = b.at(0) == 'I';
  const auto read = [&](std::size_t offset, int n) { return little ? b.little(offset, n) : b.big(offset, n); };
  if (!b.has(4, 4)) return std::nullopt;
  const std::size_t ifd = read(4, 4);
  if (!b.has(ifd, 2)) return std::nullopt;
  const std::uint32_t entries = read(ifd, 2);
  std::uint64_t width = 0, height = 0;
  std::vector<std::uint32_t> tags;
  for (std::uint32_t e = 0; e < entries; ++e) {
    const std::size_t at = ifd + 2 + 12 * static_cast<std::size_t>(e);
    if (!b.has(at, 12)) return std::nullopt;
    const std::uint32_t tag = read(at, 2), type = read(at + 2, 2);
    tags.push_back(tag);
    if (tag != 256 && tag != 257) continue;
    const std::uint64_t value = type == 3 ? read(at + 8, 2) : type == 4 ? read(at + 8, 4) : 0;
    (tag == 256 ? width : height) = value;
  }
  std::sort(tags.begin(), tags.end());
  if (const auto twice = std::adjacent_find(tags.begin(), tags.end()); twice != tags.end())
    throw DuplicateTag{*twice};
  return std::pair<std::uint64_t, std::uint64_t>{width, height};
}

std::optional<ImageFormat> format_of(const HeaderBytes& b) {
  const std::string_view s = b.view();
  if (s.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) return ImageFormat::kPng;
  if (s.size() >= 2 && s[0] == 'P' && s[1] >= '1' && s[1] <= '6') return ImageFormat::kNetpbm;
  if (s.substr(0, 3) == "\xFF\xD8\xFF") return ImageFormat::kJpeg;
  if (s.substr(0, 2) == "BM") return ImageFormat::kBmp;
  if (s.substr(0, 4) == std::string_view("II*\0", 4) || s.substr(0, 4) == std::string_view("MM\0*", 4))
    return ImageFormat::kTiff;
  return std::nullopt;
}

const char* format_name(ImageFormat format) {
  switch (format) {
    case ImageFormat::kPng: return "PNG";
    case ImageFormat::kNetpbm: return "PGM/PPM";
    case ImageFormat::kJpeg: return "JPEG";
    case ImageFormat::kBmp: return "BMP";
    case ImageFormat::kTiff: return "TIFF";
  }
  return "image";
}

std::string out_of_memory(const std::string& source, const ImageHeader& header) {
  return "cannot read " + quoted(source) + ": out of memory for its " + std::to_string(header.width) + " x " +
         std::to_string(header.height) + " pixels";
}

}  // namespace

void validate(const ImageLimits& limits) {
  if (!(limits.max_megapixels > 0.0 && limits.max_megapixels <= kMaxMegapixelsCeiling)) {
    std::ostringstream text;
    text << "the image limit (--max-megapixels) must lie in (0, " << kMaxMegapixelsCeiling << "] megapixels, got "
         << limits.max_megapixels;
    throw Error(text.str());
  }
}

std::string max_megapixels_help() {
  std::ostringstream text;
  // The front ends add the default; an image's size is read from its header, a ROS map's from its info.
  text << "refuse maps of more megapixels, before a cell is decoded (at most " << kMaxMegapixelsCeiling << ")";
  return text.str();
}

ImageHeader read_image_header(std::string_view bytes, const std::string& source) {
  if (bytes.empty()) throw Error("image " + quoted(source) + " is empty (0 bytes)");
  const HeaderBytes b(bytes);
  const std::optional<ImageFormat> format = format_of(b);
  if (!format)
    throw Error("cannot read " + quoted(source) + " as an image: not PNG, PGM/PPM, JPEG, BMP or TIFF (by its first bytes)");
  Size size;
  switch (*format) {
    case ImageFormat::kPng: size = png_size(b); break;
    case ImageFormat::kNetpbm: size = netpbm_size(b); break;
    case ImageFormat::kJpeg: size = jpeg_size(b); break;
    case ImageFormat::kBmp: size = bmp_size(b); break;
    case ImageFormat::kTiff:
      try {
        size = tiff_size(b);
      } catch (const DuplicateTag& d) {
        throw Error("cannot read " + quoted(source) + " as an image: its TIFF header gives tag " + std::to_string(d.tag) +
                    " twice (conflicting fields)");
      }
      break;
  }
  if (!size || size->first == 0 || size->second == 0)
    throw Error("cannot read " + quoted(source) + " as an image: its " + format_name(*format) +
                " header is corrupt or declares an empty image");
  return {*format, size->first, size->second};
}

void check_image_size(const ImageHeader& header, const ImageLimits& limits, const std::string& source,
                      const ExpectedSize* expected) {
  validate(limits);
  if (expected != nullptr && (header.width != expected->width || header.height != expected->height)) {
    std::ostringstream text;
    text << "image " << quoted(source) << " is " << header.width << " x " << header.height << " pixels but " << expected->of
         << " is " << expected->width << " x " << expected->height;
    throw Error(text.str());
  }
  const double megapixels = static_cast<double>(header.width) * static_cast<double>(header.height) / 1e6;
  if (megapixels > limits.max_megapixels) {
    std::ostringstream text;
    text << "image " << quoted(source) << " declares " << header.width << " x " << header.height << " pixels ("
         << megapixels << " megapixels), more than the limit of " << limits.max_megapixels
         << " megapixels (raise it with --max-megapixels)";
    throw Error(text.str());
  }
}

cv::Mat decode_image(std::string_view bytes, const std::string& source, const ImageLimits& limits,
                     const ExpectedSize* expected, ColourOrder order) {
  const ImageHeader header = read_image_header(bytes, source);
  check_image_size(header, limits, source, expected);
  const codecs::DecodeBounds bounds{header.width, header.height};
  cv::Mat image;
  try {
    switch (header.format) {
      case ImageFormat::kPng:
        image = order == ColourOrder::kBgr ? codecs::decode_png(bytes, bounds) : codecs::decode_png_rgb(bytes, bounds);
        break;
      case ImageFormat::kNetpbm: image = codecs::decode_netpbm(bytes, bounds); break;
      case ImageFormat::kJpeg: image = codecs::decode_jpeg(bytes, bounds); break;
      case ImageFormat::kBmp: image = codecs::decode_bmp(bytes, bounds); break;
      case ImageFormat::kTiff: image = codecs::decode_tiff(bytes, bounds); break;
    }
  } catch (const codecs::CodecRefusal& e) {
    throw Error("cannot read " + quoted(source) + " as an image: " + e.what());
  } catch (const codecs::CodecError&) {
    image.release();
  } catch (const std::bad_alloc&) {
    throw Error(out_of_memory(source, header));
  } catch (const cv::Exception& e) {  // an allocation the header's size made impossible
    if (e.code == cv::Error::StsNoMem) throw Error(out_of_memory(source, header));
    image.release();
  }
  if (image.empty()) throw Error("cannot read " + quoted(source) + " as an image (corrupt or truncated)");
  return image;
}

std::uint64_t max_image_file_bytes(const ImageLimits& limits) {
  validate(limits);
  // Capped below 2 GiB, the bound cv::imdecode had (an int size), so the same files are accepted.
  const double bytes = limits.max_megapixels * 1e6 * 8.0 + (1u << 20);
  return static_cast<std::uint64_t>(std::min(bytes, 2147483647.0));
}

cv::Mat read_image(const std::string& path, const std::string& what, const ImageLimits& limits,
                   const ExpectedSize* expected) {
  return decode_image(read_input_file(path, what, max_image_file_bytes(limits)), path, limits, expected);
}

ImageHeader read_image_size(const std::string& path, const std::string& what, const ImageLimits& limits) {
  const ImageHeader header = read_image_header(read_input_file(path, what, max_image_file_bytes(limits)), path);
  check_image_size(header, limits, path);
  return header;
}

}  // namespace topocut
