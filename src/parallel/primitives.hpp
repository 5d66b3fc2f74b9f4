// Device-wide primitives on both backends: parallel_for, scan, compaction, sort,
// reduce, unique, gather. CPU: Thrust's OpenMP system / OpenMP loops. CUDA: CUB
// device-wide algorithms with temporaries from the stream-ordered pool, and a
// grid-stride kernel for parallel_for.
//
// Every call is enqueued on the context's stream. Calls that return a host value
// (counts, reductions) synchronize; the others do not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include <thrust/copy.h>
#include <thrust/count.h>
#include <thrust/execution_policy.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/sort.h>
#include <thrust/system/omp/execution_policy.h>
#include <thrust/unique.h>

#include "parallel/backend.hpp"
#include "parallel/check.hpp"
#include "parallel/memory.hpp"

#if defined(__CUDACC__)
#include <cub/device/device_radix_sort.cuh>
#include <cub/device/device_reduce.cuh>
#include <cub/device/device_scan.cuh>
#include <cub/device/device_select.cuh>
#endif

namespace gdel::par {

namespace detail {
// f(i) as a T (select_mapped_to's input: an explicit type, as CUB needs from a lambda
// whose return type the host cannot query)
template <class T, class F>
struct MapIndex {
  F f;
  GDEL_HD T operator()(std::int64_t i) const { return f(i); }
};
}  // namespace detail

// ---------------------------------------------------------------------------
// CPU backend
// ---------------------------------------------------------------------------

// Below this many items a CPU primitive runs on the calling thread: waking the team
// costs more than the work (it dominated the thousands of tiny flip iterations of
// degenerate inputs such as two skew lines). Results do not depend on it.
inline constexpr std::int64_t kSerialBelow = 4096;

// Runs op(policy) with Thrust's sequential policy for small n, OpenMP otherwise.
template <class Op>
decltype(auto) with_policy(std::size_t n, Op op) {
  if (static_cast<std::int64_t>(n) < kSerialBelow) return op(thrust::seq);
  return op(thrust::omp::par);
}

// f(i) for i in [0, n), in parallel. f must be safe to run concurrently.
template <class F>
void parallel_for(Context<Cpu>&, std::int64_t n, F f) {
#pragma omp parallel for schedule(static) if (n >= kSerialBelow)
  for (std::int64_t i = 0; i < n; ++i) f(i);
}

template <class T>
void exclusive_scan(Context<Cpu>&, const T* in, T* out, std::size_t n) {
  with_policy(n, [&](auto pol) { thrust::exclusive_scan(pol, in, in + n, out, T(0)); });
}
template <class T>
void inclusive_scan(Context<Cpu>&, const T* in, T* out, std::size_t n) {
  with_policy(n, [&](auto pol) { thrust::inclusive_scan(pol, in, in + n, out); });
}
// Synchronizes. Sum of all elements.
template <class T>
T reduce_sum(Context<Cpu>&, const T* in, std::size_t n) {
  return with_policy(n, [&](auto pol) { return thrust::reduce(pol, in, in + n, T(0)); });
}
template <class T>
T reduce_max(Context<Cpu>&, const T* in, std::size_t n, T init) {
  return with_policy(n, [&](auto pol) { return thrust::reduce(pol, in, in + n, init, thrust::maximum<T>()); });
}
template <class T>
T reduce_min(Context<Cpu>&, const T* in, std::size_t n, T init) {
  return with_policy(n, [&](auto pol) { return thrust::reduce(pol, in, in + n, init, thrust::minimum<T>()); });
}
// Stable compaction of values satisfying pred; returns the count (synchronizes).
template <class T, class Pred>
std::size_t copy_if(Context<Cpu>&, const T* in, T* out, std::size_t n, Pred pred) {
  return with_policy(n, [&](auto pol) { return static_cast<std::size_t>(thrust::copy_if(pol, in, in + n, out, pred) - out); });
}
// Indices i in [0, n) with pred(i), ascending; returns the count (synchronizes).
template <class I, class Pred>
std::size_t select_indices(Context<Cpu>&, std::size_t n, I* out, Pred pred) {
  thrust::counting_iterator<I> first(0);
  return with_policy(n, [&](auto pol) {
    return static_cast<std::size_t>(thrust::copy_if(pol, first, first + n, out, pred) - out);
  });
}
// The same with the count written to *count (backend memory) instead of returned: the
// CUDA form does not wait for the host; later calls read the count on the backend
// (parallel_for_counted, for_each_with_scratch's count, predicates that read it).
template <class I, class Pred>
void select_indices_to(Context<Cpu>& c, std::size_t n, I* out, std::int64_t* count, Pred pred) {
  *count = static_cast<std::int64_t>(select_indices(c, n, out, pred));
}
// The values f(i) (of type T) that keep(f(i)) accepts, for i in [0, n) in ascending order,
// to out; their count to *count (backend memory; the CUDA form does not wait): a
// selection and a map in one pass.
template <class T, class F, class Keep>
void select_mapped_to(Context<Cpu>&, std::size_t n, T* out, std::int64_t* count, F f, Keep keep) {
  auto in = thrust::make_transform_iterator(thrust::counting_iterator<std::int64_t>(0), detail::MapIndex<T, F>{f});
  *count = with_policy(n, [&](auto pol) { return static_cast<std::int64_t>(thrust::copy_if(pol, in, in + n, out, keep) - out); });
}
// f(i) for i in [0, min(n, *count)), *count in backend memory, set by an earlier call on
// the stream: n bounds the work the host knows of, *count is what the backend found.
template <class F>
void parallel_for_counted(Context<Cpu>& c, std::int64_t n, const std::int64_t* count, F f) {
  parallel_for(c, n < *count ? n : *count, f);
}
// Number of indices i in [0, n) with pred(i) (synchronizes): to size an output exactly
// before select_indices when few are expected.
template <class Pred>
std::int64_t count_indices(Context<Cpu>&, std::size_t n, Pred pred) {
  thrust::counting_iterator<std::int64_t> first(0);
  return with_policy(n, [&](auto pol) { return static_cast<std::int64_t>(thrust::count_if(pol, first, first + n, pred)); });
}
namespace detail {
// Thrust 3.0's OpenMP stable sort mis-orders negative signed integer keys (its radix
// path treats them as unsigned). Sort signed keys as unsigned with the sign bit
// flipped, which preserves their order.
template <class K>
void flip_sign_bits(K* keys, std::size_t n) {
  using U = std::make_unsigned_t<K>;
  const U bit = U(1) << (sizeof(K) * 8 - 1);
  U* u = reinterpret_cast<U*>(keys);
#pragma omp parallel for schedule(static) if (static_cast<std::int64_t>(n) >= kSerialBelow)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) u[i] ^= bit;
}
}  // namespace detail

// Stable sort of integer keys; only bits [0, end_bit) may differ (a hint for the
// radix sort; the CPU sort compares whole keys).
template <class K>
void sort_keys(Context<Cpu>&, K* keys, std::size_t n, int /*end_bit*/ = int(sizeof(K) * 8)) {
  static_assert(std::is_integral_v<K>, "sort_keys sorts integer keys");
  if constexpr (std::is_signed_v<K>) {
    using U = std::make_unsigned_t<K>;
    detail::flip_sign_bits(keys, n);
    U* u = reinterpret_cast<U*>(keys);
    with_policy(n, [&](auto pol) { thrust::stable_sort(pol, u, u + n); });
    detail::flip_sign_bits(keys, n);
  } else {
    with_policy(n, [&](auto pol) { thrust::stable_sort(pol, keys, keys + n); });
  }
}
template <class K, class V>
void sort_pairs(Context<Cpu>&, K* keys, V* values, std::size_t n, int /*end_bit*/ = int(sizeof(K) * 8)) {
  static_assert(std::is_integral_v<K>, "sort_pairs sorts integer keys");
  if constexpr (std::is_signed_v<K>) {
    using U = std::make_unsigned_t<K>;
    detail::flip_sign_bits(keys, n);
    U* u = reinterpret_cast<U*>(keys);
    with_policy(n, [&](auto pol) { thrust::stable_sort_by_key(pol, u, u + n, values); });
    detail::flip_sign_bits(keys, n);
  } else {
    with_policy(n, [&](auto pol) { thrust::stable_sort_by_key(pol, keys, keys + n, values); });
  }
}
// The same over the first n elements of two buffers (each at least n long); the CUDA
// backend may hand the buffers its alternate arrays instead of copying the result back.
template <class K, class V>
void sort_pairs(Context<Cpu>& c, Buffer<K, Cpu>& keys, Buffer<V, Cpu>& values, std::size_t n,
                int end_bit = int(sizeof(K) * 8)) {
  sort_pairs(c, keys.data(), values.data(), n, end_bit);
}
// In-place removal of consecutive duplicates; returns the new count (synchronizes).
// (Thrust's in-place unique on the OpenMP system is not safe with several threads:
// it loses or keeps extra elements. Compact from a copy instead.)
template <class T>
std::size_t unique(Context<Cpu>& c, T* data, std::size_t n) {
  if (n < 2) return n;
  Buffer<T, Cpu> tmp(c, n);
  std::memcpy(tmp.data(), data, n * sizeof(T));
  const T* t = tmp.data();
  thrust::counting_iterator<std::size_t> first(0);
  return with_policy(n, [&](auto pol) {
    return static_cast<std::size_t>(
        thrust::copy_if(pol, t, t + n, first, data, [t](std::size_t i) { return i == 0 || !(t[i] == t[i - 1]); }) -
        data);
  });
}

// ---------------------------------------------------------------------------
// CUDA backend
// ---------------------------------------------------------------------------
#if defined(__CUDACC__)

namespace detail {
template <class F>
__global__ void for_kernel(std::int64_t n, F f) {
  const std::int64_t stride = std::int64_t(gridDim.x) * blockDim.x;
  for (std::int64_t i = std::int64_t(blockIdx.x) * blockDim.x + threadIdx.x; i < n; i += stride) f(i);
}
template <class F>
__global__ void for_counted_kernel(std::int64_t n, const std::int64_t* count, F f) {
  const std::int64_t c = *count;
  const std::int64_t m = c < n ? c : n;
  const std::int64_t stride = std::int64_t(gridDim.x) * blockDim.x;
  for (std::int64_t i = std::int64_t(blockIdx.x) * blockDim.x + threadIdx.x; i < m; i += stride) f(i);
}
inline unsigned grid_for(const Context<Cuda>& c, std::int64_t n, int block) {
  std::int64_t want = (n + block - 1) / block;
  std::int64_t cap = std::int64_t(c.sm_count()) * 64;
  return static_cast<unsigned>(want < cap ? want : cap);
}
// Runs a CUB call twice: size query, then with temporaries from the pool.
template <class Call>
void with_temp(Context<Cuda>& c, Call call) {
  std::size_t bytes = 0;
  GDEL_CUDA_CHECK(call(nullptr, bytes));
  Buffer<unsigned char, Cuda> tmp(c, bytes);
  GDEL_CUDA_CHECK(call(tmp.data(), bytes));
}
template <class T>
struct IndexPred;
}  // namespace detail

template <class F>
void parallel_for(Context<Cuda>& c, std::int64_t n, F f, int block = 256) {
  if (n <= 0) return;
  detail::for_kernel<<<detail::grid_for(c, n, block), block, 0, c.stream()>>>(n, f);
  GDEL_CUDA_CHECK_LAUNCH("parallel_for");
}

// The bound n is what the host knows; the count is usually far below it (a selection's
// survivors), so the grid is capped lower than parallel_for's: the blocks past the
// count only read it and leave.
template <class F>
void parallel_for_counted(Context<Cuda>& c, std::int64_t n, const std::int64_t* count, F f, int block = 256) {
  if (n <= 0) return;
  const unsigned cap = static_cast<unsigned>(c.sm_count()) * 8;
  const unsigned grid = detail::grid_for(c, n, block);
  detail::for_counted_kernel<<<grid < cap ? grid : cap, block, 0, c.stream()>>>(n, count, f);
  GDEL_CUDA_CHECK_LAUNCH("parallel_for_counted");
}

template <class T>
void exclusive_scan(Context<Cuda>& c, const T* in, T* out, std::size_t n) {
  if (!n) return;
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceScan::ExclusiveSum(t, b, in, out, static_cast<std::int64_t>(n), c.stream());
  });
}
template <class T>
void inclusive_scan(Context<Cuda>& c, const T* in, T* out, std::size_t n) {
  if (!n) return;
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceScan::InclusiveSum(t, b, in, out, static_cast<std::int64_t>(n), c.stream());
  });
}
template <class T>
T reduce_sum(Context<Cuda>& c, const T* in, std::size_t n) {
  if (!n) return T(0);
  Buffer<T, Cuda> r(c, 1);
  T* rp = r.data();
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceReduce::Sum(t, b, in, rp, static_cast<std::int64_t>(n), c.stream());
  });
  return r.get(0);
}
template <class T, class Op>
T reduce_with(Context<Cuda>& c, const T* in, std::size_t n, Op op, T init) {
  if (!n) return init;
  Buffer<T, Cuda> r(c, 1);
  T* rp = r.data();
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceReduce::Reduce(t, b, in, rp, static_cast<std::int64_t>(n), op, init, c.stream());
  });
  return r.get(0);
}
template <class T>
T reduce_max(Context<Cuda>& c, const T* in, std::size_t n, T init) {
  return reduce_with(c, in, n, cuda::maximum<T>(), init);
}
template <class T>
T reduce_min(Context<Cuda>& c, const T* in, std::size_t n, T init) {
  return reduce_with(c, in, n, cuda::minimum<T>(), init);
}
namespace detail {
// The one stream compaction of the CUDA backend: in[i] for i in [0, n) that keep accepts,
// in order, to out; their count to *count (device memory, no wait).
template <class In, class T, class Keep>
void select_to(Context<Cuda>& c, In in, std::size_t n, T* out, std::int64_t* count, Keep keep) {
  if (!n) {
    Memory<Cuda>::memset(c, count, 0, sizeof(std::int64_t));
    return;
  }
  with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceSelect::If(t, b, in, out, count, static_cast<std::int64_t>(n), keep, c.stream());
  });
}
}  // namespace detail
template <class T, class Pred>
std::size_t copy_if(Context<Cuda>& c, const T* in, T* out, std::size_t n, Pred pred) {
  if (!n) return 0;
  Buffer<std::int64_t, Cuda> cnt(c, 1);
  detail::select_to(c, in, n, out, cnt.data(), pred);
  return static_cast<std::size_t>(cnt.get(0));
}
template <class I, class Pred>
void select_indices_to(Context<Cuda>& c, std::size_t n, I* out, std::int64_t* count, Pred pred) {
  detail::select_to(c, thrust::counting_iterator<I>(0), n, out, count, pred);
}
template <class T, class F, class Keep>
void select_mapped_to(Context<Cuda>& c, std::size_t n, T* out, std::int64_t* count, F f, Keep keep) {
  detail::select_to(c, thrust::make_transform_iterator(thrust::counting_iterator<std::int64_t>(0), detail::MapIndex<T, F>{f}),
                    n, out, count, keep);
}
template <class I, class Pred>
std::size_t select_indices(Context<Cuda>& c, std::size_t n, I* out, Pred pred) {
  if (!n) return 0;
  Buffer<std::int64_t, Cuda> cnt(c, 1);
  select_indices_to(c, n, out, cnt.data(), pred);
  return static_cast<std::size_t>(cnt.get(0));
}
namespace detail {
template <class Pred>
struct OneIf {
  Pred pred;
  __host__ __device__ std::int64_t operator()(std::int64_t i) const { return pred(i) ? 1 : 0; }
};
}  // namespace detail
template <class Pred>
std::int64_t count_indices(Context<Cuda>& c, std::size_t n, Pred pred) {
  if (!n) return 0;
  Buffer<std::int64_t, Cuda> r(c, 1);
  std::int64_t* rp = r.data();
  thrust::counting_iterator<std::int64_t> first(0);
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceReduce::TransformReduce(t, b, first, rp, static_cast<std::int64_t>(n), cuda::std::plus<>{},
                                              detail::OneIf<Pred>{pred}, std::int64_t(0), c.stream());
  });
  return r.get(0);
}
template <class K>
void sort_keys(Context<Cuda>& c, K* keys, std::size_t n, int end_bit = int(sizeof(K) * 8)) {
  if (n < 2) return;
  Buffer<K, Cuda> alt(c, n);
  cub::DoubleBuffer<K> db(keys, alt.data());
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceRadixSort::SortKeys(t, b, db, static_cast<std::int64_t>(n), 0, end_bit, c.stream());
  });
  if (db.Current() != keys) detail::Memory<Cuda>::copy(c, keys, db.Current(), n * sizeof(K));
}
namespace detail {
// The radix pair sort of both sort_pairs forms: the result in dk.Current(), dv.Current().
template <class K, class V>
void radix_pairs(Context<Cuda>& c, cub::DoubleBuffer<K>& dk, cub::DoubleBuffer<V>& dv, std::size_t n, int end_bit) {
  with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceRadixSort::SortPairs(t, b, dk, dv, static_cast<std::int64_t>(n), 0, end_bit, c.stream());
  });
}
}  // namespace detail
template <class K, class V>
void sort_pairs(Context<Cuda>& c, K* keys, V* values, std::size_t n, int end_bit = int(sizeof(K) * 8)) {
  if (n < 2) return;
  Buffer<K, Cuda> altk(c, n);
  Buffer<V, Cuda> altv(c, n);
  cub::DoubleBuffer<K> dk(keys, altk.data());
  cub::DoubleBuffer<V> dv(values, altv.data());
  detail::radix_pairs(c, dk, dv, n, end_bit);
  if (dk.Current() != keys) detail::Memory<Cuda>::copy(c, keys, dk.Current(), n * sizeof(K));
  if (dv.Current() != values) detail::Memory<Cuda>::copy(c, values, dv.Current(), n * sizeof(V));
}
// The radix sort's result lies in its alternate arrays after an odd number of passes
// (ceil(end_bit / 8): three for 24 bits): there the buffers take those arrays' storage
// (with their elements past n copied over) instead of a copy back of n keys and values.
// (Pointers into the buffers taken before the call are stale after it.)
template <class K, class V>
void sort_pairs(Context<Cuda>& c, Buffer<K, Cuda>& keys, Buffer<V, Cuda>& values, std::size_t n,
                int end_bit = int(sizeof(K) * 8)) {
  if (n < 2) return;
  Buffer<K, Cuda> altk(c, keys.size());
  Buffer<V, Cuda> altv(c, values.size());
  cub::DoubleBuffer<K> dk(keys.data(), altk.data());
  cub::DoubleBuffer<V> dv(values.data(), altv.data());
  detail::radix_pairs(c, dk, dv, n, end_bit);
  auto take = [&](auto& buf, auto& alt, const void* cur) {
    if (cur == static_cast<const void*>(buf.data())) return;
    using T = std::remove_reference_t<decltype(*buf.data())>;
    if (buf.size() > n) detail::Memory<Cuda>::copy(c, alt.data() + n, buf.data() + n, (buf.size() - n) * sizeof(T));
    std::swap(buf, alt);
  };
  take(keys, altk, dk.Current());
  take(values, altv, dv.Current());
}
template <class T>
std::size_t unique(Context<Cuda>& c, T* data, std::size_t n) {
  if (n < 2) return n;
  Buffer<T, Cuda> out(c, n);
  Buffer<std::int64_t, Cuda> cnt(c, 1);
  std::int64_t* cp = cnt.data();
  T* op = out.data();
  detail::with_temp(c, [&](void* t, std::size_t& b) {
    return cub::DeviceSelect::Unique(t, b, data, op, cp, static_cast<std::int64_t>(n), c.stream());
  });
  std::size_t m = static_cast<std::size_t>(cnt.get(0));
  detail::Memory<Cuda>::copy(c, data, op, m * sizeof(T));
  return m;
}

#endif  // __CUDACC__

// ---------------------------------------------------------------------------
// Backend-generic helpers built on the above
// ---------------------------------------------------------------------------

// out[i] = value for i in [0, n).
template <class B, class T>
void fill(Context<B>& c, T* out, std::size_t n, T value) {
  parallel_for(c, static_cast<std::int64_t>(n), [=] GDEL_LAMBDA(std::int64_t i) { out[i] = value; });
}
// out[i] = first + i.
template <class B, class T>
void sequence(Context<B>& c, T* out, std::size_t n, T first = T(0)) {
  parallel_for(c, static_cast<std::int64_t>(n), [=] GDEL_LAMBDA(std::int64_t i) { out[i] = first + T(i); });
}
// out[i] = in[map[i]].
template <class B, class T, class I>
void gather(Context<B>& c, const I* map, const T* in, T* out, std::size_t n) {
  parallel_for(c, static_cast<std::int64_t>(n), [=] GDEL_LAMBDA(std::int64_t i) { out[i] = in[map[i]]; });
}
// Exclusive scan in place of counts; returns the total (synchronizes). counts has
// n + 1 elements; counts[n] receives the total.
template <class B, class T>
T counts_to_offsets(Context<B>& c, T* counts, std::size_t n) {
  // counts[n] is scratch; set it to 0 so the scan over n + 1 gives the total there.
  parallel_for(c, 1, [=] GDEL_LAMBDA(std::int64_t) { counts[n] = T(0); });
  exclusive_scan(c, counts, counts, n + 1);
  T total;
  detail::Memory<B>::to_host(c, &total, counts + n, sizeof(T));
  return total;
}

}  // namespace gdel::par
