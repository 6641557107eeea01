#include "app/process_heap.hpp"

#include <malloc.h>

namespace kontakt::app {

bool keep_freed_memory_in_process() {
  // glibc: no block gets its own mapping (above the heap's reach it still maps one), and -1
  // switches trimming off.
  const bool from_heap = mallopt(M_MMAP_MAX, 0) == 1;
  const bool kept = mallopt(M_TRIM_THRESHOLD, -1) == 1;
  return from_heap && kept;
}

}  // namespace kontakt::app
