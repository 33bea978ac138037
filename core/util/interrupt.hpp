#pragma once
// Ctrl+C for a command-line program. After stop_work_on_interrupt(), SIGINT
// sets a flag, and every ThreadPool made afterwards polls it (its default
// cancellation check): running work stops at the next poll, about a
// millisecond of work per thread later, with ThreadPool's Cancelled exception,
// which the program catches to clean up and exit. A second SIGINT ends the
// process at once, in case the first one is not heeded.
namespace amls {

// Installs the SIGINT handler and the pools' default check. Call it once, at
// the start of main, before any pool exists.
void stop_work_on_interrupt();

// Whether SIGINT arrived since stop_work_on_interrupt() (or request_interrupt()).
bool interrupt_requested();

// What the SIGINT handler does, for tests.
void request_interrupt();

// The exit status of a process that SIGINT ended: 128 + 2, as shells report it.
inline constexpr int kInterruptedExitStatus = 130;

}  // namespace amls
