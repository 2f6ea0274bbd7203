// The CSC pass of the batch kernel, four pairs per AVX2 instruction (dubins_batch_avx2.cpp).
#pragma once

#include <cstddef>

namespace vistrack::detail {

// For `count` pairs (rows of 3 doubles) whose |psi0| and |psi1 - psi0| are below the
// polynomial range (kFastTrigLimit): shortest length (units of rho) and word code over all six
// words, bit-identical to shortest_length_normalised(make_frame_poly(...)); ccc is set to 0
// (kept for the scalar remainder, which flags pairs still needing the CCC words).
void csc_block_avx2(const double* q0s, const double* q1s, std::size_t count, double rho, double snap_constant,
                    double* best, double* code, unsigned char* ccc);

}  // namespace vistrack::detail
