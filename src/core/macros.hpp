// Host/device annotations shared by every layer. The same algorithm source is
// compiled by nvcc for the CUDA backend and by the host compiler (Thrust OpenMP
// system) for the CPU backend; GDEL_HD marks functions usable in both.
#pragma once

#if defined(__CUDACC__)
#define GDEL_HD __host__ __device__
#define GDEL_DEVICE __device__
#define GDEL_FORCEINLINE __forceinline__
#else
#define GDEL_HD
#define GDEL_DEVICE
#define GDEL_FORCEINLINE inline __attribute__((always_inline))
#endif

// True while compiling device code (the device pass of nvcc).
#if defined(__CUDA_ARCH__)
#define GDEL_DEVICE_PASS 1
#else
#define GDEL_DEVICE_PASS 0
#endif
