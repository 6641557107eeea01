#include "linsolve/blas_threads.hpp"

#include <dlfcn.h>

#include <initializer_list>

namespace kontakt::linsolve {

bool set_blas_threads(int threads) {
  // Looked up by name so the build does not tie itself to one BLAS implementation; Debian
  // switches implementations through update-alternatives behind libblas.so.3.
  using SetThreads = void (*)(int);
  for (const char* symbol : {"openblas_set_num_threads", "bli_thread_set_num_threads"}) {
    if (auto fn = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, symbol))) {
      fn(threads);
      return true;
    }
  }
  return false;
}

}  // namespace kontakt::linsolve
