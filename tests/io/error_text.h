#pragma once
// The message of the topocut::Error a call throws ("" when it throws none), for tests of messages.
#include <functional>
#include <string>

#include "topocut/core/error.h"

namespace topocut::testing {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace topocut::testing
