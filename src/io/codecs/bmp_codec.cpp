// Windows BMP. Hand-written: Debian has no small, maintained BMP library (the ones that read BMP are
// whole imaging toolkits such as GDAL, ImageMagick or GraphicsMagick, which would bring back the
// start-up cost this replaces), and a BMP is a header, a palette and padded or run-length coded
// rows. The layout rules are those OpenCV's reader applied: a palette of greys gives one channel, other
// palettes and 15/16/24/32-bit pixels give BGR, 32-bit pixels with colour masks give BGRA, an OS/2
// header gives grey.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

class Bytes {
 public:
  explicit Bytes(std::string_view bytes) : bytes_(bytes) {}
  const unsigned char* at(std::size_t offset, std::size_t n) const {
    if (offset > bytes_.size() || n > bytes_.size() - offset) throw CodecError("the BMP data ends early");
    return reinterpret_cast<const unsigned char*>(bytes_.data() + offset);
  }
  std::uint32_t u32(std::size_t offset) const {
    const unsigned char* p = at(offset, 4);
    return p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
  }
  std::uint16_t u16(std::size_t offset) const {
    const unsigned char* p = at(offset, 2);
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
  }

 private:
  std::string_view bytes_;
};

enum Compression : std::uint32_t { kRgb = 0, kRle8 = 1, kRle4 = 2, kBitfields = 3 };

struct Header {
  std::int64_t offset = 0;
  int width = 0, height = 0, bits = 0;
  std::uint32_t compression = kRgb;
  bool colour = false, top_down = false;
  std::array<std::array<unsigned char, 3>, 256> palette{};  // B, G, R
};

bool colour_palette(const Header& h) {
  for (int i = 0; i < (1 << h.bits); ++i)
    if (h.palette[i][0] != h.palette[i][1] || h.palette[i][0] != h.palette[i][2]) return true;
  return false;
}

bool supported(const Header& h) {
  const bool paletted = h.bits == 1 || h.bits == 4 || h.bits == 8;
  return (h.compression == kRgb && (paletted || h.bits == 16 || h.bits == 24 || h.bits == 32)) ||
         (h.compression == kBitfields && (h.bits == 16 || h.bits == 32)) || (h.compression == kRle4 && h.bits == 4) ||
         (h.compression == kRle8 && h.bits == 8);
}

// The Windows header (40 bytes or longer: V4, V5) and its palette or 16-bit masks.
void read_info_header(const Bytes& b, std::uint32_t size, Header& h) {
  h.width = static_cast<std::int32_t>(b.u32(18));
  h.height = static_cast<std::int32_t>(b.u32(22));
  h.bits = b.u32(26) >> 16;
  h.compression = b.u32(30);
  const auto used = static_cast<std::int32_t>(b.u32(46));
  const std::size_t after = 14 + static_cast<std::size_t>(size);
  if (h.width <= 0 || h.height == 0 || !supported(h)) throw CodecError("unsupported BMP layout");
  h.colour = true;
  if (h.bits <= 8) {
    if (used < 0 || used > 256) throw CodecError("bad BMP palette size");
    const int entries = used == 0 ? 1 << h.bits : used;
    const unsigned char* p = b.at(after, static_cast<std::size_t>(entries) * 4);
    for (int i = 0; i < entries; ++i) h.palette[i] = {p[4 * i], p[4 * i + 1], p[4 * i + 2]};
    h.colour = colour_palette(h);
  } else if (h.bits == 16 && h.compression == kBitfields) {
    const std::uint32_t red = b.u32(after), green = b.u32(after + 4), blue = b.u32(after + 8);
    if (blue == 0x1f && green == 0x3e0 && red == 0x7c00) {
      h.bits = 15;
    } else if (!(blue == 0x1f && green == 0x7e0 && red == 0xf800)) {
      throw CodecError("unsupported BMP colour masks");
    }
  } else if (h.bits == 16) {
    h.bits = 15;
  }
}

// The OS/2 header (12 bytes): 16-bit sizes and a palette of 3-byte entries.
void read_core_header(const Bytes& b, Header& h) {
  h.width = b.u16(18);
  h.height = b.u16(20);
  h.bits = b.u32(22) >> 16;
  if (h.width <= 0 || h.height == 0 || !(h.bits == 1 || h.bits == 4 || h.bits == 8 || h.bits == 24 || h.bits == 32))
    throw CodecError("unsupported BMP layout");
  if (h.bits <= 8) {
    const int entries = 1 << h.bits;
    const unsigned char* p = b.at(26, static_cast<std::size_t>(entries) * 3);
    for (int i = 0; i < entries; ++i) h.palette[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
  }
}

Header read_header(const Bytes& b) {
  Header h;
  h.offset = static_cast<std::int32_t>(b.u32(10));
  const auto size = static_cast<std::int32_t>(b.u32(14));
  if (size >= 36) {
    read_info_header(b, static_cast<std::uint32_t>(size), h);
  } else if (size == 12) {
    read_core_header(b, h);
  } else {
    throw CodecError("unknown BMP header");
  }
  h.top_down = h.height < 0;
  h.height = h.height < 0 ? -h.height : h.height;
  if (h.offset < 0) throw CodecError("bad BMP data offset");
  return h;
}

// The grey OpenCV computes from BGR (weights 0.114, 0.587, 0.299 in 14-bit fixed point).
unsigned char grey_of(const unsigned char* bgr) {
  return static_cast<unsigned char>((bgr[0] * 1868 + bgr[1] * 9617 + bgr[2] * 4899 + (1 << 13)) >> 14);
}

// One stored row to BGR(A) pixels, four bytes a pixel (alpha 0 unless stored).
void expand_row(const Header& h, const unsigned char* in, unsigned char* bgra) {
  for (int c = 0; c < h.width; ++c, bgra += 4) {
    bgra[3] = 0;
    if (h.bits <= 8) {
      const int per_byte = 8 / h.bits;
      const int shift = 8 - h.bits * (c % per_byte + 1);
      const int index = (in[c / per_byte] >> shift) & ((1 << h.bits) - 1);
      std::memcpy(bgra, h.palette[index].data(), 3);
    } else if (h.bits == 15 || h.bits == 16) {
      const int t = in[2 * c] | (in[2 * c + 1] << 8);
      bgra[0] = static_cast<unsigned char>(t << 3);
      bgra[1] = static_cast<unsigned char>(h.bits == 15 ? (t >> 2) & ~7 : (t >> 3) & ~3);
      bgra[2] = static_cast<unsigned char>(h.bits == 15 ? (t >> 7) & ~7 : (t >> 8) & ~7);
    } else {
      const int n = h.bits / 8;
      std::memcpy(bgra, in + static_cast<std::size_t>(c) * n, static_cast<std::size_t>(n));
    }
  }
}


// Run-length coded pixels (RLE8, RLE4), written in stored row order with OpenCV's rules: a run may
// not cross the end of a row; end-of-line, delta and end-of-bitmap fill the skipped pixels with
// palette entry 0; an RLE8 run that ends a row moves to the next one, so that an end-of-line right
// after it is not a second line break. rows: stored order, one pixel = channels bytes.
class RleWriter {
 public:
  RleWriter(const Header& h, cv::Mat& rows) : h_(h), rows_(rows), channels_(rows.channels()) {}
  bool done() const { return y_ >= rows_.rows; }
  int left_in_row() const { return rows_.cols - x_; }
  int y() const { return y_; }
  void put(int index) {
    const unsigned char* bgr = h_.palette[index].data();
    unsigned char* out = rows_.ptr<unsigned char>(y_) + static_cast<std::size_t>(x_++) * channels_;
    if (channels_ == 1) {
      out[0] = grey_of(bgr);
    } else {
      std::memcpy(out, bgr, 3);
    }
  }
  // count pixels of palette entry index, continuing on the next rows (at least one step is taken,
  // so a full row moves on even when count is 0).
  void fill(long long count, int index) {
    do {
      const long long n = std::min<long long>(count, left_in_row());
      for (long long i = 0; i < n; ++i) put(index);
      count -= n;
      if (x_ >= rows_.cols) {
        x_ = 0;
        if (++y_ >= rows_.rows) break;
      }
    } while (count > 0);
  }

 private:
  const Header& h_;
  cv::Mat& rows_;
  int channels_;
  int x_ = 0, y_ = 0;
};

// The escape codes (end of line 0, end of bitmap 1, delta 2). Returns false once the image is full.
bool rle_escape(const Bytes& b, std::size_t& at, int code, bool rle8, bool& line_end_flag, RleWriter& out,
                int width, int height) {
  long long skip = out.left_in_row(), rows_down = height - out.y();
  if (rle8 && !(code != 0 || !line_end_flag || skip < width)) {  // end of line just after a full row
    line_end_flag = false;
    return true;
  }
  if (code == 2) {
    skip = b.at(at, 1)[0];
    rows_down = b.at(at + 1, 1)[0];
    at += 2;
  }
  if (rle8 && code != 0) skip += rows_down * width;  // RLE4 skips only within the row
  out.fill(skip, 0);
  line_end_flag = false;
  return !out.done();
}

void decode_rle(const Bytes& b, const Header& h, cv::Mat& rows) {
  const bool rle8 = h.compression == kRle8;
  RleWriter out(h, rows);
  std::size_t at = static_cast<std::size_t>(h.offset);
  bool line_end_flag = false;
  while (!out.done()) {
    const unsigned char* pair = b.at(at, 2);
    at += 2;
    const int count = pair[0], code = pair[1];
    if (count != 0) {  // a run of one index (RLE4: two alternating)
      if (count > out.left_in_row()) throw CodecError("a BMP run crosses the end of a row");
      const int y = out.y();
      if (rle8) {
        out.fill(count, code);
        line_end_flag = out.y() != y;
      } else {
        for (int i = 0; i < count; ++i) out.put(i % 2 ? code & 15 : code >> 4);
      }
    } else if (code > 2) {  // literal indices, padded to 16 bits
      if (code > out.left_in_row()) throw CodecError("a BMP run crosses the end of a row");
      const std::size_t size = rle8 ? (code + 1) & ~1 : (((code + 1) >> 1) + 1) & ~1;
      const unsigned char* in = b.at(at, size);
      at += size;
      for (int i = 0; i < code; ++i) out.put(rle8 ? in[i] : (i % 2 ? in[i / 2] & 15 : in[i / 2] >> 4));
      line_end_flag = false;
    } else if (!rle_escape(b, at, code, rle8, line_end_flag, out, rows.cols, rows.rows)) {
      break;
    }
  }
}
}  // namespace

cv::Mat decode_bmp(std::string_view bytes, const DecodeBounds& bounds) {
  const Bytes b(bytes);
  const Header h = read_header(b);
  check_decoded_size(static_cast<std::uint64_t>(h.width), static_cast<std::uint64_t>(h.height), bounds, "BMP");
  const int channels = !h.colour ? 1 : h.bits == 32 && h.compression == kBitfields ? 4 : 3;
  cv::Mat image(h.height, h.width, CV_8UC(channels));
  if (h.compression == kRle4 || h.compression == kRle8) {
    cv::Mat stored(h.height, h.width, image.type());
    decode_rle(b, h, stored);
    if (h.top_down) return stored;
    cv::flip(stored, image, 0);
    return image;
  }
  const std::size_t pitch = ((static_cast<std::size_t>(h.width) * (h.bits == 15 ? 16 : h.bits) + 7) / 8 + 3) & ~std::size_t{3};
  std::vector<unsigned char> bgra(static_cast<std::size_t>(h.width) * 4);
  for (int stored = 0; stored < h.height; ++stored) {
    expand_row(h, b.at(static_cast<std::size_t>(h.offset) + pitch * stored, pitch), bgra.data());
    unsigned char* out = image.ptr<unsigned char>(h.top_down ? stored : h.height - 1 - stored);
    for (int c = 0; c < h.width; ++c) {
      const unsigned char* px = &bgra[static_cast<std::size_t>(c) * 4];
      if (channels == 1) {
        out[c] = grey_of(px);
      } else {
        std::memcpy(out + static_cast<std::size_t>(c) * channels, px, static_cast<std::size_t>(channels));
      }
    }
  }
  return image;
}

std::string encode_bmp(const cv::Mat& image) {
  const int channels = image.channels();
  const std::size_t row = static_cast<std::size_t>(image.cols) * channels;
  const std::size_t pitch = (row + 3) & ~std::size_t{3};
  const std::uint32_t header = 14 + 40 + (channels > 1 ? 0 : 1024);
  std::string out;
  const auto put32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 255);
  };
  out += "BM";
  put32(static_cast<std::uint32_t>(pitch * image.rows + header));
  put32(0);
  put32(header);
  put32(40);
  put32(static_cast<std::uint32_t>(image.cols));
  put32(static_cast<std::uint32_t>(image.rows));
  put32(1u | (static_cast<std::uint32_t>(channels) << 3 << 16));  // planes, bits per pixel
  for (int i = 0; i < 6; ++i) put32(0);  // no compression, sizes, resolutions, colours
  if (channels == 1)
    for (int v = 0; v < 256; ++v) put32(static_cast<std::uint32_t>(v * 0x010101));
  for (int r = image.rows - 1; r >= 0; --r) {
    out.append(reinterpret_cast<const char*>(image.ptr(r)), row);
    out.append(pitch - row, '\0');
  }
  return out;
}

}  // namespace topocut::codecs
