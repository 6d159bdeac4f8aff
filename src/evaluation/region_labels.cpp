#include "topocut/evaluation/region_labels.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "topocut/core/error.h"

namespace topocut {

namespace {

// (red, green, blue) of 8- or 16-bit BGR(A) pixels packed into one number that sorts like the triple.
template <typename T>
cv::Mat packed_colours(const cv::Mat& image) {
  cv::Mat packed(image.size(), CV_64FC1);  // 48 bits fit a double's mantissa exactly
  const int channels = image.channels();
  for (int r = 0; r < image.rows; ++r) {
    const T* in = image.ptr<T>(r);
    double* out = packed.ptr<double>(r);
    for (int c = 0; c < image.cols; ++c, in += channels) {
      const std::uint64_t rgb = (std::uint64_t{in[2]} << 32) | (std::uint64_t{in[1]} << 16) | in[0];
      const bool transparent = channels == 4 && in[3] < (sizeof(T) == 1 ? 128 : 128 * 257);
      out[c] = transparent ? 0.0 : static_cast<double>(rgb);
    }
  }
  return packed;
}

// Numbers the distinct non-zero values 1..N in increasing order.
cv::Mat numbered(const cv::Mat& packed) {
  std::vector<double> values(packed.begin<double>(), packed.end<double>());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (!values.empty() && values.front() == 0.0) values.erase(values.begin());
  cv::Mat labels(packed.size(), CV_32SC1);
  for (int r = 0; r < packed.rows; ++r) {
    const double* in = packed.ptr<double>(r);
    int* out = labels.ptr<int>(r);
    for (int c = 0; c < packed.cols; ++c) {
      if (in[c] == 0.0) {
        out[c] = 0;
        continue;
      }
      if (c > 0 && in[c] == in[c - 1]) {  // runs of one colour are the rule
        out[c] = out[c - 1];
        continue;
      }
      out[c] = static_cast<int>(std::lower_bound(values.begin(), values.end(), in[c]) - values.begin()) + 1;
    }
  }
  return labels;
}

}  // namespace

cv::Mat region_labels(const cv::Mat& image) {
  if (image.empty()) throw Error("the label image is empty");
  const int depth = image.depth();
  if (depth != CV_8U && depth != CV_16U) throw Error("a label image must have 8 or 16 bits a channel");
  switch (image.channels()) {
    case 1: {
      cv::Mat labels;
      image.convertTo(labels, CV_32S);
      return labels;
    }
    case 2: {  // grey + alpha, should a decoder deliver it that way
      cv::Mat planes[2], labels;
      cv::split(image, planes);
      planes[0].convertTo(labels, CV_32S);
      labels.setTo(0, planes[1] < (depth == CV_8U ? 128 : 128 * 257));
      return labels;
    }
    case 3:
    case 4:
      return numbered(depth == CV_8U ? packed_colours<std::uint8_t>(image) : packed_colours<std::uint16_t>(image));
    default:
      throw Error("a label image must be grey or colour, not " + std::to_string(image.channels()) + " channels");
  }
}

cv::Mat read_region_labels(const std::string& path, const ImageLimits& limits, const ExpectedSize* expected) {
  const cv::Mat image = read_image(path, "label image", limits, expected);
  try {
    return region_labels(image);
  } catch (const Error& e) {
    throw Error("cannot use '" + path + "': " + e.what());
  }
}

}  // namespace topocut
