// The CUDA backend's algorithm instantiations, in ONE translation unit on purpose.
//
// nvcc's extended __host__ __device__ lambdas are wrapped in types named after their
// enclosing function, and each translation unit keeps its own table of the device-side
// functions. The templates that create and launch them (par::fill, par::parallel_for,
// everything in src/) are weak symbols: when two .cu files of one program instantiate
// the same ones, the linker keeps one copy of each, possibly from different files, and a
// launch can go through a table that was never filled (seen: a call to address 0 from
// par::parallel_for, bench/RESULTS.md 2026-11-23). One translation unit for every
// instantiation of the library removes the hazard inside the library; a test program
// that instantiates internal templates itself still has it (tests/gpu/star_stage.cu).
// The files below are not compiled on their own (src/CMakeLists.txt excludes them).
#include "api/delaunay_cuda.cu"
#include "api/regular_cuda.cu"
#include "verify/verify_cuda.cu"
