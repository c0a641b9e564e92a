#pragma once
// Allocator set-up of the command-line program (process-wide, so here and not in the library).

namespace rollcontact::cli {

/// Keeps freed memory in the process and backs the heap with transparent huge pages where the
/// system allows them (glibc on Linux; elsewhere, and under sanitizers' allocators, no effect).
/// Call first in main(), before the heap is in use.
void prepare_heap() noexcept;

}  // namespace rollcontact::cli
