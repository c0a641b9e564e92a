#include "heap_setup.hpp"

#include <cstddef>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#endif

namespace rollcontact::cli {

#if defined(__GLIBC__) && defined(__linux__)

namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;
/// Heap the first growth reserves and advises for transparent huge pages [bytes]; virtual
/// until touched.
constexpr std::size_t kHeapReserve = 256 * kMiB;
/// Blocks from this size on keep glibc's own mmap/munmap [bytes]: glibc's largest threshold,
/// so that the FFT buffers of large grids (12 MB at 575×647) come from the huge-page heap too.
constexpr std::size_t kMmapThreshold = 32 * kMiB;
constexpr std::size_t kHugePage = 2 * kMiB;

std::uintptr_t align_up(std::uintptr_t v, std::size_t a) {
  return (v + a - 1) / a * a;
}

}  // namespace

void prepare_heap() noexcept {
  // glibc's dynamic thresholds map blocks from 128 kB on afresh and give the heap's top back as
  // soon as 256 kB are free; a sweep meets a new grid every few cases, and its operators (spectra,
  // FFT buffers of 0.1–12 MB) then came from fresh pages, one fault per 4 kB: 11 % of a 0.5 mm
  // wheel/rail sweep's time (perf). Fixed thresholds keep such blocks in the heap, ...
  mallopt(M_MMAP_THRESHOLD, static_cast<int>(kMmapThreshold));
  mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * kHeapReserve));
  mallopt(M_TOP_PAD, static_cast<int>(kHeapReserve));
  // ... and the heap, grown once by the reserve, asks for huge pages: one fault per 2 MB. The
  // fixed thresholds alone changed nothing measurable; with the pages, sweeps ran 3–16 % faster
  // (docs/benchmarks.md). volatile: the compiler would drop a block freed unused.
  const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* volatile probe = std::malloc(kHugePage);
  std::free(probe);
  const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
  const std::uintptr_t start = align_up(before, kHugePage);
  const std::uintptr_t end = after / kHugePage * kHugePage;
  if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
}

#else

void prepare_heap() noexcept {}

#endif

}  // namespace rollcontact::cli
