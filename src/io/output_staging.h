#pragma once
// Private to io: the one place that creates output files (see topocut/io/output_files.h).
#include <string>

namespace topocut::detail {

// Writes contents to path: staged when an OutputRun is open, otherwise through an exclusive
// temporary file renamed over the target at once; character devices are written directly.
void write_output(const std::string& path, const std::string& contents);

}  // namespace topocut::detail
