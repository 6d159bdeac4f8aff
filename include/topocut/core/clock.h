#pragma once
// Clocks in milliseconds, for the library's own timings (stage times, reports) and its callers'.
namespace topocut {

// A clock read in milliseconds from an arbitrary start; only differences of two readings mean anything.
using ClockMs = double (*)();

// Wall-clock time (steady, never set back).
double wall_clock_ms();

// CPU time of the calling thread: what a thread's work costs on a busy machine, where wall-clock time
// also counts the other jobs' turns. Worker threads started by the work (OpenCV's) are not counted.
double thread_cpu_ms();

// CPU time of the whole process, every thread counted.
double process_cpu_ms();

}  // namespace topocut
