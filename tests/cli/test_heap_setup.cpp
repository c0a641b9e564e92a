// The command-line program's allocator set-up (apps/rollcontact/heap_setup.cpp): medium blocks
// stay in the heap, and the heap is eligible for transparent huge pages. A set-up compiled out
// by mistake (a missing glibc macro) left every sweep 3–16 % slower without a visible sign.

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "heap_setup.hpp"
#include "support/files.hpp"

#if defined(__GLIBC__) && defined(__linux__)
#include <unistd.h>
#endif

namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define ROLLCONTACT_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define ROLLCONTACT_TEST_SANITIZED 1
#endif
#ifdef ROLLCONTACT_TEST_SANITIZED
constexpr bool kSanitizerAllocator = true;
#else
constexpr bool kSanitizerAllocator = false;
#endif

#if defined(__GLIBC__) && defined(__linux__)

/// What /proc/self/smaps says of the mapping that holds `address`.
struct Mapping {
  bool found = false;
  std::string name;       ///< "[heap]" for the break's heap
  int thp_eligible = -1;  ///< -1: the kernel does not say
};

Mapping mapping_at(std::uintptr_t address) {
  std::istringstream smaps(rollcontact::test_support::file_text("/proc/self/smaps"));
  std::string line;
  Mapping m;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream header(line);
    if (header >> std::hex >> lo >> dash >> hi && dash == '-') {
      if (m.found) return m;  // past the mapping
      inside = lo <= address && address < hi;
      if (inside) {
        m.found = true;
        std::string field;
        for (int k = 0; k < 4 && header >> field; ++k) {  // perms, offset, device, inode
        }
        header >> m.name;
      }
      continue;
    }
    if (inside && line.rfind("THPeligible:", 0) == 0) m.thp_eligible = std::atoi(line.c_str() + 12);
  }
  return m;
}

TEST(HeapSetup, MediumBlocksComeFromTheHeapAndTheHeapMayUseHugePages) {
  const auto heap_start = reinterpret_cast<std::uintptr_t>(sbrk(0));
  rollcontact::cli::prepare_heap();
  const auto heap_end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  if (kSanitizerAllocator) GTEST_SKIP() << "a sanitizer's allocator does not use the heap";
  EXPECT_GE(heap_end - heap_start, std::size_t{64} << 20)
      << "the heap was not grown by the reserve";

  // 1 MiB: mapped afresh by glibc's default threshold (128 kB), in the heap after the set-up.
  void* volatile block = std::malloc(std::size_t{1} << 20);
  EXPECT_EQ(mapping_at(reinterpret_cast<std::uintptr_t>(block)).name, "[heap]");

  // The reserve's middle (2 MiB pages are whole there) may use huge pages where the system
  // allows them at all.
  const std::string thp =
      rollcontact::test_support::file_text("/sys/kernel/mm/transparent_hugepage/enabled");
  const Mapping reserve = mapping_at(heap_start + (heap_end - heap_start) / 2);
  ASSERT_TRUE(reserve.found);
  if (!thp.empty() && thp.find("[never]") == std::string::npos && reserve.thp_eligible >= 0) {
    EXPECT_EQ(reserve.thp_eligible, 1) << "the heap was not advised for huge pages";
  }
  std::free(block);
}

#else

TEST(HeapSetup, IsANoOpWithoutGlibc) {
  rollcontact::cli::prepare_heap();
  SUCCEED();
}

#endif

}  // namespace
