#pragma once
// Process-wide tuning of the C allocator for programs that work on large images: a program's choice,
// not the library's (the Python module and the ROS node leave their host process's allocator alone),
// made by the topocut command and the benchmarks, which compile this file too.

namespace topocut {

// Makes glibc keep freed large blocks for reuse and reserves the first 256 MiB of heap in transparent
// huge pages: every stage allocates map-sized buffers, and fresh pages faulting in one by one cost
// more than the work on virtual machines (benchmarks/README.md, "Speed, same output: huge pages").
// Peak memory grows by at most one huge page. Call once at program start; no effect outside glibc.
void keep_freed_memory_for_reuse();

}  // namespace topocut
