#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

#include "app/process_heap.hpp"

using namespace kontakt;

namespace {

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// Allocates and writes `bytes`; the asm keeps the compiler from eliding the block.
char* touched_block(std::size_t bytes) {
  auto* block = static_cast<char*>(std::malloc(bytes));
  std::memset(block, 1, bytes);
  asm volatile("" : : "r"(block) : "memory");
  return block;
}

}  // namespace

TEST(ProcessHeap, AFreedFactorSizedBlockIsReusedWithoutTheKernelZeroingItAgain) {
  // What a new contact pattern does to the numeric factor: free 128 MB, allocate it again.
  // Mapped and unmapped, each of its 32768 pages faults again; kept, next to none do.
  ASSERT_TRUE(app::keep_freed_memory_in_process());
  const std::size_t bytes = std::size_t{128} << 20;
  const long pages = static_cast<long>(bytes / static_cast<std::size_t>(sysconf(_SC_PAGESIZE)));
  std::free(touched_block(bytes));
  const long before = minor_faults();
  char* again = touched_block(bytes);
  const long faults = minor_faults() - before;
  std::free(again);
  EXPECT_LT(faults, pages / 100) << "of " << pages << " pages";
}
