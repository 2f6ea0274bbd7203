// The CPU check (see cpu.hpp). Here, not in an AVX2 file: it must itself run on any x86-64 CPU.
#include "simd/cpu.hpp"

namespace vistrack::detail {

bool avx2_kernel_available() {
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

}  // namespace vistrack::detail
