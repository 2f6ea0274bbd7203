// What the CPU running the library can do, for the kernels built for more than plain x86-64
// (dubins_batch_avx2.cpp, corner_scan_avx2.cpp); private to the library.
#pragma once

namespace vistrack::detail {

// Whether this build has the AVX2 kernels and the CPU runs them (and the environment variable
// VISTRACK_SCALAR_KERNELS is unset or 0).
bool avx2_kernel_available();

}  // namespace vistrack::detail
