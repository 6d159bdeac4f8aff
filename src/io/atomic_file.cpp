#include "topocut/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include "topocut/core/error.h"

namespace topocut {

namespace fs = std::filesystem;

namespace {
std::string temporary_name(const std::string& path) {
  return path + ".tmp." + std::to_string(static_cast<long>(::getpid()));
}
}  // namespace

void write_file_atomically(const std::string& path, const std::string& contents) {
  if (path.empty()) throw Error("output path is empty");
  const std::string tmp = temporary_name(path);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(tmp, ignored);
      throw Error("cannot write '" + path + "': write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error("cannot write '" + path + "': " + ec.message());
  }
}

void write_image_atomically(const std::string& path, const cv::Mat& image) {
  const std::string extension = fs::path(path).extension().string();
  if (extension.empty()) throw Error("cannot write image '" + path + "': the file name needs an extension such as .png");
  std::vector<unsigned char> bytes;
  bool ok = false;
  try {
    ok = cv::imencode(extension, image, bytes);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw Error("cannot encode image '" + path + "' as " + extension);
  write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

void check_writable(const std::string& path) {
  if (path.empty()) throw Error("output path is empty");
  const fs::path p(path);
  if (fs::is_directory(p)) throw Error("cannot write '" + path + "': it is a directory");
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(parent)) throw Error("cannot write '" + path + "': directory '" + parent.string() + "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0) throw Error("cannot write '" + path + "': directory is not writable");
}

std::string read_file(const std::string& path) {
  if (fs::is_directory(path)) throw Error("cannot read '" + path + "': it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read '" + path + "': " + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace topocut
