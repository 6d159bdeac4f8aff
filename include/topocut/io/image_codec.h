#pragma once
// Encoding images by file extension, without OpenCV's imgcodecs (whose GDAL and other decoders
// cost most of topocut's start-up): PNG (libpng), JPEG (libjpeg-turbo), TIFF (libtiff), PGM/PPM and
// BMP. Pixels are cv::Mat in OpenCV's layout (BGR or BGRA channel order, 8 or 16 bits), the same
// bytes OpenCV's codecs wrote for PNG, PGM and BMP. Decoding is decode_image() (image_input.h).
#include <string>

#include <opencv2/core.hpp>

namespace topocut {

// True if encode_image() writes the file name's extension (case-insensitive): .png, .jpg, .jpeg,
// .jpe, .pgm, .ppm, .pnm, .pbm (refused when encoding, as by OpenCV), .bmp, .dib, .tif, .tiff.
bool can_encode_image(const std::string& path);

// The image encoded as extension says (".png", ...), with OpenCV's defaults (PNG: fast zlib level;
// JPEG: quality 95). Images of 1, 3 or 4 channels; depths a format cannot store are saturated to 8
// bits, as cv::imencode did. Throws Error if the extension or the image cannot be encoded.
std::string encode_image(const cv::Mat& image, const std::string& extension);

}  // namespace topocut
