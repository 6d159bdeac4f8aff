// PNG through libpng (Debian's libpng-dev), with the transformations OpenCV's PNG codec used, so the
// pixels are those cv::imdecode gave and the encoded bytes those cv::imencode wrote.
#include <cstdio>
#include <cstring>
#include <vector>

#include <png.h>
#include <zlib.h>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

// libpng reports an error by calling error_fn, which must not return: it keeps the message and
// long-jumps back to the setjmp in the (C-only) function that called libpng. Warnings (for
// example an ancillary chunk's CRC or a known-incorrect sRGB profile) did not stop OpenCV's decoder
// either; they are dropped so that nothing reaches stderr.
struct PngContext {
  std::string_view input;
  std::size_t position = 0;
  std::string* output = nullptr;
  char message[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* context = static_cast<PngContext*>(png_get_error_ptr(png));
  std::snprintf(context->message, sizeof context->message, "%s", message ? message : "libpng error");
  png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

void read_input(png_structp png, png_bytep out, png_size_t n) {
  auto* context = static_cast<PngContext*>(png_get_io_ptr(png));
  if (n > context->input.size() - context->position) png_error(png, "the PNG data ends early");
  std::memcpy(out, context->input.data() + context->position, n);
  context->position += n;
}

void write_output(png_structp png, png_bytep data, png_size_t n) {
  static_cast<PngContext*>(png_get_io_ptr(png))->output->append(reinterpret_cast<const char*>(data), n);
}

void flush_output(png_structp) {}

struct PngImage {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0, channels = 0;
};

// Phase 1: the header, and the channel count OpenCV chose for it (palette and RGB with a tRNS
// chunk, grey+alpha and RGBA become BGRA; grey, even with tRNS, stays one channel).
bool read_header(png_structp png, png_infop info, PngImage& image) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  int interlace = 0, compression = 0, filter = 0;
  png_get_IHDR(png, info, &image.width, &image.height, &image.bit_depth, &image.colour_type, &interlace, &compression,
               &filter);
  png_bytep trans = nullptr;
  int num_trans = 0;
  png_color_16p trans_values = nullptr;
  switch (image.colour_type) {
    case PNG_COLOR_TYPE_RGB:
    case PNG_COLOR_TYPE_PALETTE:
      png_get_tRNS(png, info, &trans, &num_trans, &trans_values);
      image.channels = num_trans > 0 ? 4 : 3;
      break;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
    case PNG_COLOR_TYPE_RGB_ALPHA: image.channels = 4; break;
    default: image.channels = 1;
  }
  return true;
}

// Phase 2: the rows, expanded to 8 or 16 bits, BGR order (bgr false: the file's RGB), little-endian
// 16-bit samples.
bool read_rows(png_structp png, png_infop info, const PngImage& image, bool bgr, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  if (image.bit_depth == 16) png_set_swap(png);
  if (image.channels < 4) {
    png_set_strip_alpha(png);
  } else {
    png_set_tRNS_to_alpha(png);
  }
  if (image.colour_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if ((image.colour_type & PNG_COLOR_MASK_COLOR) == 0 && image.bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (image.colour_type & PNG_COLOR_MASK_COLOR) {
    if (bgr) png_set_bgr(png);
  } else if (image.channels > 1) {
    png_set_gray_to_rgb(png);
  }
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

// OpenCV's settings when no parameter is given: the SUB filter, zlib level 1 and the RLE strategy.
bool write_png(png_structp png, png_infop info, const cv::Mat& image, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_compression_strategy(png, Z_RLE);
  const int channels = image.channels();
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.cols), static_cast<png_uint_32>(image.rows),
               image.depth() == CV_8U ? 8 : 16,
               channels == 1 ? PNG_COLOR_TYPE_GRAY : channels == 3 ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_set_bgr(png);
  png_set_swap(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

// libpng's read or write state and its info struct, destroyed together.
class PngStruct {
 public:
  PngStruct(PngContext& context, bool write) : write_(write) {
    png_ = write ? png_create_write_struct(PNG_LIBPNG_VER_STRING, &context, on_error, on_warning)
                 : png_create_read_struct(PNG_LIBPNG_VER_STRING, &context, on_error, on_warning);
    info_ = png_ ? png_create_info_struct(png_) : nullptr;
    if (!png_ || !info_) {
      destroy();
      throw CodecError("libpng could not start");
    }
    if (write) {
      png_set_write_fn(png_, &context, write_output, flush_output);
    } else {
      png_set_read_fn(png_, &context, read_input);
    }
  }
  ~PngStruct() { destroy(); }
  PngStruct(const PngStruct&) = delete;
  PngStruct& operator=(const PngStruct&) = delete;
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

 private:
  void destroy() {
    if (write_) {
      png_destroy_write_struct(&png_, &info_);
    } else {
      png_destroy_read_struct(&png_, &info_, nullptr);
    }
  }
  bool write_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

std::vector<png_bytep> row_pointers(const cv::Mat& image) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(image.rows));
  for (int r = 0; r < image.rows; ++r) rows[static_cast<std::size_t>(r)] = const_cast<png_bytep>(image.ptr(r));
  return rows;
}

// The pixels of a PNG, in BGR order or (bgr false) the file's own.
cv::Mat decoded_png(std::string_view bytes, const DecodeBounds& bounds, bool bgr) {
  PngContext context;
  context.input = bytes;
  const PngStruct reader(context, false);
  // zlib's Adler-32 of the inflated rows is not checked: every chunk's CRC-32 already rejects a
  // damaged file, and the sum cost an eighth of a large map's decoding (office_g furnished: 68 of
  // 510 M instructions).
  png_set_option(reader.png(), PNG_IGNORE_ADLER32, PNG_OPTION_ON);
  PngImage header;
  if (!read_header(reader.png(), reader.info(), header)) throw CodecError(context.message);
  check_decoded_size(header.width, header.height, bounds, "PNG");
  cv::Mat image(static_cast<int>(header.height), static_cast<int>(header.width),
                CV_MAKETYPE(header.bit_depth == 16 ? CV_16U : CV_8U, header.channels));
  std::vector<png_bytep> rows = row_pointers(image);
  if (!read_rows(reader.png(), reader.info(), header, bgr, rows.data())) throw CodecError(context.message);
  return image;
}

}  // namespace

cv::Mat decode_png(std::string_view bytes, const DecodeBounds& bounds) { return decoded_png(bytes, bounds, true); }

cv::Mat decode_png_rgb(std::string_view bytes, const DecodeBounds& bounds) { return decoded_png(bytes, bounds, false); }

std::string encode_png(const cv::Mat& image) {
  std::string out;
  PngContext context;
  context.output = &out;
  const PngStruct writer(context, true);
  std::vector<png_bytep> rows = row_pointers(image);
  if (!write_png(writer.png(), writer.info(), image, rows.data())) throw CodecError(context.message);
  return out;
}

}  // namespace topocut::codecs
