#pragma once
// Process-wide tuning of the C allocator for programs that work on large images: a program's choice,
// not the library's (the Python module and the ROS node leave their host process's allocator alone),
// made by the topocut command and the benchmarks, which compile this file too.

namespace topocut {

// Makes glibc keep freed large blocks for reuse instead of returning them to the system: every
// stage allocates and frees map-sized buffers (masks, labels, distance images), and by default each
// one above 128 KiB is a fresh mapping whose pages fault in one by one; on virtual machines that
// cost more than the work itself (office_a: cleaning 41 -> 15 ms, segment 43 -> 18 ms). The first
// 256 MiB of the heap are also reserved (address space only) with transparent huge pages advised,
// so that the first use of a buffer faults 2 MiB at a time (`topocut segment` of Benedetti.pgm:
// 5450 -> 1450 page faults, 126 -> 73 ms CPU). Peak memory grows by at most the last huge page the
// heap touches (1-2 MB); memory is returned when the process ends. Call once at program start (the topocut command and the benchmarks do). No
// effect with other C libraries.
void keep_freed_memory_for_reuse();

}  // namespace topocut
