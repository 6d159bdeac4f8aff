// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo-dev), decoded and encoded as OpenCV's JPEG
// codec did: grey stays grey, colour comes out BGR (CMYK converted), quality 95 when writing.
#include <csetjmp>
#include <cstdio>
#include <vector>

#include <jpeglib.h>
#include <jerror.h>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

// libjpeg reports a fatal error through error_exit, which must not return: the message is kept and
// control long-jumps back to the setjmp in the function that called libjpeg. Warnings and trace
// messages are dropped (output_message is never allowed to reach stderr).
struct JpegError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX] = "";
  bool scan_cut = false;  // the entropy-coded data stopped at a marker before the image was complete
  bool refused = false;   // a limit of ours, not libjpeg's error
};

void on_error(j_common_ptr cinfo) {
  auto* error = reinterpret_cast<JpegError*>(cinfo->err);
  cinfo->err->format_message(cinfo, error->message);
  std::longjmp(error->jump, 1);
}

void on_message(j_common_ptr) {}

void on_emit(j_common_ptr cinfo, int level) {
  if (level >= 0) return;  // trace messages
  ++cinfo->err->num_warnings;
  if (cinfo->err->msg_code == JWRN_HIT_MARKER) reinterpret_cast<JpegError*>(cinfo->err)->scan_cut = true;
}

void install(JpegError& error) {
  jpeg_std_error(&error.manager);
  error.manager.error_exit = on_error;
  error.manager.output_message = on_message;
  error.manager.emit_message = on_emit;
}

// libjpeg calls the progress monitor before it consumes each piece of input, so a scan beyond the
// limit is refused before its pass over the coefficients: an empty scan costs as much as a full one.
void limit_scans(j_common_ptr common) {
  auto* cinfo = reinterpret_cast<j_decompress_ptr>(common);
  if (cinfo->input_scan_number <= kMaxJpegScans) return;
  auto* error = reinterpret_cast<JpegError*>(common->err);
  std::snprintf(error->message, sizeof error->message,
                "the JPEG has more than %d scans, each a pass over the whole image (the limit)", kMaxJpegScans);
  error->refused = true;
  std::longjmp(error->jump, 1);
}

class Decompress {
 public:
  Decompress() {
    install(error_);
    cinfo_.err = &error_.manager;
    jpeg_create_decompress(&cinfo_);
    progress_.progress_monitor = limit_scans;
    cinfo_.progress = &progress_;
  }
  ~Decompress() { jpeg_destroy_decompress(&cinfo_); }
  Decompress(const Decompress&) = delete;
  Decompress& operator=(const Decompress&) = delete;
  jpeg_decompress_struct cinfo_{};
  JpegError error_;
  jpeg_progress_mgr progress_{};
};

class Compress {
 public:
  Compress() {
    install(error_);
    cinfo_.err = &error_.manager;
    jpeg_create_compress(&cinfo_);
  }
  ~Compress() {
    jpeg_destroy_compress(&cinfo_);
    std::free(buffer_);
  }
  Compress(const Compress&) = delete;
  Compress& operator=(const Compress&) = delete;
  jpeg_compress_struct cinfo_{};
  JpegError error_;
  unsigned char* buffer_ = nullptr;
  unsigned long size_ = 0;
};

// Where the data ends before the decoder is done: an end-of-image marker is supplied (as libjpeg's
// own memory source does) and the fact recorded, so that a file lacking only its final marker still
// decodes (as it did with OpenCV) while one cut inside the scan (the data ended and the decoder hit
// that marker early) is refused instead of giving rows of made-up pixels.
boolean end_of_data(j_decompress_ptr cinfo) {
  static const JOCTET end_of_image[2] = {0xFF, JPEG_EOI};
  *static_cast<bool*>(cinfo->client_data) = true;
  cinfo->src->next_input_byte = end_of_image;
  cinfo->src->bytes_in_buffer = 2;
  return TRUE;
}

// Phase 1: the header and the output colour space (grey, RGB, or CMYK to be converted).
bool read_header(Decompress& d, std::string_view bytes, bool& ended) {
  if (setjmp(d.error_.jump)) return false;
  jpeg_mem_src(&d.cinfo_, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<unsigned long>(bytes.size()));
  d.cinfo_.client_data = &ended;
  d.cinfo_.src->fill_input_buffer = end_of_data;
  jpeg_read_header(&d.cinfo_, TRUE);
  if (d.cinfo_.num_components == 1) {
    d.cinfo_.out_color_space = JCS_GRAYSCALE;
  } else if (d.cinfo_.num_components == 4) {
    d.cinfo_.out_color_space = JCS_CMYK;
  } else {
    d.cinfo_.out_color_space = JCS_EXT_BGR;
  }
  return true;
}

// Phase 2: the scanlines, into rows (BGR, grey or CMYK). False if libjpeg fails or the data ends
// before the last row.
bool read_scanlines(Decompress& d, unsigned char** rows, int height, const bool& ended) {
  if (setjmp(d.error_.jump)) return false;
  jpeg_start_decompress(&d.cinfo_);
  for (int y = 0; y < height;) {
    const JDIMENSION n = jpeg_read_scanlines(&d.cinfo_, rows + y, static_cast<JDIMENSION>(height - y));
    if (n == 0) break;
    y += static_cast<int>(n);
  }
  if (ended && d.error_.scan_cut) {
    std::snprintf(d.error_.message, sizeof d.error_.message, "the JPEG data ends early");
    return false;
  }
  jpeg_finish_decompress(&d.cinfo_);
  return true;
}

// The conversion OpenCV applied to Adobe-style (inverted) CMYK samples.
void cmyk_to_bgr(const cv::Mat& cmyk, cv::Mat& bgr) {
  for (int r = 0; r < cmyk.rows; ++r) {
    const unsigned char* in = cmyk.ptr<unsigned char>(r);
    unsigned char* out = bgr.ptr<unsigned char>(r);
    for (int c = 0; c < cmyk.cols; ++c, in += 4, out += 3) {
      const int k = in[3];
      out[2] = static_cast<unsigned char>(k - ((255 - in[0]) * k >> 8));
      out[1] = static_cast<unsigned char>(k - ((255 - in[1]) * k >> 8));
      out[0] = static_cast<unsigned char>(k - ((255 - in[2]) * k >> 8));
    }
  }
}

std::vector<unsigned char*> row_pointers(cv::Mat& image) {
  std::vector<unsigned char*> rows(static_cast<std::size_t>(image.rows));
  for (int r = 0; r < image.rows; ++r) rows[static_cast<std::size_t>(r)] = image.ptr(r);
  return rows;
}

bool write_scanlines(Compress& e, const cv::Mat& image, unsigned char** rows) {
  if (setjmp(e.error_.jump)) return false;
  jpeg_mem_dest(&e.cinfo_, &e.buffer_, &e.size_);
  e.cinfo_.image_width = static_cast<JDIMENSION>(image.cols);
  e.cinfo_.image_height = static_cast<JDIMENSION>(image.rows);
  const bool colour = image.channels() > 1;
  e.cinfo_.input_components = colour ? 3 : 1;
  e.cinfo_.in_color_space = colour ? JCS_RGB : JCS_GRAYSCALE;
  jpeg_set_defaults(&e.cinfo_);
  e.cinfo_.restart_interval = 0;
  jpeg_set_quality(&e.cinfo_, 95, TRUE);
  e.cinfo_.in_color_space = colour ? (image.channels() == 4 ? JCS_EXT_BGRX : JCS_EXT_BGR) : JCS_GRAYSCALE;
  e.cinfo_.input_components = image.channels();
  jpeg_start_compress(&e.cinfo_, TRUE);
  jpeg_write_scanlines(&e.cinfo_, rows, static_cast<JDIMENSION>(image.rows));
  jpeg_finish_compress(&e.cinfo_);
  return true;
}

// libjpeg's error, or our refusal, as the exception decode_image() reports.
[[noreturn]] void fail(const JpegError& error) {
  if (error.refused) throw CodecRefusal(error.message);
  throw CodecError(error.message);
}

}  // namespace

cv::Mat decode_jpeg(std::string_view bytes, const DecodeBounds& bounds) {
  Decompress d;
  bool ended = false;
  if (!read_header(d, bytes, ended)) fail(d.error_);
  check_decoded_size(d.cinfo_.image_width, d.cinfo_.image_height, bounds, "JPEG");
  const int height = static_cast<int>(d.cinfo_.image_height), width = static_cast<int>(d.cinfo_.image_width);
  const int stored = d.cinfo_.out_color_space == JCS_GRAYSCALE ? 1 : d.cinfo_.out_color_space == JCS_CMYK ? 4 : 3;
  cv::Mat decoded(height, width, CV_8UC(stored), cv::Scalar::all(0));
  std::vector<unsigned char*> rows = row_pointers(decoded);
  if (!read_scanlines(d, rows.data(), height, ended)) fail(d.error_);
  if (stored != 4) return decoded;
  cv::Mat bgr(height, width, CV_8UC3);
  cmyk_to_bgr(decoded, bgr);
  return bgr;
}

std::string encode_jpeg(const cv::Mat& image) {
  Compress e;
  cv::Mat pixels = image;
  std::vector<unsigned char*> rows = row_pointers(pixels);
  if (!write_scanlines(e, image, rows.data())) throw CodecError(e.error_.message);
  return std::string(reinterpret_cast<const char*>(e.buffer_), e.size_);
}

}  // namespace topocut::codecs
