#include "topocut/io/atomic_file.h"

#include <filesystem>
#include <vector>

#include <unistd.h>

#include "output_staging.h"
#include "topocut/core/error.h"
#include "topocut/io/image_codec.h"

namespace topocut {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path, const std::string& contents) {
  detail::write_output(path, contents);
}

void write_image_atomically(const std::string& path, const cv::Mat& image) {
  const std::string extension = fs::path(path).extension().string();
  if (extension.empty()) throw Error("cannot write image '" + path + "': the file name needs an extension such as .png");
  std::string bytes;
  try {
    bytes = encode_image(image, extension);
  } catch (const Error&) {
    throw Error("cannot encode image '" + path + "' as " + extension);
  }
  write_file_atomically(path, bytes);
}

void check_writable(const std::string& path) {
  if (path.empty()) throw Error("output path is empty");
  const fs::path p(path);
  if (fs::is_directory(p)) throw Error("cannot write '" + path + "': it is a directory");
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(parent)) throw Error("cannot write '" + path + "': directory '" + parent.string() + "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0) throw Error("cannot write '" + path + "': directory is not writable");
}

}  // namespace topocut
