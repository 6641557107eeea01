// The heap policy of a process that runs a job: freed memory stays with the process.
#pragma once

namespace kontakt::app {

/// Large blocks come from the heap rather than from mappings of their own, and the heap's free
/// top is never returned to the kernel. Why: a contact model frees its numeric factor and
/// allocates a new one whenever the contact pattern changes (hundreds of MB at 60k equations);
/// an unmapped block's pages are zeroed again by the kernel at their next first touch, which
/// made the first factorisation of a new pattern ~1 s (80 %) slower on the a/h 12 Hertz
/// sphere. A job process holds its peak until it ends anyway; the daemon runs one job per
/// process. False when the allocator does not take the settings (a sanitizer's).
bool keep_freed_memory_in_process();

}  // namespace kontakt::app
