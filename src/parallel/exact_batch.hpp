// The fast-kernel / exact-kernel split (ALGORITHMS.md §1.3) as one reusable step.
//
// fast_then_exact(ctx, n, undecided, fast, exact, work_doubles):
//   pass 1 (all items, full occupancy): fast(i), false when the floating-point
//          filters could not decide item i;
//   compaction of the undecided items;
//   pass 2 (only those): exact(i, work) with `work` a private scratch of
//          work_doubles doubles for expansion arithmetic.
// fast_then_exact_tiered(..., tiered): exact returns bool (false: not decided). With
// `tiered`, between the two passes every undecided item is first tried with
// work = nullptr (no scratch: see exact_threads for how many threads); exact answers false
// where it needs the scratch (flip::Geo on integer input: its evaluations over finite
// points run in the integer stage and never touch it), and only those items go on to pass
// 2's scratch threads. two_stage_signs is the same for a sign per item. fast_then_split:
// items whose exact evaluation splits into independent pieces decided without a scratch run
// a piece per thread, then a join per item.
// On the GPU pass 2 runs with a bounded number of threads, each owning a slice of a
// global-memory scratch (exact expansions are far too long for registers), grid-
// striding over the list; on the CPU each OpenMP thread uses a heap scratch.
// Returns the number of items that needed the exact pass (synchronizes), or adds it to a
// counter on the backend without waiting (the `tally` forms).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "parallel/primitives.hpp"

namespace gdel::par {

inline constexpr std::int8_t kUndecided = 2;
// Index lists over at most this many items are sized by the items, not counted first:
// the selection alone gives the count, one wait for the host instead of two, for at
// most 32 MiB of int64 list (fast_then_exact; gFlip3D's proposer list).
inline constexpr std::int64_t kUncountedListMax = std::int64_t(1) << 22;

// Runs f(k, work) for k in [0, n) with a private scratch of work_doubles doubles; with
// scratch_free (the caller knows that f never touches it: flip::Geo::int_all) with
// work = nullptr instead (no scratch allocated). With `count` (backend memory, set by an
// earlier call on the stream) only k < min(n, *count): n is then a bound. max_threads > 0
// caps the threads (and so the scratch) on the CUDA backend, where they stride over the
// items; the CPU backend's team is the cap there. block: the CUDA blocks' threads (a few
// hundred costly items spread over more SMs in smaller blocks); not used on the CPU.
// The scratch-free form calls f(k, nullptr), a std::nullptr_t, in a kernel of its own on
// the CUDA backend: a generic f (`auto work`) there instantiates the exact forms without a
// scratch (geom's predicates.hpp: no expansions compiled in; they decide in the integer
// stage or answer kUncertain), with fewer registers and no spills (bench/RESULTS.md,
// session 42); f(k, double*) still works, with a null pointer. detail::scratch_pass<Free>
// is the one launch of each form.
namespace detail {
template <bool Free, class F>
void scratch_pass(Context<Cpu>&, std::int64_t n, std::size_t work_doubles, F f, const std::int64_t* count,
                  std::int64_t /*max_threads*/, int /*block*/, std::int64_t count_scale = 1) {
  if (count && *count * count_scale < n) n = *count * count_scale;
  if (n <= 0) return;
#pragma omp parallel if (n >= 64)  // exact items are costly: a team pays off early
  {
    std::vector<double> work(Free ? 0 : work_doubles);
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t k = 0; k < n; ++k) {
      if constexpr (Free) f(k, nullptr);
      else f(k, work.data());
    }
  }
}
}  // namespace detail

#if defined(__CUDACC__)
namespace detail {
// Free: work is the constant nullptr (the scratch-free form), else the thread's slice.
// The scratch-free form spreads its items over the first `spread` warps (those the
// device holds at once: scratch_pass; 0: no spreading): with n items, lanes 0..L-1 of
// each of them work, L = ceil(n / spread), on item warp * L + lane. A warp whose threads
// take different paths (the SoS walks of exact ties) runs them one after the other, so
// a few items per warp over every resident warp finish sooner than full warps on a few
// SMs. From L = 32 on it is the plain mapping (item = thread, striding over the launch).
template <bool Free, class F>
__global__ void scratch_kernel(std::int64_t n, const std::int64_t* count, std::int64_t count_scale, double* scratch,
                               std::size_t work_doubles, std::int64_t spread, F f) {
  if (count && *count * count_scale < n) n = *count * count_scale;
  const std::int64_t tid = std::int64_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if constexpr (Free) {
    const std::int64_t lanes = spread > 0 && n < 32 * spread ? (n + spread - 1) / spread : 32;
    if (lanes < 32) {  // n <= spread * lanes: one item at most per thread
      const std::int64_t lane = tid & 31, k = (tid >> 5) * lanes + lane;
      if (lane < lanes && k < n) f(k, nullptr);
      return;
    }
  }
  const std::int64_t stride = std::int64_t(gridDim.x) * blockDim.x;
  for (std::int64_t k = tid; k < n; k += stride) {
    if constexpr (Free) f(k, nullptr);
    else f(k, scratch + tid * work_doubles);
  }
}
inline std::int64_t env_per_sm(const char* name, std::int64_t dflt) {
  const char* e = std::getenv(name);
  const long long v = e ? std::atoll(e) : 0;
  return v > 0 ? v : dflt;
}
}  // namespace detail

// Threads for exact passes: enough to keep the SMs busy with divergent, memory-
// heavy work, few enough that the scratch stays small (slices of work_doubles). Per SM:
// 128 with a scratch (0.95 GB on 132 SMs), GDEL_EXACT_PER_SM for measurements; without
// one (scratch_free) as many as are resident, 2 048, GDEL_FREE_PER_SM for measurements
// (bench/RESULTS.md, session 19: the sphere's exact passes and star builds −11 %
// against 128; 64 was 13 % slower).
inline std::int64_t exact_threads(const Context<Cuda>& c, std::int64_t n, bool scratch_free = false) {
  static const std::int64_t with = detail::env_per_sm("GDEL_EXACT_PER_SM", 128);
  static const std::int64_t without = detail::env_per_sm("GDEL_FREE_PER_SM", 2048);
  const std::int64_t cap = std::int64_t(c.sm_count()) * (scratch_free ? without : with);
  return n < cap ? n : cap;
}

namespace detail {
// Whether scratch-free passes spread their items (scratch_kernel); GDEL_SPREAD_ITEMS=0
// for measurements: no.
inline bool spread_items() {
  static const bool v = !knob_off("GDEL_SPREAD_ITEMS");
  return v;
}
// The warps of `kernel` the device holds at once in blocks of `block` threads (its
// occupancy; asked once per kernel: each call site launches its kernel, a lambda of its
// own, with one block size).
template <class K>
std::int64_t resident_warps(const Context<Cuda>& c, K kernel, int block) {
  static const std::int64_t resident = [&] {
    int per_sm = 0;
    if (cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_sm, kernel, block, 0) != cudaSuccess || per_sm < 1) {
      (void)cudaGetLastError();
      per_sm = 1;
    }
    return std::int64_t(c.sm_count()) * per_sm * (block / 32);
  }();
  return resident;
}
template <bool Free, class F>
void scratch_pass(Context<Cuda>& c, std::int64_t n, std::size_t work_doubles, F f, const std::int64_t* count,
                  std::int64_t max_threads, int block, std::int64_t count_scale = 1) {
  if (n <= 0) return;
  std::int64_t want = exact_threads(c, n, Free);
  if (max_threads > 0 && max_threads < want) want = max_threads;
  // spreading: up to one warp per item, over the resident warps (scratch_kernel)
  std::int64_t spread = 0;
  if (Free && spread_items()) {
    spread = resident_warps(c, scratch_kernel<Free, F>, block);
    if (n < spread) spread = n;
    if (32 * spread > want) want = 32 * spread;
  }
  std::int64_t threads = (want + block - 1) / block * block;
  Buffer<double, Cuda> scratch(c, Free ? 0 : static_cast<std::size_t>(threads) * work_doubles);
  scratch_kernel<Free><<<static_cast<unsigned>(threads / block), block, 0, c.stream()>>>(
      n, count, count_scale, scratch.data(), work_doubles, spread, f);
  GDEL_CUDA_CHECK_LAUNCH("for_each_with_scratch");
}
}  // namespace detail
#endif

template <class B, class F>
void for_each_with_scratch(Context<B>& ctx, std::int64_t n, std::size_t work_doubles, F f, bool scratch_free = false,
                           const std::int64_t* count = nullptr, std::int64_t max_threads = -1, int block = 64) {
  if (scratch_free) detail::scratch_pass<true>(ctx, n, work_doubles, f, count, max_threads, block);
  else detail::scratch_pass<false>(ctx, n, work_doubles, f, count, max_threads, block);
}

namespace detail {
// The undecided items' list: list[0, cnt[0]) (cnt has 2 counters), bound >= cnt[0] known
// to the host (0: no items). wait: the host reads the count (bound = cnt[0]).
template <class B>
struct UndecidedList {
  Buffer<std::int64_t, B> cnt, list;
  std::int64_t bound = 0;
};
template <class B>
UndecidedList<B> undecided_list(Context<B>& ctx, std::int64_t n, const std::int8_t* undecided, bool wait) {
  auto und = [=] GDEL_LAMBDA(std::int64_t i) { return undecided[i] != 0; };
  // Over many items the undecided ones (few) are counted first (a wait), so that the
  // list is as long as they are, not n (see kUncountedListMax).
  UndecidedList<B> u{Buffer<std::int64_t, B>(ctx, 2), Buffer<std::int64_t, B>(ctx), 0};
  u.bound = n > kUncountedListMax ? count_indices(ctx, static_cast<std::size_t>(n), und) : n;
  if (u.bound == 0) return u;
  u.list.resize(static_cast<std::size_t>(u.bound));
  select_indices_to(ctx, static_cast<std::size_t>(n), u.list.data(), u.cnt.data(), und);
  if (wait) u.bound = u.cnt.get(0);
  return u;
}
// One path for both forms: the undecided items' list, its length on the backend (cnt[0]),
// the passes bounded by what the host knows and cut by the backend's count. With a tally
// nothing waits for the host before the exact passes are enqueued (below 2^22 items);
// without one the count is read first, so that the scratch is sized by it.
template <bool Tiers, class B, class Exact>
std::int64_t exact_after_fast(Context<B>& ctx, std::int64_t n, const std::int8_t* undecided, Exact exact,
                              std::size_t work_doubles, bool tiered, std::int64_t* tally, std::int64_t max_threads) {
  // Without a tally the caller waits for the count anyway: wait here, so that the
  // scratch is sized by the items, not by n (0.95 GB at n = 10^6: session 19's s19a).
  UndecidedList<B> u = undecided_list(ctx, n, undecided, !tally);
  std::int64_t bound = u.bound;
  if (bound == 0) return 0;
  std::int64_t* cp = u.cnt.data();
  std::int64_t* lp = u.list.data();
  if constexpr (Tiers) {  // (exact's return type is not asked for: nvcc's device lambdas hide it from host code)
    if (tiered) {
      scratch_pass</*Free=*/true>(
          ctx, bound, 0, [=] GDEL_LAMBDA(std::int64_t k, auto work) {
            if (exact(lp[k], work)) lp[k] = -1;
          },
          cp, -1, 64);
      Buffer<std::int64_t, B> rest(ctx, static_cast<std::size_t>(bound));
      std::int64_t* rp = rest.data();
      select_indices_to(ctx, static_cast<std::size_t>(bound), rp, cp + 1,
                        [=] GDEL_LAMBDA(std::int64_t k) { return k < cp[0] && lp[k] >= 0; });
      scratch_pass<false>(
          ctx, bound, work_doubles, [=] GDEL_LAMBDA(std::int64_t k, double* work) { exact(lp[rp[k]], work); },
          cp + 1, max_threads, 64);
    }
  }
  if (!Tiers || !tiered)
    scratch_pass<false>(
        ctx, bound, work_doubles, [=] GDEL_LAMBDA(std::int64_t k, double* work) { exact(lp[k], work); }, cp,
        max_threads, 64);
  if (!tally) return bound;
  parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { *tally += cp[0]; });
  return 0;
}
template <bool Tiers, class B, class Fast, class Exact>
std::int64_t fast_then_exact_impl(Context<B>& ctx, std::int64_t n, std::int8_t* undecided, Fast fast, Exact exact,
                                  std::size_t work_doubles, bool tiered, std::int64_t* tally,
                                  std::int64_t max_threads) {
  if (n <= 0) return 0;
  parallel_for(ctx, n, [=] GDEL_LAMBDA(std::int64_t i) { undecided[i] = fast(i) ? 0 : 1; });
  return exact_after_fast<Tiers>(ctx, n, undecided, exact, work_doubles, tiered, tally, max_threads);
}
}  // namespace detail

// Items whose exact evaluation is `parts` independent pieces, each decided without a
// scratch (flip::Geo::int_all: gFlip3D's proposals on integer input, a piece per face),
// split into one item per piece: part(k, p, nullptr) -> std::int8_t for p < parts, then
// join(k, r) with r[0, parts) those answers, for k < min(n, *count) (count: backend
// memory, or nullptr for n). One thread per piece: a warp then runs the same kind of
// test in each lane (an exact tie's SoS walk beside another's), where a thread per item
// runs its pieces' tests one after the other, each warp mixing tests of every kind
// (bench/RESULTS.md, session 49). The pieces run in the scratch-free pass (spread over
// the resident warps); their answers in a buffer of parts bytes per item.
template <class B, class Part, class Join>
void split_scratch_free(Context<B>& ctx, std::int64_t n, const std::int64_t* count, int parts, Part part, Join join) {
  if (n <= 0) return;
  Buffer<std::int8_t, B> res(ctx, static_cast<std::size_t>(n * parts));
  std::int8_t* rp = res.data();
  detail::scratch_pass</*Free=*/true>(  // (pieces: parts * min(n, *count))
      ctx, n * parts, 0, [=] GDEL_LAMBDA(std::int64_t j, auto work) { rp[j] = part(j / parts, int(j % parts), work); },
      count, -1, 64, parts);
  parallel_for(ctx, n, [=] GDEL_LAMBDA(std::int64_t k) {
    if (!count || k < *count) join(k, rp + k * parts);
  });
}
// fast_then_exact with the exact evaluation split as split_scratch_free's: fast(i) on all
// n items, then part(i, p, nullptr) and join(i, r) for the undecided ones. The count of
// undecided items is returned (a wait), or with `tally` (backend memory) added to *tally
// without a wait for the host below kUncountedListMax items.
template <class B, class Fast, class Part, class Join>
std::int64_t fast_then_split(Context<B>& ctx, std::int64_t n, std::int8_t* undecided, Fast fast, int parts,
                             Part part, Join join, std::int64_t* tally = nullptr) {
  if (n <= 0) return 0;
  parallel_for(ctx, n, [=] GDEL_LAMBDA(std::int64_t i) { undecided[i] = fast(i) ? 0 : 1; });
  detail::UndecidedList<B> u = detail::undecided_list(ctx, n, undecided, !tally);
  if (u.bound == 0) return 0;
  const std::int64_t* lp = u.list.data();
  std::int64_t* cp = u.cnt.data();
  split_scratch_free(
      ctx, u.bound, cp, parts,
      [=] GDEL_LAMBDA(std::int64_t k, int p, auto work) -> std::int8_t { return part(lp[k], p, work); },
      [=] GDEL_LAMBDA(std::int64_t k, const std::int8_t* r) { join(lp[k], r); });
  if (!tally) return u.bound;
  parallel_for(ctx, 1, [=] GDEL_LAMBDA(std::int64_t) { *tally += cp[0]; });
  return 0;
}

// Runs fast(i) on all n items (full occupancy); the items for which it returns false
// (undecided) are compacted and run through exact(i, work) with a private scratch of
// work_doubles doubles. `undecided` is caller scratch of n bytes. Returns the number
// of items that needed an exact evaluation (synchronizes); with `tally` (one counter in
// backend memory) adds that number to *tally instead and returns 0, without waiting for
// the host when n <= kUncountedListMax (gFlip3D's flip iterations: bench/RESULTS.md,
// session 19). The host then does not know how many items need the scratch; max_threads
// > 0 caps the scratch threads (for_each_with_scratch), which the caller sizes from what
// it saw before: otherwise the scratch is sized by n.
template <class B, class Fast, class Exact>
std::int64_t fast_then_exact(Context<B>& ctx, std::int64_t n, std::int8_t* undecided, Fast fast, Exact exact,
                             std::size_t work_doubles, std::int64_t* tally = nullptr, std::int64_t max_threads = -1) {
  return detail::fast_then_exact_impl<false>(ctx, n, undecided, fast, exact, work_doubles, false, tally, max_threads);
}
// The same with exact(i, work) returning whether it decided item i; with `tiered` the
// undecided items are first tried with work = nullptr, and only
// those it leaves go to the scratch threads (see the top of this file).
template <class B, class Fast, class Exact>
std::int64_t fast_then_exact_tiered(Context<B>& ctx, std::int64_t n, std::int8_t* undecided, Fast fast, Exact exact,
                                    std::size_t work_doubles, bool tiered, std::int64_t* tally = nullptr,
                                    std::int64_t max_threads = -1) {
  return detail::fast_then_exact_impl<true>(ctx, n, undecided, fast, exact, work_doubles, tiered, tally,
                                            max_threads);
}

// Signs: out[i] = filter(i) (a sign, or kUndecided), then exact(i, work) for the
// undecided items.
template <class B, class Filter, class Exact>
std::int64_t two_stage_signs(Context<B>& ctx, std::int64_t n, std::int8_t* out, Filter filter, Exact exact,
                             std::size_t work_doubles) {
  if (n <= 0) return 0;
  Buffer<std::int8_t, B> und(ctx, static_cast<std::size_t>(n));
  return fast_then_exact(
      ctx, n, und.data(),
      [=] GDEL_LAMBDA(std::int64_t i) {
        out[i] = filter(i);
        return out[i] != kUndecided;
      },
      [=] GDEL_LAMBDA(std::int64_t i, double* work) { out[i] = exact(i, work); }, work_doubles);
}

}  // namespace gdel::par
