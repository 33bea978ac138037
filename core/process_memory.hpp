#pragma once

namespace amls {

// The process's peak resident memory so far in MiB (VmHWM), or 0 where unknown.
double peak_memory_mib();

}  // namespace amls
