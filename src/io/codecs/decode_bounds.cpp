#include <string>

#include "io/codecs/codecs.h"

namespace topocut::codecs {

void check_decoded_size(std::uint64_t width, std::uint64_t height, const DecodeBounds& bounds, const char* format) {
  if (width == bounds.width && height == bounds.height) return;
  throw CodecRefusal("its " + std::string(format) + " header gives two sizes, " + std::to_string(bounds.width) + " x " +
                     std::to_string(bounds.height) + " and " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels (conflicting fields)");
}

}  // namespace topocut::codecs
