// io's image codecs (libpng, libjpeg-turbo, libtiff, hand-written PNM and BMP) against OpenCV's: every
// accepted format decodes to the pixels cv::imdecode(IMREAD_UNCHANGED) gives, PNG, PGM and BMP encode
// to the bytes cv::imencode writes, images round-trip, and bad files give one Error line, silently.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <png.h>
#include <zlib.h>

#include "topocut/core/error.h"
#include "topocut/io/image_codec.h"
#include "topocut/io/image_input.h"

namespace topocut {
namespace {

cv::Mat random_image(int type, int rows = 13, int cols = 17) {
  cv::Mat image(rows, cols, type);
  cv::RNG rng(static_cast<std::uint64_t>(type) * 31 + rows);
  rng.fill(image, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return image;
}

std::string opencv_encoded(const cv::Mat& image, const std::string& extension, const std::vector<int>& params = {}) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(extension, image, bytes, params)) << extension;
  return std::string(bytes.begin(), bytes.end());
}

cv::Mat opencv_decoded(const std::string& bytes) {
  return cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data())),
                      cv::IMREAD_UNCHANGED);
}

bool same_pixels(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

// The same pixels from io and from OpenCV, for bytes both accept.
void expect_decodes_like_opencv(const std::string& bytes, const std::string& what) {
  SCOPED_TRACE(what);
  const cv::Mat expected = opencv_decoded(bytes);
  ASSERT_FALSE(expected.empty());
  const cv::Mat ours = decode_image(bytes, what, {});
  EXPECT_EQ(ours.type(), expected.type());
  EXPECT_TRUE(same_pixels(ours, expected));
}

// A PNG written through libpng's simplified API: grey+alpha and palette images, which OpenCV cannot write.
std::string simplified_png(png_uint_32 format, const std::vector<unsigned char>& pixels, int width, int height,
                           const std::vector<unsigned char>& colormap = {}) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width);
  image.height = static_cast<png_uint_32>(height);
  image.format = format;
  image.colormap_entries = static_cast<png_uint_32>(colormap.size() / PNG_IMAGE_SAMPLE_CHANNELS(format & ~PNG_FORMAT_FLAG_COLORMAP));
  png_alloc_size_t size = 0;
  EXPECT_TRUE(png_image_write_to_memory(&image, nullptr, &size, 0, pixels.data(), 0, colormap.empty() ? nullptr : colormap.data()));
  std::string bytes(size, '\0');
  EXPECT_TRUE(png_image_write_to_memory(&image, bytes.data(), &size, 0, pixels.data(), 0,
                                        colormap.empty() ? nullptr : colormap.data()));
  bytes.resize(size);
  return bytes;
}

TEST(ImageCodec, PngDecodesLikeOpenCv) {
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3, CV_8UC4, CV_16UC4})
    expect_decodes_like_opencv(opencv_encoded(random_image(type), ".png"), "png type " + std::to_string(type));
  const int w = 7, h = 5;
  std::vector<unsigned char> grey_alpha(static_cast<std::size_t>(w) * h * 2), indices(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < grey_alpha.size(); ++i) grey_alpha[i] = static_cast<unsigned char>(i * 37);
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<unsigned char>(i % 4);
  const std::string ga = simplified_png(PNG_FORMAT_GA, grey_alpha, w, h);
  expect_decodes_like_opencv(ga, "grey+alpha png");
  EXPECT_EQ(decode_image(ga, "ga", {}).channels(), 4);  // OpenCV's layout: BGRA with grey copied
  expect_decodes_like_opencv(simplified_png(PNG_FORMAT_RGB_COLORMAP, indices, w, h, {0, 0, 0, 255, 255, 255, 10, 200, 30, 128, 128, 128}),
                             "palette png");
  expect_decodes_like_opencv(
      simplified_png(PNG_FORMAT_RGBA_COLORMAP, indices, w, h, {0, 0, 0, 0, 255, 255, 255, 255, 10, 200, 30, 90, 1, 2, 3, 255}),
      "palette png with transparency");
}

// ColourOrder::kAny: a colour PNG in its own order, red and blue the other way round from kBgr's;
// grey ones (and their alpha) as before.
TEST(ImageCodec, PngInAnyColourOrderIsItsOwnRgb) {
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3, CV_8UC4, CV_16UC4}) {
    SCOPED_TRACE(type);
    const std::string bytes = opencv_encoded(random_image(type), ".png");
    const cv::Mat bgr = decode_image(bytes, "bgr", {});
    const cv::Mat any = decode_image(bytes, "any", {}, nullptr, ColourOrder::kAny);
    cv::Mat expected = bgr.clone();
    if (bgr.channels() == 3) cv::cvtColor(bgr, expected, cv::COLOR_BGR2RGB);
    if (bgr.channels() == 4) cv::cvtColor(bgr, expected, cv::COLOR_BGRA2RGBA);
    EXPECT_TRUE(same_pixels(any, expected));
    if (bgr.channels() > 1) {
      EXPECT_FALSE(same_pixels(any, bgr));
    }
  }
}

TEST(ImageCodec, NetpbmDecodesLikeOpenCv) {
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3}) {
    const std::string extension = CV_MAT_CN(type) == 1 ? ".pgm" : ".ppm";
    const cv::Mat image = random_image(type);
    expect_decodes_like_opencv(opencv_encoded(image, extension), "binary " + extension);
    expect_decodes_like_opencv(opencv_encoded(image, extension, {cv::IMWRITE_PXM_BINARY, 0}), "ascii " + extension);
  }
  // Maximum values other than 255 and 65535, comments, and both bitmap kinds (OpenCV writes none of these).
  expect_decodes_like_opencv("P2\n# comment\n3 2\n100\n0 50 100\n120 7 99\n", "ascii pgm, maxval 100");
  expect_decodes_like_opencv(std::string("P5 3 1 100\n") + std::string("\x00\x32\x7f", 3), "binary pgm, maxval 100");
  expect_decodes_like_opencv("P2 2 2 1000\n0 999 1000 2000\n", "ascii 16-bit pgm");
  expect_decodes_like_opencv("P1\n4 2\n1 0 1 1\n0001\n", "ascii pbm");
  expect_decodes_like_opencv(std::string("P4\n10 2\n") + std::string("\xA5\xC0\x0F\x40", 4), "binary pbm");
}

TEST(ImageCodec, JpegBmpAndTiffDecodeLikeOpenCv) {
  for (const int type : {CV_8UC1, CV_8UC3}) {
    const std::string jpeg = opencv_encoded(random_image(type), ".jpg");
    expect_decodes_like_opencv(jpeg, "jpeg");
    // Without its end-of-image marker it still decodes, to the whole image (OpenCV left the last rows
    // undecoded there).
    EXPECT_TRUE(same_pixels(decode_image(jpeg.substr(0, jpeg.size() - 2), "cut.jpg", {}), decode_image(jpeg, "j.jpg", {})));
  }
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4}) expect_decodes_like_opencv(opencv_encoded(random_image(type), ".bmp"), "bmp");
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3})
    expect_decodes_like_opencv(opencv_encoded(random_image(type), ".tiff"), "tiff type " + std::to_string(type));
  // BMPs OpenCV does not write: an OS/2 header with a colour palette, 4 bits a pixel; and 32 bits a pixel with colour masks (BGRA).
  std::string os2("BM\0\0\0\0\0\0\0\0", 10);
  const auto put = [](std::string& s, std::uint32_t v, int n) {
    for (int i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 255);
  };
  put(os2, 14 + 12 + 48, 4);
  put(os2, 12, 4);
  put(os2, 3, 2);
  put(os2, 2, 2);
  put(os2, 1 | (4u << 16), 4);
  for (int i = 0; i < 16; ++i) put(os2, static_cast<std::uint32_t>(i * 0x0f0703), 3);
  os2 += std::string("\x12\x30\0\0\xfe\xd0\0\0", 8);
  expect_decodes_like_opencv(os2, "os/2 bmp");
  for (const int bits : {8, 4}) {  // run-length coded: runs, literals, end of line, delta, end of bitmap
    std::string rle("BM\0\0\0\0\0\0\0\0", 10);
    put(rle, 14 + 40 + 64, 4);
    put(rle, 40, 4);
    put(rle, 6, 4);  // width
    put(rle, 4, 4);  // height
    put(rle, 1 | (static_cast<std::uint32_t>(bits) << 16), 4);
    put(rle, bits == 8 ? 1 : 2, 4);
    for (int i = 0; i < 3; ++i) put(rle, 0, 4);  // image size, resolution
    put(rle, 16, 4);  // colours used
    put(rle, 0, 4);
    for (int i = 0; i < 16; ++i) put(rle, static_cast<std::uint32_t>(i * 0x100f07 + 9), 4);
    const std::string rows = bits == 8 ? std::string("\x06\x03\x00\x00"          // row 0: six of index 3, end of line
                                                     "\x02\x05\x00\x03\x01\x02\x04\x00\x00\x00"  // row 1: run, 3 literals, end of line
                                                     "\x00\x02\x02\x01\x01\x07\x00\x01", 22)  // delta (2, 1), run, end of bitmap
                                       : std::string("\x06\x34\x00\x00"
                                                     "\x02\x56\x00\x03\x12\x40\x00\x00"
                                                     "\x00\x02\x02\x00\x01\x77\x00\x00\x04\x89\x00\x01", 24);
    rle += rows;
    expect_decodes_like_opencv(rle, "rle bmp, bits " + std::to_string(bits));
    expect_decodes_like_opencv(std::string(rle).replace(rle.size() - rows.size(), 2, "\x06\x0a"), "rle bmp, other run");
  }
  std::string masked = opencv_encoded(random_image(CV_8UC4, 3, 2), ".bmp");
  masked[30] = 3;  // BI_BITFIELDS
  expect_decodes_like_opencv(masked, "32-bit bmp with masks");
}

TEST(ImageCodec, PngPgmAndBmpEncodeToOpenCvsBytes) {
  for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3, CV_8UC4, CV_16UC4}) {
    const cv::Mat image = random_image(type, 40, 50);
    EXPECT_EQ(encode_image(image, ".png"), opencv_encoded(image, ".png")) << type;
  }
  for (const int type : {CV_8UC1, CV_16UC1}) EXPECT_EQ(encode_image(random_image(type), ".pgm"), opencv_encoded(random_image(type), ".pgm"));
  for (const int type : {CV_8UC3, CV_16UC3}) EXPECT_EQ(encode_image(random_image(type), ".ppm"), opencv_encoded(random_image(type), ".ppm"));
  for (const int type : {CV_8UC1, CV_8UC3, CV_8UC4}) EXPECT_EQ(encode_image(random_image(type), ".bmp"), opencv_encoded(random_image(type), ".bmp"));
  // Depths a format cannot store are saturated to 8 bits, as cv::imencode did.
  const cv::Mat labels = random_image(CV_32SC1) - 100;
  EXPECT_EQ(encode_image(labels, ".png"), opencv_encoded(labels, ".png"));
}

TEST(ImageCodec, RoundTrips) {
  for (const std::string extension : {".png", ".tif"})
    for (const int type : {CV_8UC1, CV_16UC1, CV_8UC3, CV_16UC3, CV_8UC4}) {
      const cv::Mat image = random_image(type);
      EXPECT_TRUE(same_pixels(decode_image(encode_image(image, extension), "x", {}), image)) << extension << " " << type;
    }
  for (const int type : {CV_8UC1, CV_16UC1}) {
    const cv::Mat image = random_image(type);
    EXPECT_TRUE(same_pixels(decode_image(encode_image(image, ".pgm"), "x.pgm", {}), image)) << type;
  }
  const cv::Mat bgr = random_image(CV_8UC3);
  EXPECT_TRUE(same_pixels(decode_image(encode_image(bgr, ".bmp"), "x.bmp", {}), bgr));
  // JPEG is lossy: a flat image comes back flat.
  const cv::Mat flat(16, 16, CV_8UC3, cv::Scalar(10, 120, 230));
  EXPECT_LE(cv::norm(decode_image(encode_image(flat, ".jpg"), "x.jpg", {}), flat, cv::NORM_INF), 2.0);
}

TEST(ImageCodec, WritesOnlyWhatItCanEncode) {
  EXPECT_TRUE(can_encode_image("a/rooms.PNG"));
  EXPECT_TRUE(can_encode_image("rooms.jpeg"));
  EXPECT_FALSE(can_encode_image("rooms.gif"));
  EXPECT_FALSE(can_encode_image("rooms"));
  EXPECT_THROW(encode_image(random_image(CV_8UC2), ".png"), Error);
  EXPECT_THROW(encode_image(random_image(CV_8UC3), ".pgm"), Error);
  EXPECT_THROW(encode_image(cv::Mat(), ".png"), Error);
}

// Truncated and corrupted files: one Error line naming the file, nothing printed by a decoder, and
// OpenCV refusing the same damaged bytes (so no file that decoded before is refused now), except a
// JPEG cut inside its scan, which OpenCV returned with rows it never decoded (uninitialised memory).
TEST(ImageCodec, DamagedFilesGiveOneErrorLine) {
  const std::vector<std::pair<std::string, cv::Mat>> samples = {
      {".png", random_image(CV_8UC3, 30, 30)}, {".pgm", random_image(CV_8UC1)}, {".ppm", random_image(CV_16UC3)},
      {".bmp", random_image(CV_8UC3)},         {".tiff", random_image(CV_8UC1)}, {".jpg", random_image(CV_8UC3, 40, 40)}};
  for (const auto& [extension, image] : samples) {
    const std::string good = opencv_encoded(image, extension);
    std::string corrupt = good;
    for (std::size_t i = corrupt.size() / 2; i < corrupt.size(); i += 7) corrupt[i] = static_cast<char>(~corrupt[i]);
    for (const std::string& bad : {good.substr(0, good.size() * 3 / 4), corrupt}) {
      SCOPED_TRACE(extension);
      const bool opencv_reads = !opencv_decoded(bad).empty();
      ::testing::internal::CaptureStderr();
      std::string message;
      cv::Mat ours;
      try {
        ours = decode_image(bad, "bad" + extension, {});
      } catch (const Error& e) {
        message = e.what();
      }
      EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
      if (opencv_reads && extension == ".jpg" && bad.size() < good.size()) {
        EXPECT_NE(message.find("cannot read 'bad.jpg' as an image"), std::string::npos) << message;
      } else if (opencv_reads) {
        const cv::Mat theirs = opencv_decoded(bad);
        EXPECT_TRUE(same_pixels(ours, theirs)) << message << " size " << bad.size() << " of " << good.size() << " types "
                                               << ours.type() << " " << theirs.type() << " diff "
                                               << (ours.type() == theirs.type() ? cv::norm(ours, theirs, cv::NORM_INF) : -1.0);
      } else {
        EXPECT_NE(message.find("cannot read 'bad" + extension + "' as an image"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos);
      }
    }
  }
}

// The decoder leaves zlib's Adler-32 of the inflated rows unchecked: each chunk's CRC-32 finds a
// damaged file. A PNG whose Adler-32 is wrong but whose chunks' CRCs are right decodes to its pixels;
// the same change without the IDAT's CRC made right again is refused.
TEST(ImageCodec, PngDamageIsFoundByTheChunkChecksums) {
  const cv::Mat image = random_image(CV_8UC3, 30, 30);
  const std::string good = opencv_encoded(image, ".png");
  const auto be32 = [](const std::string& s, std::size_t at) {
    return static_cast<std::uint32_t>(static_cast<unsigned char>(s[at])) << 24 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 1])) << 16 |
           static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 2])) << 8 | static_cast<unsigned char>(s[at + 3]);
  };
  std::size_t at = 8;  // after the signature: chunks of length, type, data and CRC
  while (at + 8 <= good.size() && good.compare(at + 4, 4, "IDAT") != 0) at += 12 + be32(good, at);
  ASSERT_LT(at + 8, good.size());
  const std::size_t length = be32(good, at);
  std::string wrong_sum = good;
  wrong_sum[at + 8 + length - 1] = static_cast<char>(~wrong_sum[at + 8 + length - 1]);  // the Adler-32's last byte
  const std::string refused = wrong_sum;
  const auto crc = static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(wrong_sum.data() + at + 4),
                                                    static_cast<uInt>(length + 4)));
  for (int k = 0; k < 4; ++k) wrong_sum[at + 8 + length + k] = static_cast<char>(crc >> (24 - 8 * k));
  EXPECT_TRUE(same_pixels(decode_image(wrong_sum, "sum.png", {}), decode_image(good, "good.png", {})));
  try {
    decode_image(refused, "crc.png", {});
    ADD_FAILURE() << "a PNG whose IDAT does not match its CRC was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read 'crc.png' as an image"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topocut
