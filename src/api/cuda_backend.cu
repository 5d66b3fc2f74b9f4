// The CUDA backend's algorithm instantiations, in one translation unit.
//
// Until 2026-11-26 this was a guard against nvcc's extended __host__ __device__
// lambdas: their wrappers copy themselves through per-translation-unit function
// pointers, while the templates that launch them are weak symbols merged across units,
// so two .cu files instantiating the same template could launch through pointers that
// were never set (a call to address 0, bench/RESULTS.md 2026-11-23). The per-element
// lambdas are now __device__ lambdas in CUDA units (GDEL_LAMBDA, core/macros.hpp), whose
// wrappers hold no such pointers, so tests that instantiate internal templates
// themselves (tests/gpu/star_stage.cu) are safe too. One unit is kept because it
// instantiates each template once for the whole library.
// The files below are not compiled on their own (src/CMakeLists.txt excludes them).
#include "api/delaunay_cuda.cu"
#include "api/regular_cuda.cu"
#include "verify/verify_cuda.cu"
