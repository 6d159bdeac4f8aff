#pragma once
// Valid images in the layouts real files come in, written by the formats' own libraries (libtiff,
// libpng, libjpeg-turbo) or byte by byte (BMP, Netpbm), for the differential tests and the fuzz
// target that decode them with topocut and with OpenCV. Each layout is a few plain fields, so a
// fuzzer's bytes can pick one (variant_from_bytes).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <jpeglib.h>
#include <png.h>
#include <tiffio.h>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace topocut::testing {

// Deterministic pixel values: a gradient with noise, so that every sample differs.
inline cv::Mat pattern(int rows, int cols, int type, std::uint64_t seed) {
  cv::Mat m(rows, cols, type);
  cv::RNG rng(seed);
  rng.fill(m, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return m;
}

// ---- TIFF through libtiff, into memory ----

struct TiffLayout {
  int width = 37, height = 29;
  int bits = 8;        // 1, 2, 4, 8 or 16
  int samples = 1;     // 1, 3 or 4 (the fourth an associated alpha)
  int photometric = PHOTOMETRIC_MINISBLACK;  // MINISBLACK, MINISWHITE, RGB or PALETTE
  bool tiled = false;
  int block_width = 16, block_height = 16;  // a tile, or block_height rows per strip
  bool separate = false;                    // one plane per sample
  int compression = COMPRESSION_NONE;       // NONE, LZW, ADOBE_DEFLATE, PACKBITS
  int orientation = ORIENTATION_TOPLEFT;
  std::uint64_t seed = 1;
};

struct TiffMemory {
  std::string bytes;
  toff_t position = 0;
};

inline tmsize_t tiff_memory_read(thandle_t, void*, tmsize_t) { return 0; }
inline tmsize_t tiff_memory_write(thandle_t h, void* data, tmsize_t n) {
  auto* m = static_cast<TiffMemory*>(h);
  if (m->bytes.size() < m->position + n) m->bytes.resize(m->position + n);
  std::memcpy(m->bytes.data() + m->position, data, static_cast<std::size_t>(n));
  m->position += static_cast<toff_t>(n);
  return n;
}
inline toff_t tiff_memory_seek(thandle_t h, toff_t offset, int whence) {
  auto* m = static_cast<TiffMemory*>(h);
  m->position = whence == SEEK_SET ? offset : whence == SEEK_CUR ? m->position + offset : m->bytes.size() + offset;
  return m->position;
}
inline int tiff_memory_close(thandle_t) { return 0; }
inline toff_t tiff_memory_size(thandle_t h) { return static_cast<TiffMemory*>(h)->bytes.size(); }
inline int tiff_memory_map(thandle_t, void**, toff_t*) { return 0; }
inline void tiff_memory_unmap(thandle_t, void*, toff_t) {}

// The samples of one block (a tile or strip) of one plane, packed at `bits` bits, rows padded to bytes.
inline std::vector<unsigned char> tiff_block(const cv::Mat& samples, const TiffLayout& l, int x0, int y0, int w, int h,
                                             int plane) {
  const int per_pixel = l.separate ? 1 : l.samples;
  const std::size_t row_bytes = (static_cast<std::size_t>(w) * per_pixel * l.bits + 7) / 8;
  std::vector<unsigned char> out(row_bytes * h, 0);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      for (int k = 0; k < per_pixel; ++k) {
        const int y = y0 + r, x = x0 + c, channel = l.separate ? plane : k;
        const bool inside = y < l.height && x < l.width;
        const std::uint32_t v = !inside ? 0
                                : l.bits == 16 ? samples.ptr<std::uint16_t>(y)[x * l.samples + channel]
                                               : samples.ptr<std::uint8_t>(y)[x * l.samples + channel] >> (8 - std::min(8, l.bits));
        const std::size_t bit = (static_cast<std::size_t>(c) * per_pixel + k) * l.bits;
        unsigned char* row = out.data() + r * row_bytes;
        if (l.bits == 16) {
          std::memcpy(row + bit / 8, &v, 2);  // native order: libtiff writes the file in it
        } else if (l.bits == 8) {
          row[bit / 8] = static_cast<unsigned char>(v);
        } else {
          row[bit / 8] |= static_cast<unsigned char>(v << (8 - l.bits - bit % 8));
        }
      }
  return out;
}

// A TIFF of random samples in layout l; empty if libtiff refuses to write it.
inline std::string tiff_bytes(const TiffLayout& l) {
  const cv::Mat samples = pattern(l.height, l.width, CV_MAKETYPE(l.bits == 16 ? CV_16U : CV_8U, l.samples), l.seed);
  TiffMemory memory;
  TIFF* t = TIFFClientOpen("variant", "w", &memory, tiff_memory_read, tiff_memory_write, tiff_memory_seek, tiff_memory_close,
                           tiff_memory_size, tiff_memory_map, tiff_memory_unmap);
  if (!t) return {};
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(l.width));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(l.height));
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, static_cast<std::uint16_t>(l.bits));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, static_cast<std::uint16_t>(l.samples));
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC, static_cast<std::uint16_t>(l.photometric));
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, static_cast<std::uint16_t>(l.separate ? PLANARCONFIG_SEPARATE : PLANARCONFIG_CONTIG));
  TIFFSetField(t, TIFFTAG_COMPRESSION, static_cast<std::uint16_t>(l.compression));
  TIFFSetField(t, TIFFTAG_ORIENTATION, static_cast<std::uint16_t>(l.orientation));
  if (l.samples == 4) {
    const std::uint16_t extra = EXTRASAMPLE_ASSOCALPHA;
    TIFFSetField(t, TIFFTAG_EXTRASAMPLES, 1, &extra);
  }
  if (l.photometric == PHOTOMETRIC_PALETTE) {
    std::vector<std::uint16_t> red(1u << l.bits), green(1u << l.bits), blue(1u << l.bits);
    for (std::size_t i = 0; i < red.size(); ++i) {
      red[i] = static_cast<std::uint16_t>((i * 97 % 256) * 257);
      green[i] = static_cast<std::uint16_t>((i * 31 % 256) * 257);
      blue[i] = static_cast<std::uint16_t>((255 - i % 256) * 257);
    }
    TIFFSetField(t, TIFFTAG_COLORMAP, red.data(), green.data(), blue.data());
  }
  const int bw = l.tiled ? l.block_width : l.width, bh = l.block_height;
  if (l.tiled) {
    TIFFSetField(t, TIFFTAG_TILEWIDTH, static_cast<std::uint32_t>(l.block_width));
    TIFFSetField(t, TIFFTAG_TILELENGTH, static_cast<std::uint32_t>(l.block_height));
  } else {
    TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, static_cast<std::uint32_t>(l.block_height));
  }
  bool ok = true;
  for (int plane = 0; plane < (l.separate ? l.samples : 1) && ok; ++plane)
    for (int y = 0; y < l.height && ok; y += bh)
      for (int x = 0; x < l.width && ok; x += bw) {
        // A strip's last block holds only the rows left; a tile is always whole.
        const int h = l.tiled ? bh : std::min(bh, l.height - y);
        std::vector<unsigned char> block = tiff_block(samples, l, x, y, bw, h, plane);
        const tmsize_t n = static_cast<tmsize_t>(block.size());
        ok = l.tiled ? TIFFWriteEncodedTile(t, TIFFComputeTile(t, x, y, 0, plane), block.data(), n) >= 0
                     : TIFFWriteEncodedStrip(t, TIFFComputeStrip(t, y, plane), block.data(), n) >= 0;
      }
  TIFFClose(t);
  return ok ? memory.bytes : std::string();
}

// The pixels a TIFF of layout l holds, in OpenCV's layout (tiff_bytes's samples read back): up to 8
// bits as libtiff's RGBA reader gives them (grey scaled to 0..255, min-is-white inverted, palette
// entries' high bytes), 16 bits as stored; BGR(A), turned upright by the orientation tag.
inline cv::Mat tiff_expected(const TiffLayout& l) {
  const cv::Mat samples = pattern(l.height, l.width, CV_MAKETYPE(l.bits == 16 ? CV_16U : CV_8U, l.samples), l.seed);
  const int channels = l.photometric == PHOTOMETRIC_PALETTE ? 3 : l.samples;
  cv::Mat out(l.height, l.width, CV_8UC(channels));
  if (l.bits == 16) {
    out = samples.clone();
    if (l.samples >= 3)
      for (int r = 0; r < out.rows; ++r)
        for (int c = 0; c < out.cols; ++c) std::swap(out.ptr<std::uint16_t>(r)[c * l.samples], out.ptr<std::uint16_t>(r)[c * l.samples + 2]);
  }
  const int top = (1 << l.bits) - 1;
  for (int r = 0; r < l.height && l.bits <= 8; ++r)
    for (int c = 0; c < l.width; ++c) {
      const std::uint8_t* in = samples.ptr<std::uint8_t>(r) + c * l.samples;
      std::uint8_t* px = out.ptr<std::uint8_t>(r) + c * channels;
      const int v = in[0] >> (8 - l.bits);
      if (l.photometric == PHOTOMETRIC_PALETTE) {
        px[0] = static_cast<std::uint8_t>(255 - v % 256);
        px[1] = static_cast<std::uint8_t>(v * 31 % 256);
        px[2] = static_cast<std::uint8_t>(v * 97 % 256);
      } else if (channels == 1) {
        const int grey = v * 255 / top;
        px[0] = static_cast<std::uint8_t>(l.photometric == PHOTOMETRIC_MINISWHITE ? 255 - grey : grey);
      } else {
        px[0] = in[2], px[1] = in[1], px[2] = in[0];
        if (channels == 4) px[3] = in[3];
      }
    }
  // The orientation tag names where row 0 and column 0 are; upright means row 0 at the top, column 0 left.
  cv::Mat upright;
  switch (l.orientation) {
    case ORIENTATION_TOPRIGHT: cv::flip(out, upright, 1); break;
    case ORIENTATION_BOTRIGHT: cv::flip(out, upright, -1); break;
    case ORIENTATION_BOTLEFT: cv::flip(out, upright, 0); break;
    case ORIENTATION_LEFTTOP: cv::transpose(out, upright); break;
    case ORIENTATION_RIGHTTOP: cv::rotate(out, upright, cv::ROTATE_90_CLOCKWISE); break;
    case ORIENTATION_RIGHTBOT: cv::transpose(out, upright), cv::flip(upright, upright, -1); break;
    case ORIENTATION_LEFTBOT: cv::rotate(out, upright, cv::ROTATE_90_COUNTERCLOCKWISE); break;
    default: upright = out;
  }
  return upright;
}

// ---- TIFF byte by byte: one directory of (tag, type, count, value) entries, for hostile headers ----

struct TiffEntry {
  std::uint16_t tag, type;
  std::uint32_t count, value;  // the value itself (SHORT or LONG, count 1) or an offset
};

// Little-endian "II*", the directory at offset 8 with entries in the order given, then `data`
// (entries point into it at offset 8 + 2 + 12 n + 4).
inline std::string tiff_with_entries(const std::vector<TiffEntry>& entries, const std::string& data) {
  std::string s("II*\0\x08\0\0\0", 8);
  const auto put = [&s](std::uint32_t v, int n) {
    for (int i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 255);
  };
  put(static_cast<std::uint32_t>(entries.size()), 2);
  for (const TiffEntry& e : entries) {
    put(e.tag, 2);
    put(e.type, 2);
    put(e.count, 4);
    put(e.value, 4);
  }
  put(0, 4);  // no next directory
  return s + data;
}

// Where tiff_with_entries puts `data` for n entries.
inline std::uint32_t tiff_data_offset(std::size_t entries) { return static_cast<std::uint32_t>(8 + 2 + 12 * entries + 4); }

// ---- PNG through libpng ----

struct PngLayout {
  int width = 23, height = 19;
  int colour_type = PNG_COLOR_TYPE_GRAY;  // GRAY, GRAY_ALPHA, RGB, RGB_ALPHA, PALETTE
  int bits = 8;                           // 1, 2, 4, 8 or 16 as the colour type allows
  bool interlaced = false;
  bool transparency = false;  // a tRNS chunk (grey, RGB, palette)
  std::uint64_t seed = 1;
};

inline void png_memory_write(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
inline void png_memory_flush(png_structp) {}

inline std::string png_bytes(const PngLayout& l) {
  const int channels = l.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                       : l.colour_type == PNG_COLOR_TYPE_RGB       ? 3
                       : l.colour_type == PNG_COLOR_TYPE_RGB_ALPHA ? 4
                                                                   : 1;
  const cv::Mat samples = pattern(l.height, l.width, CV_MAKETYPE(l.bits == 16 ? CV_16U : CV_8U, channels), l.seed);
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return {};
  }
  png_set_write_fn(png, &out, png_memory_write, png_memory_flush);
  png_set_IHDR(png, info, static_cast<png_uint_32>(l.width), static_cast<png_uint_32>(l.height), l.bits, l.colour_type,
               l.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette;
  std::vector<png_byte> alphas;
  if (l.colour_type == PNG_COLOR_TYPE_PALETTE) {
    for (int i = 0; i < (1 << l.bits); ++i)
      palette.push_back({static_cast<png_byte>(i * 37), static_cast<png_byte>(255 - i * 11), static_cast<png_byte>(i * 5)});
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    if (l.transparency) {
      for (int i = 0; i < (1 << l.bits) / 2 + 1; ++i) alphas.push_back(static_cast<png_byte>(i * 53));
      png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
    }
  } else if (l.transparency && (l.colour_type == PNG_COLOR_TYPE_GRAY || l.colour_type == PNG_COLOR_TYPE_RGB)) {
    png_color_16 colour{};
    colour.gray = colour.red = colour.green = colour.blue = 1;
    png_set_tRNS(png, info, nullptr, 0, &colour);
  }
  png_write_info(png, info);
  if (l.bits == 16) png_set_swap(png);
  if (l.bits < 8) png_set_packing(png);
  std::vector<std::vector<png_byte>> rows(static_cast<std::size_t>(l.height));
  for (int r = 0; r < l.height; ++r) {
    if (l.bits == 16) {
      const auto* p = samples.ptr<png_byte>(r);
      rows[r].assign(p, p + static_cast<std::size_t>(l.width) * channels * 2);
    } else {
      rows[r].resize(static_cast<std::size_t>(l.width) * channels);
      for (std::size_t i = 0; i < rows[r].size(); ++i) rows[r][i] = samples.ptr<png_byte>(r)[i] >> (8 - l.bits);
    }
  }
  std::vector<png_bytep> pointers;
  for (auto& row : rows) pointers.push_back(row.data());
  png_write_image(png, pointers.data());
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

// ---- JPEG through libjpeg-turbo ----

struct JpegLayout {
  int width = 41, height = 27;
  int components = 1;        // 1 grey, 3 YCbCr, 4 Adobe CMYK
  bool progressive = false;
  bool arithmetic = false;
  int restart_rows = 0;      // restart markers every N MCU rows (0: none)
  bool subsampled = true;    // 4:2:0 for colour, else 4:4:4
  int exif_orientation = 0;  // an EXIF APP1 with this orientation (0: none); OpenCV's IMREAD_UNCHANGED ignores it
  int extra_scans = 0;       // empty AC scans appended after the image's own (hostile: work, not size)
  std::uint64_t seed = 1;
};

inline std::string exif_orientation_segment(int orientation) {
  // APP1 "Exif\0\0", a little-endian TIFF header and one IFD entry: Orientation (274), SHORT, 1.
  std::string tiff("II*\0\x08\0\0\0\x01\0\x12\x01\x03\0\x01\0\0\0", 18);
  tiff += static_cast<char>(orientation);
  tiff += std::string("\0\0\0\0\0\0\0", 7);
  const std::string payload = std::string("Exif\0\0", 6) + tiff;
  return payload;
}

// The scan header of an AC scan of one component (Ss 1, Se 63, Ah 0, Al 0) with no data behind it.
inline std::string empty_ac_scan(int component_id) {
  return std::string("\xFF\xDA\x00\x08\x01", 5) + static_cast<char>(component_id) + std::string("\x00\x01\x3F\x00", 4);
}

inline std::string jpeg_bytes(const JpegLayout& l) {
  const int channels = l.components;
  cv::Mat samples = pattern(l.height, l.width, CV_8UC(channels), l.seed);
  cv::GaussianBlur(samples, samples, cv::Size(5, 5), 0);  // photo-like, so the file stays small
  jpeg_compress_struct cinfo{};
  jpeg_error_mgr error{};
  cinfo.err = jpeg_std_error(&error);
  jpeg_create_compress(&cinfo);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&cinfo, &buffer, &size);
  cinfo.image_width = static_cast<JDIMENSION>(l.width);
  cinfo.image_height = static_cast<JDIMENSION>(l.height);
  cinfo.input_components = channels;
  cinfo.in_color_space = channels == 1 ? JCS_GRAYSCALE : channels == 3 ? JCS_RGB : JCS_CMYK;
  jpeg_set_defaults(&cinfo);
  jpeg_set_quality(&cinfo, 90, TRUE);
  if (channels == 3 && !l.subsampled)
    for (int c = 0; c < 3; ++c) cinfo.comp_info[c].h_samp_factor = cinfo.comp_info[c].v_samp_factor = 1;
  cinfo.arith_code = l.arithmetic ? TRUE : FALSE;
  cinfo.restart_in_rows = l.restart_rows;
  if (l.progressive) jpeg_simple_progression(&cinfo);
  jpeg_start_compress(&cinfo, TRUE);
  if (l.exif_orientation > 0) {
    const std::string app1 = exif_orientation_segment(l.exif_orientation);
    jpeg_write_marker(&cinfo, JPEG_APP0 + 1, reinterpret_cast<const JOCTET*>(app1.data()), static_cast<unsigned>(app1.size()));
  }
  for (int r = 0; r < l.height; ++r) {
    JSAMPROW row = samples.ptr(r);
    jpeg_write_scanlines(&cinfo, &row, 1);
  }
  jpeg_finish_compress(&cinfo);
  const int first_component = cinfo.comp_info[0].component_id;  // 1 for grey and YCbCr, 'C' for CMYK
  jpeg_destroy_compress(&cinfo);
  std::string out(reinterpret_cast<const char*>(buffer), size);
  std::free(buffer);
  if (l.extra_scans > 0 && l.progressive) {
    std::string scans;
    for (int i = 0; i < l.extra_scans; ++i) scans += empty_ac_scan(first_component);
    out.insert(out.size() - 2, scans);  // before the end-of-image marker
  }
  return out;
}

// ---- BMP byte by byte: palette (1, 4, 8 bits), 16 bits (5-5-5), 24 and 32 bits, bottom-up or top-down ----

struct BmpLayout {
  int width = 19, height = 13;
  int bits = 24;
  bool top_down = false;
  bool grey_palette = false;
  std::uint64_t seed = 1;
};

inline std::string bmp_bytes(const BmpLayout& l) {
  const auto put = [](std::string& s, std::uint32_t v, int n) {
    for (int i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 255);
  };
  const int colours = l.bits <= 8 ? 1 << l.bits : 0;
  const std::size_t pitch = ((static_cast<std::size_t>(l.width) * l.bits + 31) / 32) * 4;
  const std::uint32_t offset = 14 + 40 + 4 * colours;
  std::string s("BM", 2);
  put(s, static_cast<std::uint32_t>(offset + pitch * l.height), 4);
  put(s, 0, 4);
  put(s, offset, 4);
  put(s, 40, 4);
  put(s, static_cast<std::uint32_t>(l.width), 4);
  put(s, static_cast<std::uint32_t>(l.top_down ? -l.height : l.height), 4);
  put(s, 1 | (static_cast<std::uint32_t>(l.bits) << 16), 4);
  put(s, 0, 4);  // no compression
  put(s, static_cast<std::uint32_t>(pitch * l.height), 4);
  put(s, 2835, 4);
  put(s, 2835, 4);
  put(s, static_cast<std::uint32_t>(colours), 4);
  put(s, 0, 4);
  for (int i = 0; i < colours; ++i) {
    const int grey = i * 255 / (colours - 1);
    put(s, l.grey_palette ? static_cast<std::uint32_t>(grey * 0x010101) : static_cast<std::uint32_t>(i * 0x2f1b07 + 0x102030), 4);
  }
  const cv::Mat samples = pattern(l.height, static_cast<int>(pitch), CV_8UC1, l.seed);
  for (int r = 0; r < l.height; ++r) s.append(reinterpret_cast<const char*>(samples.ptr(r)), pitch);
  return s;
}

}  // namespace topocut::testing
