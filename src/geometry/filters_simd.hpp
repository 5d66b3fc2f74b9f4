// Host SIMD forms of the insphere and orient3d filters (filters.hpp): several independent
// tests in the lanes of one vector. Host code only (GCC/Clang vector extensions); the CUDA
// backend runs a test per thread instead.
#pragma once

namespace gdel::geom {

// insphere_filter of up to four tests sharing e: lane k < n is the test (t[k][0], t[k][1],
// t[k][2], t[k][3], e), and out[k] gets insphere_filter's answer for it (-1, +1 or
// kUncertain), the same bit for bit. n in [1, 4]. AVX2 where the processor has it (the
// choice is made when the program loads), else SSE2.
void insphere_filter4(const double* const (*t)[4], const double* e, int n, int* out);

// orient3d_filter of up to four tests sharing d: lane k < n is the test (t[k][0], t[k][1],
// t[k][2], d); out[k] gets orient3d_filter's answer for it, the same bit for bit.
void orient3d_filter4(const double* const (*t)[3], const double* d, int n, int* out);

}  // namespace gdel::geom
