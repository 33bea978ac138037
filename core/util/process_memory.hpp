#pragma once

namespace amls {

// The process's peak resident memory so far in MiB (VmHWM), or 0 where unknown.
double peak_memory_mib();

// Starts a new peak: resets VmHWM to the current resident size (Linux's
// /proc/self/clear_refs, value 5). Returns false where that is not possible.
bool reset_peak_memory();

// The machine's physical memory in MiB, or 0 where unknown.
double physical_memory_mib();

}  // namespace amls
