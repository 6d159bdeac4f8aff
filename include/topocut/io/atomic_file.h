#pragma once
// Writing outputs so that a failure never leaves a half-written file behind: data goes to an
// exclusive temporary file next to the target, renamed over it only when complete (and, while an
// OutputRun is open, only when the whole run succeeded: see output_files.h).
#include <string>

#include <opencv2/core.hpp>

namespace topocut {

// Writes contents to path atomically; throws Error naming the path if it cannot be written.
void write_file_atomically(const std::string& path, const std::string& contents);

// Encodes image by the path's extension (.png, .pgm, ...) and writes it atomically; throws Error.
void write_image_atomically(const std::string& path, const cv::Mat& image);

// Throws Error unless a file could be created at path (checked before long work starts).
void check_writable(const std::string& path);

}  // namespace topocut
