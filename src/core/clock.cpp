#include "topocut/core/clock.h"

#include <time.h>

#include <chrono>

namespace topocut {

namespace {

double read_ms(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace

double wall_clock_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double thread_cpu_ms() { return read_ms(CLOCK_THREAD_CPUTIME_ID); }

double process_cpu_ms() { return read_ms(CLOCK_PROCESS_CPUTIME_ID); }

}  // namespace topocut
