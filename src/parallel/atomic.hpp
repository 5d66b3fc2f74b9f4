// Atomics for algorithm code on both backends, through libcu++'s cuda::atomic_ref
// (device scope on the GPU, plain std::atomic semantics on the host). Relaxed
// ordering unless stated: kernels are separated by stream order, which orders them.
#pragma once

#include <cuda/atomic>

#include "core/macros.hpp"

namespace gdel::par {

template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_add(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_add(v, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_sub(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_sub(v, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_min(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_min(v, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_max(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_max(v, cuda::memory_order_relaxed);
}
// atomic_max without its result, and only a load where *p already holds v or more: for
// many writers of one address, most of which lose (a maximum only grows, so a value seen
// at or above v stays there).
template <class T>
GDEL_HD GDEL_FORCEINLINE void atomic_raise(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  if (r.load(cuda::memory_order_relaxed) < v) r.fetch_max(v, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_or(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.fetch_or(v, cuda::memory_order_relaxed);
}
// Returns true and stores desired iff *p == expected.
template <class T>
GDEL_HD GDEL_FORCEINLINE bool atomic_cas(T* p, T expected, T desired) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  return r.compare_exchange_strong(expected, desired, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE void atomic_store(T* p, T v) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*p);
  r.store(v, cuda::memory_order_relaxed);
}
template <class T>
GDEL_HD GDEL_FORCEINLINE T atomic_load(const T* p) {
  cuda::atomic_ref<T, cuda::thread_scope_device> r(*const_cast<T*>(p));
  return r.load(cuda::memory_order_relaxed);
}

}  // namespace gdel::par
