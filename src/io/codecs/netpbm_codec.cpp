// PBM/PGM/PPM, binary and ASCII, 8 and 16 bit. Hand-written: Debian's libnetpbm reads whole files
// through stdio with its own exit-on-error handling and different sample scaling, and the format is a
// text header over raw samples; the rules below are those OpenCV's reader applied (binary samples
// are taken as stored whatever the maximum value, ASCII 8-bit samples are scaled to 0..255, ASCII
// 16-bit samples are kept, values above the maximum are clamped, PBM's 1 is black).
#include <cctype>
#include <climits>
#include <cstdio>
#include <cstring>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  int byte() {
    if (at_ >= bytes_.size()) throw CodecError("the Netpbm data ends early");
    return static_cast<unsigned char>(bytes_[at_++]);
  }
  int peek() const { return at_ < bytes_.size() ? static_cast<unsigned char>(bytes_[at_]) : -1; }
  const unsigned char* take(std::size_t n) {
    if (n > bytes_.size() - at_) throw CodecError("the Netpbm data ends early");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at_);
    at_ += n;
    return p;
  }
  // A decimal number after white space and # comments; the byte after it is consumed. max_digits
  // 1 reads PBM's ASCII samples, which need no separator.
  int number(int max_digits = 0) {
    int c = byte();
    while (!std::isdigit(c)) {
      if (c == '#') {
        do c = byte();
        while (c != '\n' && c != '\r');
        c = byte();
      } else if (std::isspace(c)) {
        while (std::isspace(c)) c = byte();
      } else {
        throw CodecError("unexpected character in Netpbm data");
      }
    }
    long long value = 0;
    int digits = 0;
    do {
      value = value * 10 + (c - '0');
      if (value > INT_MAX) throw CodecError("a Netpbm number is too large");
      if (max_digits != 0 && ++digits >= max_digits) break;
      c = byte();
    } while (std::isdigit(c));
    return static_cast<int>(value);
  }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

struct Header {
  int bits = 8;  // per pixel: 1 (PBM), 8 (PGM), 24 (PPM)
  bool binary = true;
  int width = 0, height = 0, maxval = 1;
};

Header read_header(Reader& in) {
  if (in.byte() != 'P') throw CodecError("not a Netpbm file");
  const int code = in.byte();
  if (code < '1' || code > '6' || !std::isspace(in.peek())) throw CodecError("not a PBM, PGM or PPM file");
  Header h;
  h.bits = code == '1' || code == '4' ? 1 : code == '2' || code == '5' ? 8 : 24;
  h.binary = code >= '4';
  h.width = in.number();
  h.height = in.number();
  if (h.bits > 1) h.maxval = in.number();
  if (h.width <= 0 || h.height <= 0 || h.maxval <= 0 || h.maxval > 65535) throw CodecError("bad Netpbm header");
  return h;
}

void read_bitmap(Reader& in, const Header& h, cv::Mat& image) {
  const std::size_t pitch = (static_cast<std::size_t>(h.width) + 7) / 8;
  for (int r = 0; r < h.height; ++r) {
    unsigned char* out = image.ptr<unsigned char>(r);
    if (h.binary) {
      const unsigned char* bits = in.take(pitch);
      for (int c = 0; c < h.width; ++c) out[c] = (bits[c / 8] >> (7 - c % 8)) & 1 ? 0 : 255;
    } else {
      for (int c = 0; c < h.width; ++c) out[c] = in.number(1) != 0 ? 0 : 255;
    }
  }
}

template <typename T>
void read_samples(Reader& in, const Header& h, cv::Mat& image) {
  const int channels = image.channels();
  const std::size_t samples = static_cast<std::size_t>(h.width) * channels;
  for (int r = 0; r < h.height; ++r) {
    T* out = image.ptr<T>(r);
    if (h.binary) {
      const unsigned char* raw = in.take(samples * sizeof(T));
      for (std::size_t i = 0; i < samples; ++i)
        out[i] = sizeof(T) == 1 ? raw[i] : static_cast<T>((raw[2 * i] << 8) | raw[2 * i + 1]);
    } else {
      for (std::size_t i = 0; i < samples; ++i) {
        const int code = std::min(in.number(), h.maxval);
        out[i] = sizeof(T) == 1 ? static_cast<T>(code * 255 / h.maxval) : static_cast<T>(code);
      }
    }
    if (channels == 3)  // stored RGB, kept BGR
      for (int c = 0; c < h.width; ++c) std::swap(out[3 * c], out[3 * c + 2]);
  }
}

}  // namespace

cv::Mat decode_netpbm(std::string_view bytes, const DecodeBounds& bounds) {
  Reader in(bytes);
  const Header h = read_header(in);
  check_decoded_size(static_cast<std::uint64_t>(h.width), static_cast<std::uint64_t>(h.height), bounds, "PGM/PPM");
  const int depth = h.maxval > 255 ? CV_16U : CV_8U;
  cv::Mat image(h.height, h.width, CV_MAKETYPE(depth, h.bits == 24 ? 3 : 1));
  if (h.bits == 1) {
    read_bitmap(in, h, image);
  } else if (depth == CV_8U) {
    read_samples<unsigned char>(in, h, image);
  } else {
    read_samples<unsigned short>(in, h, image);
  }
  return image;
}

std::string encode_netpbm(const cv::Mat& image, NetpbmKind kind) {
  const int channels = image.channels();
  if (kind == NetpbmKind::kAuto) kind = channels == 1 ? NetpbmKind::kPgm : NetpbmKind::kPpm;
  if (kind == NetpbmKind::kPbm) throw CodecError("writing PBM is not supported");
  if (kind == NetpbmKind::kPgm && channels != 1) throw CodecError("a PGM image has one channel");
  if (kind == NetpbmKind::kPpm && channels != 3) throw CodecError("a PPM image has three channels");
  const bool sixteen = image.depth() == CV_16U;
  char header[64];
  const int n = std::snprintf(header, sizeof header, "P%c\n%d %d\n%d\n", kind == NetpbmKind::kPpm ? '6' : '5',
                              image.cols, image.rows, sixteen ? 65535 : 255);
  std::string out(header, static_cast<std::size_t>(n));
  const std::size_t samples = static_cast<std::size_t>(image.cols) * channels;
  out.reserve(out.size() + samples * image.rows * (sixteen ? 2 : 1));
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      for (int k = 0; k < channels; ++k) {
        const int from = channels == 3 ? 2 - k : k;  // BGR in memory, RGB in the file
        const std::size_t i = static_cast<std::size_t>(c) * channels + from;
        if (sixteen) {
          const unsigned short v = image.ptr<unsigned short>(r)[i];
          out += static_cast<char>(v >> 8);
          out += static_cast<char>(v & 255);
        } else {
          out += static_cast<char>(image.ptr<unsigned char>(r)[i]);
        }
      }
    }
  }
  return out;
}

}  // namespace topocut::codecs
