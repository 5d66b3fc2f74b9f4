// GPU tests of src/geometry: the same predicates evaluated in a kernel (grid-stride loop,
// each thread's exact work buffer a slice of kPredicateWork doubles of global scratch),
// compared on the host with GMP and with the host implementation; plus the contraction
// regression on the device (nvcc fuses a*b+c by default; our code must not be affected).
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cpu/predicates_oracle.hpp"
#include "geometry/predicates.hpp"

using namespace gdel::geom;
using gdel_test::Case;
using gdel_test::Generator;
using gdel_test::Oracle;

#define CUDA_OK(call)                                                                  \
  do {                                                                                 \
    const cudaError_t err_ = (call);                                                   \
    ASSERT_EQ(err_, cudaSuccess) << #call << ": " << cudaGetErrorString(err_);         \
  } while (0)

namespace {

constexpr int kMasks = 14;  // column masks 1..14 (1..3 columns)

struct Result {
  int o3, o3x, o3s;
  int in, inx, ins, inl;
  int pw, pwx, pws, pwl;
  int minor[kMasks];
  int minor_exact[kMasks];
  int o3small, inlsmall;  // the small-integer stage where its callers may use it, else kUncertain
};

template <class Work>  // double* (a scratch) or std::nullptr_t (none: the scratch-free instances)
GDEL_HD void evaluate(const Case& k, Result& r, Work work) {
  const double *a = k.p[0], *b = k.p[1], *c = k.p[2], *d = k.p[3], *e = k.p[4];
  const double* w = k.w;
  const std::int64_t* id = k.id;
  r.o3 = orient3d(a, b, c, d, work);
  r.o3x = orient3d_exact(a, b, c, d, work);
  r.o3s = orient3d_sos(a, b, c, d, id[0], id[1], id[2], id[3], work);
  r.in = insphere(a, b, c, d, e, work);
  r.inx = insphere_exact(a, b, c, d, e, work);
  r.ins = insphere_sos(a, b, c, d, e, id[0], id[1], id[2], id[3], id[4], work);
  r.inl = insphere_lift_sos(a, b, c, d, e, id[0], id[1], id[2], id[3], id[4], work);
  r.pw = power(a, b, c, d, e, w[0], w[1], w[2], w[3], w[4], work);
  r.pwx = power_exact(a, b, c, d, e, w[0], w[1], w[2], w[3], w[4], work);
  r.pws = power_sos(a, b, c, d, e, w[0], w[1], w[2], w[3], w[4], id[0], id[1], id[2], id[3], id[4], work);
  r.pwl = power_lift_sos(a, b, c, d, e, w[0], w[1], w[2], w[3], w[4], id[0], id[1], id[2], id[3],
                         id[4], work);
  const double* pts[5] = {a, b, c, d, e};
  bool quarters = true, integers = true;
  for (int i = 0; i < 5; ++i) {
    quarters = quarters && (i == 4 || integer_point(pts[i], 0.0, kQuarterScale));
    integers = integers && integer_point(pts[i]);
  }
  r.o3small = quarters ? orient3d_sos_small(a, b, c, d, id[0], id[1], id[2], id[3]) : kUncertain;
  r.inlsmall = integers ? insphere_lift_sos_small(a, b, c, d, e, id[0], id[1], id[2], id[3], id[4]) : kUncertain;
  double* mw = work;  // (the minors' API takes a double*: null without a scratch)
  for (int m = 0; m < kMasks; ++m) {
    r.minor[m] = lifted_minor(pts, w, static_cast<unsigned>(m + 1), mw);
    r.minor_exact[m] = lifted_minor_exact(pts, w, static_cast<unsigned>(m + 1), mw);
  }
}

__global__ void evaluate_kernel(const Case* cases, int n, Result* out, double* scratch) {
  const int tid = blockIdx.x * blockDim.x + threadIdx.x;
  double* work = scratch + static_cast<std::size_t>(tid) * kPredicateWork;
  for (int i = tid; i < n; i += gridDim.x * blockDim.x) evaluate(cases[i], out[i], work);
}

// The same without a scratch: work the constant nullptr, as in the scratch-free exact
// passes (par::for_each_with_scratch), where the expansions and per-minor walks drop out.
__global__ void evaluate_free_kernel(const Case* cases, int n, Result* out) {
  const int tid = blockIdx.x * blockDim.x + threadIdx.x;
  for (int i = tid; i < n; i += gridDim.x * blockDim.x) evaluate(cases[i], out[i], nullptr);
}

// Whether the first np points (and weights when weighted) are all of the integer stage at
// scale 1 or all at the quarter scale: then no evaluation needs a scratch.
bool of_stage(const Case& k, int np, bool weighted) {
  for (const double sc : {1.0, kQuarterScale}) {
    bool all = true;
    for (int i = 0; i < np; ++i) all = all && integer_point(k.p[i], weighted ? k.w[i] : 0.0, sc);
    if (all) return true;
  }
  return false;
}

// Contraction regression on the device: two_product of given pairs, and orient3d of a
// configuration whose exact determinant is 0 while its FMA-evaluated one is not.
__global__ void contraction_kernel(const double* ab, int n, double* xy, const double* pts,
                                   int* o3, double* fused, double* scratch) {
  const int tid = blockIdx.x * blockDim.x + threadIdx.x;
  for (int i = tid; i < n; i += gridDim.x * blockDim.x) {
    ex::two_product(ab[2 * i], ab[2 * i + 1], xy[2 * i], xy[2 * i + 1]);
  }
  if (tid == 0) {
    const double *a = pts, *b = pts + 3, *c = pts + 6, *d = pts + 9;
    o3[0] = orient3d(a, b, c, d, scratch);
    o3[1] = orient3d_exact(a, b, c, d, scratch);
    o3[2] = orient3d_filter(a, b, c, d);
    // What default nvcc code generation (--fmad=true) makes of vx*wy - vy*wx: one FMA.
    const double vx = b[0] - a[0], vy = b[1] - a[1], wx = c[0] - a[0], wy = c[1] - a[1];
    fused[0] = fma(vx, wy, -(vy * wx));
  }
}

// orient3d_centroid_sos per case (the same scratch slices as evaluate_kernel).
__global__ void centroid_kernel(const gdel_test::CentroidCase* cases, int n, int* out, double* scratch) {
  const int tid = blockIdx.x * blockDim.x + threadIdx.x;
  double* work = scratch + static_cast<std::size_t>(tid) * kPredicateWork;
  for (int i = tid; i < n; i += gridDim.x * blockDim.x) {
    const gdel_test::CentroidCase& c = cases[i];
    const double* p[4] = {c.p[0], c.p[1], c.p[2], c.p[3]};
    const double* q[4] = {c.q[0], c.q[1], c.q[2], c.q[3]};
    out[i] = orient3d_centroid_sos(p, c.kpos, q, c.id, work);
  }
}

bool have_device() {
  int n = 0;
  return cudaGetDeviceCount(&n) == cudaSuccess && n > 0;
}

template <class T>
struct DeviceBuffer {
  T* ptr = nullptr;
  ~DeviceBuffer() {
    if (ptr) cudaFree(ptr);
  }
};

}  // namespace

TEST(GpuPredicates, MatchGmpAndHost) {
  if (!have_device()) GTEST_SKIP() << "no CUDA device";
  // GDEL_GPU_PREDICATE_CASES overrides the number of cases of each kind (debugging).
  const char* env = std::getenv("GDEL_GPU_PREDICATE_CASES");
  // >= 10^6 random and >= 10^5 degenerate / near-degenerate cases (issue criterion)
  const int n_random = env ? std::atoi(env) : (1 << 20);
  const int n_degenerate = env ? std::atoi(env) : (1 << 17);
  const int n_narrow = env ? std::atoi(env) : (1 << 15);  // the integer stage's narrow form at its limit
  std::vector<Case> cases;
  cases.reserve(n_random + n_degenerate + n_narrow);
  Generator g(20240601);
  for (int i = 0; i < n_random; ++i) {
    const int sel = i % 16;
    cases.push_back(g.random(sel == 0 ? 0x1p198 : sel == 1 ? 0x1p-120 : 1.0));
  }
  for (int i = 0; i < n_degenerate; ++i) cases.push_back(g.degenerate(i));
  for (int i = 0; i < n_narrow; ++i) cases.push_back(g.int_narrow_limit());
  const int n = static_cast<int>(cases.size());

  const int blocks = 64, threads = 64;  // few threads: exact work is register-hungry
  DeviceBuffer<Case> d_cases;
  DeviceBuffer<Result> d_out;
  DeviceBuffer<double> d_scratch;
  CUDA_OK(cudaMalloc(&d_cases.ptr, sizeof(Case) * n));
  CUDA_OK(cudaMalloc(&d_out.ptr, sizeof(Result) * n));
  CUDA_OK(cudaMalloc(&d_scratch.ptr, sizeof(double) * kPredicateWork * blocks * threads));
  CUDA_OK(cudaMemcpy(d_cases.ptr, cases.data(), sizeof(Case) * n, cudaMemcpyHostToDevice));
  const auto t0 = std::chrono::steady_clock::now();
  evaluate_kernel<<<blocks, threads>>>(d_cases.ptr, n, d_out.ptr, d_scratch.ptr);
  CUDA_OK(cudaGetLastError());
  CUDA_OK(cudaDeviceSynchronize());
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<Result> out(n), free_out(n);
  CUDA_OK(cudaMemcpy(out.data(), d_out.ptr, sizeof(Result) * n, cudaMemcpyDeviceToHost));
  evaluate_free_kernel<<<blocks, threads>>>(d_cases.ptr, n, d_out.ptr);
  CUDA_OK(cudaGetLastError());
  CUDA_OK(cudaDeviceSynchronize());
  CUDA_OK(cudaMemcpy(free_out.data(), d_out.ptr, sizeof(Result) * n, cudaMemcpyDeviceToHost));

  long bad = 0, zero_sos = 0, brute = 0, free_decided = 0, small_ties = 0;
  // The GMP checks run on all host threads (one oracle and scratch per thread).
#pragma omp parallel reduction(+ : bad, zero_sos, brute, free_decided, small_ties)
  {
    Oracle o;
    std::vector<double> work(kPredicateWork);
    auto fail = [&](int i, const char* what) {
      ++bad;
#pragma omp critical
      if (bad <= 20) ADD_FAILURE() << what << " case " << i;
    };
#pragma omp for schedule(dynamic, 1024)
    for (int i = 0; i < n; ++i) {
      const Case& k = cases[i];
      const Result& r = out[i];
      Result h;
      evaluate(k, h, work.data());  // host implementation: identical signs expected
      if (std::memcmp(&h, &r, sizeof(Result)) != 0) fail(i, "device != host");
      // without a scratch: the same signs where the points are of the integer stage (every
      // orient3d-only result needs only the first four), elsewhere those or kUncertain
      {
        const Result& f = free_out[i];
        Result hf;
        evaluate(k, hf, nullptr);
        if (std::memcmp(&hf, &f, sizeof(Result)) != 0) fail(i, "device != host without a scratch");
        const bool s4 = of_stage(k, 4, false), s5 = of_stage(k, 5, false), s5w = of_stage(k, 5, true);
        auto same = [&](int a, int b, bool stage) { return stage ? a == b : (a == b || a == kUncertain); };
        bool ok = same(f.o3, r.o3, s4) && same(f.o3x, r.o3x, s4) && same(f.o3s, r.o3s, s4) &&
                  same(f.in, r.in, s5) && same(f.inx, r.inx, s5) && same(f.ins, r.ins, s5) &&
                  same(f.inl, r.inl, s5) && same(f.pw, r.pw, s5w) && same(f.pwx, r.pwx, s5w) &&
                  same(f.pws, r.pws, s5w) && same(f.pwl, r.pwl, s5w);
        for (int m = 0; m < kMasks; ++m)
          ok = ok && same(f.minor[m], r.minor[m], s5w) && same(f.minor_exact[m], r.minor_exact[m], s5w);
        if (!ok) fail(i, "without a scratch");
        free_decided += s5w && f.pwl != kUncertain && f.inl != kUncertain;
      }
      o.load(k, 4, false);
      const int x3 = o.orient3d();
      if (r.o3 != x3 || r.o3x != x3) fail(i, "orient3d");
      o.load(k, 5, false);
      const int xi = o.lifted();
      if (r.in != xi || r.inx != xi) fail(i, "insphere");
      if (xi == 0 && i % 8 == 0) {
        ++brute;
        if (r.inl != o.lift_sos(k.id)) fail(i, "insphere_lift_sos brute force");
        if (r.ins != o.em_sos(5, k.id)) fail(i, "insphere_sos brute force");
      }
      o.load(k, 5, true);
      const int xp = o.lifted();
      if (r.pw != xp || r.pwx != xp) fail(i, "power");
      for (int m = 0; m < kMasks; ++m) {
        const int xm = o.minor(static_cast<unsigned>(m + 1));
        if (r.minor[m] != xm || r.minor_exact[m] != xm) fail(i, "minor");
      }
      if (x3 == 0 && i % 8 == 0 && r.o3s != o.em_sos(4, k.id)) fail(i, "orient3d_sos brute force");
      if ((r.o3small != kUncertain && r.o3small != r.o3s) || (r.inlsmall != kUncertain && r.inlsmall != r.inl))
        fail(i, "small-integer stage");
      small_ties += (r.o3small != kUncertain && x3 == 0) + (r.inlsmall != kUncertain && xi == 0);
      zero_sos += r.o3s == 0 || r.ins == 0 || r.inl == 0 || r.pws == 0 || r.pwl == 0;
      if ((x3 && r.o3s != x3) || (xi && (r.ins != xi || r.inl != xi)) || (xp && (r.pws != xp || r.pwl != xp)))
        fail(i, "sos disagrees with a non-zero exact sign");
    }
  }
  std::printf("[gpu] %d cases (%d random, %d degenerate, %d at the integer stage's narrow limit) in %.2f s on "
              "the device; %ld brute-force SoS checks; %ld integer cases decided without a scratch; %ld ties "
              "decided by the small-integer stage\n", n, n_random, n_degenerate, n_narrow, sec, brute, free_decided,
              small_ties);
  EXPECT_GT(free_decided, n_degenerate / 10);
  EXPECT_GT(small_ties, n_degenerate / 20);  // (11 477 of 131 072 on the H200, session 47)
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(zero_sos, 0);
}

TEST(GpuPredicates, NoContractionOnDevice) {
  if (!have_device()) GTEST_SKIP() << "no CUDA device";
  Generator g(99);
  const int n = 1 << 16;
  std::vector<double> ab(2 * n);
  for (int i = 0; i < n; ++i) {
    ab[2 * i] = std::ldexp(g.uniform(0.5, 1.0), g.integer(-200, 200)) * ((i & 1) ? -1 : 1);
    ab[2 * i + 1] = std::ldexp(g.uniform(0.5, 1.0), g.integer(-200, 200));
  }
  const double pts[12] = {0.0, 0.0, 0.0, 0.1, 0.7, 0.0, 0.2, 1.4, 0.0, 0.0, 0.0, 1.0};
  DeviceBuffer<double> d_ab, d_xy, d_pts, d_fused, d_scratch;
  DeviceBuffer<int> d_o3;
  CUDA_OK(cudaMalloc(&d_ab.ptr, sizeof(double) * 2 * n));
  CUDA_OK(cudaMalloc(&d_xy.ptr, sizeof(double) * 2 * n));
  CUDA_OK(cudaMalloc(&d_pts.ptr, sizeof(pts)));
  CUDA_OK(cudaMalloc(&d_fused.ptr, sizeof(double)));
  CUDA_OK(cudaMalloc(&d_o3.ptr, 3 * sizeof(int)));
  CUDA_OK(cudaMalloc(&d_scratch.ptr, sizeof(double) * kPredicateWork));
  CUDA_OK(cudaMemcpy(d_ab.ptr, ab.data(), sizeof(double) * 2 * n, cudaMemcpyHostToDevice));
  CUDA_OK(cudaMemcpy(d_pts.ptr, pts, sizeof(pts), cudaMemcpyHostToDevice));
  contraction_kernel<<<64, 128>>>(d_ab.ptr, n, d_xy.ptr, d_pts.ptr, d_o3.ptr, d_fused.ptr, d_scratch.ptr);
  CUDA_OK(cudaGetLastError());
  CUDA_OK(cudaDeviceSynchronize());
  std::vector<double> xy(2 * n);
  int o3[3];
  double fused;
  CUDA_OK(cudaMemcpy(xy.data(), d_xy.ptr, sizeof(double) * 2 * n, cudaMemcpyDeviceToHost));
  CUDA_OK(cudaMemcpy(o3, d_o3.ptr, sizeof(o3), cudaMemcpyDeviceToHost));
  CUDA_OK(cudaMemcpy(&fused, d_fused.ptr, sizeof(double), cudaMemcpyDeviceToHost));
  for (int i = 0; i < n; ++i) {
    const double a = ab[2 * i], b = ab[2 * i + 1];
    ASSERT_EQ(xy[2 * i], a * b) << a << " " << b;
    ASSERT_EQ(xy[2 * i + 1], std::fma(a, b, -(a * b))) << a << " " << b;
  }
  EXPECT_NE(fused, 0.0);  // the fused expression is not exactly zero ...
  EXPECT_EQ(o3[0], 0);    // ... while orient3d is
  EXPECT_EQ(o3[1], 0);
  EXPECT_EQ(o3[2], kUncertain);
}

TEST(GpuPredicates, Orient3dWithAnExactCentroidMatchesGmp) {
  if (!have_device()) GTEST_SKIP() << "no CUDA device";
  // the CPU test's cases (gdel_test::centroid_cases), more of them
  const std::vector<gdel_test::CentroidCase> cases = gdel_test::centroid_cases(1 << 15, 56);
  const int n = static_cast<int>(cases.size());
  constexpr int kBlocks = 64, kThreads = 128;
  DeviceBuffer<gdel_test::CentroidCase> d_cases;
  DeviceBuffer<int> d_out;
  DeviceBuffer<double> d_scratch;
  CUDA_OK(cudaMalloc(&d_cases.ptr, sizeof(gdel_test::CentroidCase) * n));
  CUDA_OK(cudaMalloc(&d_out.ptr, sizeof(int) * n));
  CUDA_OK(cudaMalloc(&d_scratch.ptr, sizeof(double) * kPredicateWork * kBlocks * kThreads));
  CUDA_OK(cudaMemcpy(d_cases.ptr, cases.data(), sizeof(gdel_test::CentroidCase) * n, cudaMemcpyHostToDevice));
  centroid_kernel<<<kBlocks, kThreads>>>(d_cases.ptr, n, d_out.ptr, d_scratch.ptr);
  CUDA_OK(cudaGetLastError());
  CUDA_OK(cudaDeviceSynchronize());
  std::vector<int> out(cases.size());
  CUDA_OK(cudaMemcpy(out.data(), d_out.ptr, sizeof(int) * n, cudaMemcpyDeviceToHost));
  int ties = 0, wrong = 0;
  for (int i = 0; i < n; ++i) {
    ties += cases[i].tie;
    wrong += out[i] != cases[i].want;
    if (wrong == 1 && out[i] != cases[i].want) ADD_FAILURE() << "case " << i << ": " << out[i] << " against GMP's " << cases[i].want;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(ties, n / 4);
  std::printf("[gpu centroid orient3d] %d cases as GMP (%d wrong), %d exact ties\n", n, wrong, ties);
}
