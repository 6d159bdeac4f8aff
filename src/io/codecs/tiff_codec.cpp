// TIFF through libtiff (Debian's libtiff-dev), in OpenCV's layout: 8-bit and smaller samples through
// libtiff's RGBA reader (palette, bilevel, YCbCr and min-is-white handled there) as grey, BGR or
// BGRA by the samples per pixel; 16-bit grey, RGB and RGBA read as stored, in BGR(A) order. Errors
// and warnings go to per-handle handlers, never to stderr.
//
// libtiff is opened with dlopen() on the first TIFF, not linked: its seven dependent libraries would
// slow every process's start-up (benchmarks/README.md, "Start-up") while maps are almost never TIFF.
#include <dlfcn.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <tiffio.h>

#include "io/codecs/codecs.h"

namespace topocut::codecs {
namespace {

// A TIFF is read in strips or tiles, each with its own decoder set-up and seek: their number bounds
// the work beyond the pixels (a 16 x 16 tiling of 268 megapixels).
constexpr std::uint64_t kMaxTiffBlocks = 1u << 20;
// A strip or tile may exceed the image it covers (a 256 x 256 tile of a 10 x 10 image) up to this.
constexpr std::uint64_t kMinTiffBlockLimit = 1u << 20;

// libtiff's largest single allocation (the strip or tile offsets, a decoded block): the bound of
// the image file itself, 8 bytes a pixel plus 1 MiB.
tmsize_t max_tiff_allocation(const DecodeBounds& bounds) {
  return static_cast<tmsize_t>(8 * bounds.width * bounds.height + (1u << 20));
}

// The libtiff functions used here, resolved once from the shared library named at build time.
struct LibTiff {
  decltype(&TIFFOpenOptionsAlloc) OpenOptionsAlloc = nullptr;
  decltype(&TIFFOpenOptionsFree) OpenOptionsFree = nullptr;
  decltype(&TIFFOpenOptionsSetErrorHandlerExtR) SetErrorHandler = nullptr;
  decltype(&TIFFOpenOptionsSetWarningHandlerExtR) SetWarningHandler = nullptr;
  decltype(&TIFFOpenOptionsSetMaxSingleMemAlloc) SetMaxSingleMemAlloc = nullptr;
  decltype(&TIFFClientOpenExt) ClientOpenExt = nullptr;
  decltype(&TIFFClose) Close = nullptr;
  decltype(&TIFFGetField) GetField = nullptr;
  decltype(&TIFFGetFieldDefaulted) GetFieldDefaulted = nullptr;
  decltype(&TIFFSetField) SetField = nullptr;
  decltype(&TIFFReadRGBAImageOriented) ReadRGBAImageOriented = nullptr;
  decltype(&TIFFIsTiled) IsTiled = nullptr;
  decltype(&TIFFTileSize64) TileSize = nullptr;
  decltype(&TIFFStripSize64) StripSize = nullptr;
  decltype(&TIFFNumberOfTiles) NumberOfTiles = nullptr;
  decltype(&TIFFNumberOfStrips) NumberOfStrips = nullptr;
  decltype(&TIFFReadEncodedTile) ReadEncodedTile = nullptr;
  decltype(&TIFFReadEncodedStrip) ReadEncodedStrip = nullptr;
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
               resolve(library, "TIFFOpenOptionsSetMaxSingleMemAlloc", t.SetMaxSingleMemAlloc) &&
               resolve(library, "TIFFClientOpenExt", t.ClientOpenExt) && resolve(library, "TIFFClose", t.Close) &&
               resolve(library, "TIFFGetField", t.GetField) &&
               resolve(library, "TIFFGetFieldDefaulted", t.GetFieldDefaulted) &&
               resolve(library, "TIFFSetField", t.SetField) &&
               resolve(library, "TIFFReadRGBAImageOriented", t.ReadRGBAImageOriented) &&
               resolve(library, "TIFFIsTiled", t.IsTiled) &&
               resolve(library, "TIFFTileSize64", t.TileSize) && resolve(library, "TIFFStripSize64", t.StripSize) &&
               resolve(library, "TIFFNumberOfTiles", t.NumberOfTiles) &&
               resolve(library, "TIFFNumberOfStrips", t.NumberOfStrips) &&
               resolve(library, "TIFFReadEncodedTile", t.ReadEncodedTile) &&
               resolve(library, "TIFFReadEncodedStrip", t.ReadEncodedStrip) &&
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
// Reading maps the input: libtiff then decodes strips and tiles in place (it never writes to mapped
// data). Read through read_memory instead, libtiff 4.5.0 refuses uncompressed tiles smaller than
// its minimum read buffer ("Invalid tile byte count"), which OpenCV reads from a file it maps.
int map_memory(thandle_t h, void** base, toff_t* size) {
  auto* m = static_cast<Memory*>(h);
  if (m->output) return 0;
  *base = const_cast<char*>(m->input.data());
  *size = m->input.size();
  return 1;
}
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
  // max_allocation: the largest single allocation libtiff may make (0: no limit).
  Handle(Memory& memory, const char* mode, tmsize_t max_allocation = 0) {
    const LibTiff& lib = libtiff();
    TIFFOpenOptions* options = lib.OpenOptionsAlloc();
    lib.SetErrorHandler(options, on_error, &memory);
    lib.SetWarningHandler(options, on_warning, &memory);
    lib.SetMaxSingleMemAlloc(options, max_allocation);
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

// libtiff's message; its own limits (the scans of a JPEG-compressed TIFF, the allocation bound set
// in Handle) are refusals the user should read.
[[noreturn]] void fail(const Memory& memory, const char* fallback) {
  const std::string& m = memory.message;
  if (m.find("exceeds maximum scans") != std::string::npos || m.find("byte limit defined in open options") != std::string::npos)
    throw CodecRefusal(m);
  throw CodecError(m.empty() ? fallback : m);
}

// The image turned upright from the stored order its orientation tag describes, as OpenCV did
// (libtiff's RGBA reader alone flips but never transposes).
cv::Mat upright(const cv::Mat& stored, std::uint16_t orientation) {
  cv::Mat out;
  switch (orientation) {
    case ORIENTATION_TOPRIGHT: cv::flip(stored, out, 1); break;
    case ORIENTATION_BOTRIGHT: cv::flip(stored, out, -1); break;
    case ORIENTATION_BOTLEFT: cv::flip(stored, out, 0); break;
    case ORIENTATION_LEFTTOP: cv::transpose(stored, out); break;
    case ORIENTATION_RIGHTTOP: cv::rotate(stored, out, cv::ROTATE_90_CLOCKWISE); break;
    case ORIENTATION_RIGHTBOT: cv::transpose(stored, out), cv::flip(out, out, -1); break;
    case ORIENTATION_LEFTBOT: cv::rotate(stored, out, cv::ROTATE_90_COUNTERCLOCKWISE); break;
    default: return stored;
  }
  return out;
}

std::uint16_t orientation_of(TIFF* tiff) {
  std::uint16_t orientation = ORIENTATION_TOPLEFT;
  libtiff().GetFieldDefaulted(tiff, TIFFTAG_ORIENTATION, &orientation);
  return orientation < ORIENTATION_TOPLEFT || orientation > ORIENTATION_LEFTBOT ? ORIENTATION_TOPLEFT : orientation;
}

cv::Mat read_rgba(TIFF* tiff, Memory& memory, int width, int height, int channels) {
  std::vector<std::uint32_t> rgba(static_cast<std::size_t>(width) * height);
  // Asked for the file's own orientation, libtiff gives the rows and columns as stored.
  const std::uint16_t orientation = orientation_of(tiff);
  if (!libtiff().ReadRGBAImageOriented(tiff, static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), rgba.data(),
                                       orientation, 0))
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
  return upright(image, orientation);
}

// How the samples are stored: in tiles, or in strips (tiles as wide as the image), each plane apart
// when planar is separate.
struct Blocks {
  std::uint32_t width = 0, height = 0;  // of one block
  bool tiled = false;
  bool separate = false;
  tmsize_t bytes = 0;  // of one decoded block
};

// 16-bit samples as stored (grey, RGB or RGBA; strips or tiles; contiguous or separate planes), in
// BGR(A) order, turned upright.
cv::Mat read_sixteen(TIFF* tiff, Memory& memory, int width, int height, int channels, const Blocks& blocks) {
  cv::Mat image(height, width, CV_16UC(channels));
  const int per_block = blocks.separate ? 1 : channels;  // samples of a pixel in one block
  const std::uint32_t across = (static_cast<std::uint32_t>(width) + blocks.width - 1) / blocks.width;
  const std::uint32_t down = (static_cast<std::uint32_t>(height) + blocks.height - 1) / blocks.height;
  std::vector<std::uint16_t> block(static_cast<std::size_t>(blocks.bytes) / 2 + 1);
  for (int plane = 0; plane < (blocks.separate ? channels : 1); ++plane)
    for (std::uint32_t by = 0; by < down; ++by)
      for (std::uint32_t bx = 0; bx < across; ++bx) {
        const std::uint32_t index = (static_cast<std::uint32_t>(plane) * down + by) * across + bx;
        const tmsize_t read = blocks.tiled ? libtiff().ReadEncodedTile(tiff, index, block.data(), blocks.bytes)
                                           : libtiff().ReadEncodedStrip(tiff, index, block.data(), blocks.bytes);
        const int x0 = static_cast<int>(bx * blocks.width), y0 = static_cast<int>(by * blocks.height);
        const int cols = std::min<int>(static_cast<int>(blocks.width), width - x0);
        const int rows = std::min<int>(static_cast<int>(blocks.height), height - y0);
        const std::size_t pitch = static_cast<std::size_t>(blocks.tiled ? blocks.width : static_cast<std::uint32_t>(width)) * per_block;
        if (read < 0 || static_cast<std::size_t>(read) < ((rows - 1) * pitch + static_cast<std::size_t>(cols) * per_block) * 2)
          fail(memory, "the TIFF data does not decode");
        for (int r = 0; r < rows; ++r) {
          const std::uint16_t* in = block.data() + r * pitch;
          std::uint16_t* out = image.ptr<std::uint16_t>(y0 + r) + static_cast<std::size_t>(x0) * channels + plane;
          for (int c = 0; c < cols; ++c)
            for (int k = 0; k < per_block; ++k) out[c * channels + k] = in[c * per_block + k];
        }
      }
  if (channels >= 3)
    for (int r = 0; r < height; ++r) {
      auto* row = image.ptr<std::uint16_t>(r);
      for (int c = 0; c < width; ++c) std::swap(row[c * channels], row[c * channels + 2]);
    }
  return upright(image, orientation_of(tiff));
}

// The strips or tiles as the directory describes them; a layout whose blocks are too many or too
// large for the image is refused before anything is read.
Blocks blocks_of(TIFF* tiff, std::uint64_t image_bytes) {
  const LibTiff& lib = libtiff();
  Blocks b;
  std::uint16_t planar = PLANARCONFIG_CONTIG;
  lib.GetFieldDefaulted(tiff, TIFFTAG_PLANARCONFIG, &planar);
  b.separate = planar == PLANARCONFIG_SEPARATE;
  b.tiled = lib.IsTiled(tiff) != 0;
  std::uint32_t width = 0, rows_per_strip = 0;
  lib.GetField(tiff, TIFFTAG_IMAGEWIDTH, &width);
  if (b.tiled) {
    lib.GetField(tiff, TIFFTAG_TILEWIDTH, &b.width);
    lib.GetField(tiff, TIFFTAG_TILELENGTH, &b.height);
  } else {
    lib.GetFieldDefaulted(tiff, TIFFTAG_ROWSPERSTRIP, &rows_per_strip);
    std::uint32_t height = 0;
    lib.GetField(tiff, TIFFTAG_IMAGELENGTH, &height);
    b.width = width;
    b.height = std::min(rows_per_strip, height);
  }
  const std::uint64_t bytes = b.tiled ? lib.TileSize(tiff) : lib.StripSize(tiff);
  const std::uint64_t count = b.tiled ? lib.NumberOfTiles(tiff) : lib.NumberOfStrips(tiff);
  if (b.width == 0 || b.height == 0 || bytes == 0) throw CodecError("the TIFF's strips or tiles are empty");
  if (count > kMaxTiffBlocks) {
    throw CodecRefusal("the TIFF is cut into " + std::to_string(count) + " strips or tiles, more than the limit of " +
                       std::to_string(kMaxTiffBlocks));
  }
  if (bytes > std::max<std::uint64_t>(kMinTiffBlockLimit, 4 * image_bytes))
    throw CodecRefusal("the TIFF's strips or tiles (" + std::to_string(bytes) + " bytes each) are far larger than its image");
  b.bytes = static_cast<tmsize_t>(bytes);
  return b;
}

}  // namespace

cv::Mat decode_tiff(std::string_view bytes, const DecodeBounds& bounds) {
  Memory memory;
  memory.input = bytes;
  const Handle handle(memory, "r", max_tiff_allocation(bounds));
  TIFF* tiff = handle.get();
  const LibTiff& lib = libtiff();
  std::uint32_t width = 0, height = 0;
  std::uint16_t photometric = 0, bits = 1, samples = 1, format = SAMPLEFORMAT_UINT;
  if (!lib.GetField(tiff, TIFFTAG_IMAGEWIDTH, &width) || !lib.GetField(tiff, TIFFTAG_IMAGELENGTH, &height) ||
      !lib.GetField(tiff, TIFFTAG_PHOTOMETRIC, &photometric))
    fail(memory, "the TIFF header lacks its size or photometric tag");
  check_decoded_size(width, height, bounds, "TIFF");
  lib.GetField(tiff, TIFFTAG_BITSPERSAMPLE, &bits);
  lib.GetField(tiff, TIFFTAG_SAMPLESPERPIXEL, &samples);
  lib.GetField(tiff, TIFFTAG_SAMPLEFORMAT, &format);
  if (format != SAMPLEFORMAT_UINT) throw CodecRefusal("TIFF samples that are not unsigned integers are not read");
  if (!(bits == 1 || bits == 2 || bits == 4 || bits == 8 || bits == 16))
    throw CodecRefusal("TIFF samples of " + std::to_string(bits) + " bits are not read (1, 2, 4, 8 or 16)");
  if (samples < 1 || samples > 4)
    throw CodecRefusal("TIFF pixels of " + std::to_string(samples) + " samples are not read (1 to 4)");
  const std::uint64_t image_bytes = static_cast<std::uint64_t>(width) * height * samples * ((bits + 7) / 8);
  const Blocks blocks = blocks_of(tiff, image_bytes);
  const bool grey = photometric == PHOTOMETRIC_MINISWHITE || photometric == PHOTOMETRIC_MINISBLACK;
  const int channels = photometric == PHOTOMETRIC_PALETTE ? 3 : samples >= 4 ? 4 : samples == 3 ? 3 : 1;
  if (bits <= 8) return read_rgba(tiff, memory, static_cast<int>(width), static_cast<int>(height), channels);
  if (bits == 16 && (grey ? samples == 1 : (photometric == PHOTOMETRIC_RGB && (samples == 3 || samples == 4))))
    return read_sixteen(tiff, memory, static_cast<int>(width), static_cast<int>(height), grey ? 1 : samples, blocks);
  throw CodecRefusal("this 16-bit TIFF layout is not read (grey, RGB or RGBA only)");
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
