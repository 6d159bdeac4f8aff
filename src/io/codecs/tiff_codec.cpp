// TIFF through libtiff (Debian's libtiff-dev), in OpenCV's layout: 8-bit and smaller samples through
// libtiff's RGBA reader (palette, bilevel, YCbCr and min-is-white handled there) as grey, BGR or
// BGRA by the samples per pixel; 16-bit grey, RGB and RGBA read as stored, in BGR(A) order. Errors
// and warnings go to per-handle handlers, never to stderr.
//
// libtiff is opened with dlopen() on the first TIFF, not linked: it brings seven more shared
// libraries (WebP, Zstandard, LZMA, LERC, JBIG, libdeflate), which cost every topocut process about
// 3-4 ms of CPU at start-up (10 % of `topocut --version`, benchmarks/README.md "Start-up") while
// maps are almost never TIFF.
#include <dlfcn.h>

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include <tiffio.h>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

// The libtiff functions used here, resolved once from the shared library named at build time.
struct LibTiff {
  decltype(&TIFFOpenOptionsAlloc) OpenOptionsAlloc = nullptr;
  decltype(&TIFFOpenOptionsFree) OpenOptionsFree = nullptr;
  decltype(&TIFFOpenOptionsSetErrorHandlerExtR) SetErrorHandler = nullptr;
  decltype(&TIFFOpenOptionsSetWarningHandlerExtR) SetWarningHandler = nullptr;
  decltype(&TIFFClientOpenExt) ClientOpenExt = nullptr;
  decltype(&TIFFClose) Close = nullptr;
  decltype(&TIFFGetField) GetField = nullptr;
  decltype(&TIFFGetFieldDefaulted) GetFieldDefaulted = nullptr;
  decltype(&TIFFSetField) SetField = nullptr;
  decltype(&TIFFReadRGBAImageOriented) ReadRGBAImageOriented = nullptr;
  decltype(&TIFFIsTiled) IsTiled = nullptr;
  decltype(&TIFFScanlineSize) ScanlineSize = nullptr;
  decltype(&TIFFReadScanline) ReadScanline = nullptr;
  decltype(&TIFFWriteScanline) WriteScanline = nullptr;
  decltype(&TIFFDefaultStripSize) DefaultStripSize = nullptr;
  bool complete = false;
};

template <typename F>
bool resolve(void* library, const char* name, F& f) {
  f = reinterpret_cast<F>(::dlsym(library, name));
  return f != nullptr;
}

LibTiff load_libtiff() {
  LibTiff t;
  void* library = ::dlopen(TOPOCUT_LIBTIFF_SONAME, RTLD_NOW | RTLD_LOCAL);
  if (!library) return t;
  t.complete = resolve(library, "TIFFOpenOptionsAlloc", t.OpenOptionsAlloc) &&
               resolve(library, "TIFFOpenOptionsFree", t.OpenOptionsFree) &&
               resolve(library, "TIFFOpenOptionsSetErrorHandlerExtR", t.SetErrorHandler) &&
               resolve(library, "TIFFOpenOptionsSetWarningHandlerExtR", t.SetWarningHandler) &&
               resolve(library, "TIFFClientOpenExt", t.ClientOpenExt) && resolve(library, "TIFFClose", t.Close) &&
               resolve(library, "TIFFGetField", t.GetField) &&
               resolve(library, "TIFFGetFieldDefaulted", t.GetFieldDefaulted) &&
               resolve(library, "TIFFSetField", t.SetField) &&
               resolve(library, "TIFFReadRGBAImageOriented", t.ReadRGBAImageOriented) &&
               resolve(library, "TIFFIsTiled", t.IsTiled) && resolve(library, "TIFFScanlineSize", t.ScanlineSize) &&
               resolve(library, "TIFFReadScanline", t.ReadScanline) &&
               resolve(library, "TIFFWriteScanline", t.WriteScanline) &&
               resolve(library, "TIFFDefaultStripSize", t.DefaultStripSize);
  return t;  // the library stays loaded for the process's lifetime
}

const LibTiff& libtiff() {
  static const LibTiff t = load_libtiff();
  if (!t.complete) throw CodecError("TIFF needs " TOPOCUT_LIBTIFF_SONAME " (Debian package libtiff6)");
  return t;
}

struct Memory {
  std::string_view input;
  std::string* output = nullptr;
  toff_t position = 0;
  std::string message;
};

tmsize_t read_memory(thandle_t h, void* out, tmsize_t n) {
  auto* m = static_cast<Memory*>(h);
  if (m->position >= m->input.size()) return 0;
  const tmsize_t available = static_cast<tmsize_t>(m->input.size() - m->position);
  const tmsize_t k = n < available ? n : available;
  std::memcpy(out, m->input.data() + m->position, static_cast<std::size_t>(k));
  m->position += static_cast<toff_t>(k);
  return k;
}

tmsize_t write_memory(thandle_t h, void* data, tmsize_t n) {
  auto* m = static_cast<Memory*>(h);
  if (m->output->size() < m->position + n) m->output->resize(m->position + n);
  std::memcpy(m->output->data() + m->position, data, static_cast<std::size_t>(n));
  m->position += static_cast<toff_t>(n);
  return n;
}

toff_t seek_memory(thandle_t h, toff_t offset, int whence) {
  auto* m = static_cast<Memory*>(h);
  const toff_t size = m->output ? m->output->size() : m->input.size();
  m->position = whence == SEEK_SET ? offset : whence == SEEK_CUR ? m->position + offset : size + offset;
  return m->position;
}

int close_memory(thandle_t) { return 0; }
toff_t size_memory(thandle_t h) {
  auto* m = static_cast<Memory*>(h);
  return m->output ? m->output->size() : m->input.size();
}
int map_memory(thandle_t, void**, toff_t*) { return 0; }
void unmap_memory(thandle_t, void*, toff_t) {}

int on_error(TIFF*, void* user, const char*, const char* format, va_list args) {
  auto* m = static_cast<Memory*>(user);
  if (m->message.empty()) {
    char text[256];
    std::vsnprintf(text, sizeof text, format, args);
    m->message = text;
  }
  return 1;  // handled: libtiff's global handler (stderr) is not called
}

int on_warning(TIFF*, void*, const char*, const char*, va_list) { return 1; }

class Handle {
 public:
  Handle(Memory& memory, const char* mode) {
    const LibTiff& lib = libtiff();
    TIFFOpenOptions* options = lib.OpenOptionsAlloc();
    lib.SetErrorHandler(options, on_error, &memory);
    lib.SetWarningHandler(options, on_warning, &memory);
    tiff_ = lib.ClientOpenExt("image", mode, &memory, read_memory, write_memory, seek_memory, close_memory,
                              size_memory, map_memory, unmap_memory, options);
    lib.OpenOptionsFree(options);
    if (!tiff_) throw CodecError(memory.message.empty() ? "not a readable TIFF" : memory.message);
  }
  ~Handle() {
    if (tiff_) libtiff().Close(tiff_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  TIFF* get() const { return tiff_; }

 private:
  TIFF* tiff_ = nullptr;
};

void fail(const Memory& memory, const char* fallback) {
  throw CodecError(memory.message.empty() ? fallback : memory.message);
}

cv::Mat read_rgba(TIFF* tiff, Memory& memory, int width, int height, int channels) {
  std::vector<std::uint32_t> rgba(static_cast<std::size_t>(width) * height);
  if (!libtiff().ReadRGBAImageOriented(tiff, static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), rgba.data(),
                                 ORIENTATION_TOPLEFT, 0))
    fail(memory, "the TIFF data does not decode");
  cv::Mat image(height, width, CV_8UC(channels));
  for (int r = 0; r < height; ++r) {
    unsigned char* out = image.ptr<unsigned char>(r);
    for (int c = 0; c < width; ++c, out += channels) {
      const std::uint32_t p = rgba[static_cast<std::size_t>(r) * width + c];
      const unsigned char bgra[4] = {static_cast<unsigned char>(TIFFGetB(p)), static_cast<unsigned char>(TIFFGetG(p)),
                                     static_cast<unsigned char>(TIFFGetR(p)), static_cast<unsigned char>(TIFFGetA(p))};
      if (channels == 1) {  // OpenCV's weighted grey, exact for the equal channels of a grey image
        out[0] = static_cast<unsigned char>((bgra[0] * 1868 + bgra[1] * 9617 + bgra[2] * 4899 + (1 << 13)) >> 14);
      } else {
        std::memcpy(out, bgra, static_cast<std::size_t>(channels));
      }
    }
  }
  return image;
}

cv::Mat read_sixteen(TIFF* tiff, Memory& memory, int width, int height, int channels) {
  std::uint16_t planar = PLANARCONFIG_CONTIG;
  libtiff().GetFieldDefaulted(tiff, TIFFTAG_PLANARCONFIG, &planar);
  if (planar != PLANARCONFIG_CONTIG || libtiff().IsTiled(tiff)) throw CodecError("unsupported 16-bit TIFF layout");
  cv::Mat image(height, width, CV_16UC(channels));
  if (libtiff().ScanlineSize(tiff) != static_cast<tmsize_t>(image.cols * image.elemSize())) throw CodecError("bad TIFF row size");
  for (int r = 0; r < height; ++r) {
    auto* row = image.ptr<std::uint16_t>(r);
    if (libtiff().ReadScanline(tiff, row, static_cast<std::uint32_t>(r), 0) < 0) fail(memory, "the TIFF data does not decode");
    if (channels >= 3)
      for (int c = 0; c < width; ++c) std::swap(row[c * channels], row[c * channels + 2]);
  }
  return image;
}

}  // namespace

cv::Mat decode_tiff(std::string_view bytes) {
  Memory memory;
  memory.input = bytes;
  const Handle handle(memory, "rm");
  TIFF* tiff = handle.get();
  std::uint32_t width = 0, height = 0;
  std::uint16_t photometric = 0, bits = 1, samples = 1, format = SAMPLEFORMAT_UINT;
  if (!libtiff().GetField(tiff, TIFFTAG_IMAGEWIDTH, &width) || !libtiff().GetField(tiff, TIFFTAG_IMAGELENGTH, &height) ||
      !libtiff().GetField(tiff, TIFFTAG_PHOTOMETRIC, &photometric))
    fail(memory, "the TIFF header lacks its size or photometric tag");
  libtiff().GetField(tiff, TIFFTAG_BITSPERSAMPLE, &bits);
  libtiff().GetField(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples);
  libtiff().GetField(tiff, TIFFTAG_SAMPLEFORMAT, &format);
  const bool grey = photometric == PHOTOMETRIC_MINISWHITE || photometric == PHOTOMETRIC_MINISBLACK;
  const int channels = photometric == PHOTOMETRIC_PALETTE ? 3 : samples >= 4 ? 4 : samples == 3 ? 3 : 1;
  if (format != SAMPLEFORMAT_UINT) throw CodecError("only unsigned integer TIFF samples are supported");
  if (bits <= 8) return read_rgba(tiff, memory, static_cast<int>(width), static_cast<int>(height), channels);
  if (bits == 16 && (grey ? samples == 1 : samples == 3 || samples == 4))
    return read_sixteen(tiff, memory, static_cast<int>(width), static_cast<int>(height), grey ? 1 : samples);
  throw CodecError("unsupported TIFF layout");
}

std::string encode_tiff(const cv::Mat& image) {
  std::string out;
  Memory memory;
  memory.output = &out;
  {
    const Handle handle(memory, "w");
    TIFF* tiff = handle.get();
    const int channels = image.channels();
    libtiff().SetField(tiff, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(image.cols));
    libtiff().SetField(tiff, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(image.rows));
    libtiff().SetField(tiff, TIFFTAG_BITSPERSAMPLE, static_cast<std::uint16_t>(image.elemSize1() * 8));
    libtiff().SetField(tiff, TIFFTAG_SAMPLESPERPIXEL, static_cast<std::uint16_t>(channels));
    libtiff().SetField(tiff, TIFFTAG_PHOTOMETRIC, channels > 1 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
    libtiff().SetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    libtiff().SetField(tiff, TIFFTAG_COMPRESSION, COMPRESSION_LZW);
    if (channels == 4) {
      const std::uint16_t extra = EXTRASAMPLE_ASSOCALPHA;
      libtiff().SetField(tiff, TIFFTAG_EXTRASAMPLES, 1, &extra);
    }
    libtiff().SetField(tiff, TIFFTAG_ROWSPERSTRIP, libtiff().DefaultStripSize(tiff, 0));
    cv::Mat row(1, image.cols, image.type());
    for (int r = 0; r < image.rows; ++r) {
      const cv::Mat source = image.row(r);
      source.copyTo(row);
      if (channels >= 3) {  // BGR(A) in memory, RGB(A) in the file
        const int from_to[] = {0, 2, 1, 1, 2, 0, 3, 3};
        cv::mixChannels(&source, 1, &row, 1, from_to, static_cast<std::size_t>(channels));
      }
      if (libtiff().WriteScanline(tiff, row.ptr(), static_cast<std::uint32_t>(r), 0) < 0) fail(memory, "libtiff could not write");
    }
  }
  return out;
}

}  // namespace topocut::codecs
