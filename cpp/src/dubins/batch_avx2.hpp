// The CSC pass of the batch kernel, four pairs per AVX2 instruction (dubins_batch_avx2.cpp).
#pragma once

#include <cstddef>

namespace vistrack::detail {

// Whether this build has the AVX2 kernel and the CPU runs it.
bool avx2_kernel_available();

// For `count` pairs (rows of 3 doubles) whose |psi0| and |psi1 - psi0| are below the
// polynomial range (kFastTrigLimit): best CSC length (units of rho), its word code and whether
// a CCC word must still be checked, bit-identical to shortest_csc(make_frame_poly(...)).
void csc_block_avx2(const double* q0s, const double* q1s, std::size_t count, double rho, double snap_constant,
                    double* best, double* code, unsigned char* ccc);

}  // namespace vistrack::detail
