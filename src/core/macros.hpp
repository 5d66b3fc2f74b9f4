// Host/device annotations shared by every layer. The same algorithm source is
// compiled by nvcc for the CUDA backend and by the host compiler (Thrust OpenMP
// system) for the CPU backend; GDEL_HD marks functions usable in both.
#pragma once

#if defined(__CUDACC__)
#define GDEL_HD __host__ __device__
#define GDEL_DEVICE __device__
#define GDEL_FORCEINLINE __forceinline__
#define GDEL_NOINLINE __noinline__
#else
#define GDEL_HD
#define GDEL_DEVICE
#define GDEL_FORCEINLINE inline __attribute__((always_inline))
#define GDEL_NOINLINE __attribute__((noinline))
#endif

// The per-element lambdas handed to the parallel primitives (parallel_for, copy_if,
// select_indices, ...): `[=] GDEL_LAMBDA(std::int64_t i) { ... }`. In CUDA
// translation units they are nvcc's extended __device__ lambdas, never
// __host__ __device__ ones. An extended __host__ __device__ lambda's wrapper copies
// itself through function pointers that nvcc keeps in an anonymous namespace of each
// translation unit and sets only when that unit constructs the wrapper, while the
// functions templated on the wrapper type (parallel_for<W>, CUB's dispatch) are weak
// symbols the linker merges across units. Two units instantiating the same algorithm
// template (the library's, a test's) then share one copy that may read the other
// unit's pointers before they are set: a call to address 0 on the host (seen in
// tests/gpu_star_stage until 2026-11-26). A __device__ lambda's wrapper holds only its
// captures, so merged copies are all the same code. Such a lambda may be called only
// on the device on the CUDA backend; nothing on the host may call it or ask its return
// type (wrap it with cuda::proclaim_return_type where a CUB call needs that).
#if defined(__CUDACC__)
#define GDEL_LAMBDA __device__
#else
#define GDEL_LAMBDA
#endif

// True while compiling device code (the device pass of nvcc).
#if defined(__CUDA_ARCH__)
#define GDEL_DEVICE_PASS 1
#else
#define GDEL_DEVICE_PASS 0
#endif
