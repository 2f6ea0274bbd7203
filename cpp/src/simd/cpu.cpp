// The CPU check (see cpu.hpp). Here, not in an AVX2 file: it must itself run on any x86-64 CPU.
#include "simd/cpu.hpp"

#include <cstdlib>

namespace vistrack::detail {

bool avx2_kernel_available() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  // VISTRACK_SCALAR_KERNELS=1 keeps the plain loops: the same results, for timing the kernels
  // against them (docs/benchmarks.md).
  const char* scalar = std::getenv("VISTRACK_SCALAR_KERNELS");
  if (scalar != nullptr && scalar[0] != '\0' && scalar[0] != '0') return false;
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

}  // namespace vistrack::detail
