#include "topocut/io/label_image.h"

#include <filesystem>
#include <vector>


#include "topocut/core/error.h"
#include "topocut/io/image_input.h"
#include "topocut/io/atomic_file.h"

namespace topocut {

void write_label_image(const std::string& path, const cv::Mat& labels) {
  if (labels.empty()) throw Error("cannot write label image '" + path + "': there are no labels");
  if (labels.channels() != 1 || labels.depth() == CV_32F || labels.depth() == CV_64F)
    throw Error("cannot write label image '" + path + "': labels must be one channel of integers");
  double low = 0.0, high = 0.0;
  cv::minMaxLoc(labels, &low, &high);
  if (low < 0.0) throw Error("cannot write label image '" + path + "': labels must not be negative");
  if (high > 65535.0)
    throw Error("cannot write label image '" + path + "': " + std::to_string(static_cast<long>(high)) +
                " rooms do not fit in a 16-bit PNG");
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension != ".png" && extension != ".PNG")
    throw Error("cannot write label image '" + path + "': label images are 16-bit PNGs, use a .png name");
  cv::Mat sixteen;
  labels.convertTo(sixteen, CV_16U);
  write_image_atomically(path, sixteen);
}

cv::Mat read_label_image(const std::string& path) {
  const cv::Mat image = read_image(path, "label image", ImageLimits{});
  if (image.channels() != 1) throw Error("label image '" + path + "' must have one channel, it has " + std::to_string(image.channels()));
  if (image.depth() != CV_8U && image.depth() != CV_16U)
    throw Error("label image '" + path + "' must be 8- or 16-bit");
  cv::Mat labels;
  image.convertTo(labels, CV_32S);
  return labels;
}

}  // namespace topocut
