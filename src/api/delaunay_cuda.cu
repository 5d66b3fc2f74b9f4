// CUDA instantiation of gdel::delaunay, and gdel::delaunay_device (points and results in
// device memory).
#include <thrust/iterator/counting_iterator.h>
#include <thrust/system/cuda/execution_policy.h>
#include <thrust/transform_reduce.h>

#include <cfloat>
#include <climits>
#include <cmath>

#include "api/delaunay_impl.hpp"
#include "api/device_precheck.hpp"
#include "api/validate.hpp"
#include "core/backend_select.hpp"

namespace gdel::cuda_backend {
Triangulation delaunay(std::span<const double> points, const Options& options) {
  par::Context<par::Cuda> ctx(options.device);
  ctx.memory().set_limit(options.device_memory_limit);
  api::device_memory_precheck(ctx, static_cast<std::int64_t>(points.size() / 3), options.algorithm, false);
  return api::delaunay_on(ctx, points, options);
}
}  // namespace gdel::cuda_backend

namespace gdel {

void device_free(void* p, int device) noexcept {
  if (!p) return;
  int prev = -1;
  if (cudaGetDevice(&prev) != cudaSuccess) prev = -1;
  if (prev != device) cudaSetDevice(device);
  cudaFree(p);  // synchronizes the device: no kernel can still be using p
  if (prev >= 0 && prev != device) cudaSetDevice(prev);
  cudaGetLastError();  // an error here (e.g. the runtime shutting down) is not reported
}

namespace api::device_detail {

using I64 = std::int64_t;

// cudaMalloc'd result memory (outlives the context and its stream-ordered pool). When it
// fails and a context is given, the context's pool returns its unused memory and the
// allocation is tried once more.
template <class T>
DeviceArray<T> allocate(par::Context<par::Cuda>* ctx, int device, I64 n) {
  if (n <= 0) return DeviceArray<T>(nullptr, 0, device);
  void* p = nullptr;
  const std::size_t bytes = static_cast<std::size_t>(n) * sizeof(T);
  cudaError_t e = cudaMalloc(&p, bytes);
  if (e == cudaErrorMemoryAllocation && ctx) {
    cudaGetLastError();
    ctx->trim_pool();
    e = cudaMalloc(&p, bytes);
  }
  if (e == cudaErrorMemoryAllocation) {
    cudaGetLastError();
    std::size_t free_b = 0, total_b = 0;
    cudaMemGetInfo(&free_b, &total_b);
    throw OutOfDeviceMemory("out of device memory for the result: needed " + std::to_string(bytes) + " bytes, " +
                                std::to_string(free_b) + " free of " + std::to_string(total_b),
                            bytes, free_b);
  }
  GDEL_CUDA_CHECK(e);
  return DeviceArray<T>(static_cast<T*>(p), n, device);
}

// delaunay_into()'s sink for device-resident input and output: the coordinates are
// read where they are, and each result is written to (or copied device-to-device into)
// memory that the DeviceTriangulation owns.
struct DeviceOutput {
  DeviceTriangulation* res;
  int device;

  const double* input(par::Buffer<double, par::Cuda>&, std::span<const double> points) { return points.data(); }
  void representative(par::Context<par::Cuda>& ctx, const par::Buffer<I64, par::Cuda>& rep, I64 n, Triangulation&) {
    auto a = allocate<std::int32_t>(&ctx, device, n);
    std::int32_t* ap = a.data();
    const I64* rp = rep.data();
    par::parallel_for(ctx, n, [=] GDEL_LAMBDA(I64 i) { ap[i] = static_cast<std::int32_t>(rp[i]); });
    res->representative = std::move(a);
  }
  void failed_vertices(par::Context<par::Cuda>& ctx, const par::Buffer<I64, par::Cuda>& fl, std::size_t nfv,
                       const par::Buffer<I64, par::Cuda>& sid, Triangulation&) {
    auto a = allocate<std::int32_t>(&ctx, device, static_cast<I64>(nfv));
    std::int32_t* ap = a.data();
    const I64* flp = fl.data();
    const I64* sp = sid.data();
    par::parallel_for(ctx, static_cast<I64>(nfv),
                      [=] GDEL_LAMBDA(I64 k) { ap[k] = static_cast<std::int32_t>(sp[flp[k]]); });
    par::sort_keys(ctx, ap, nfv);  // ascending, as Triangulation::failed_vertices
    res->failed_vertices = std::move(a);
  }
  // One array at a time, each released once copied (the tets may sit in the larger
  // storage of the mesh's records: TetMesh::take_tets).
  void tets(par::Buffer<std::int32_t, par::Cuda>& tv, par::Buffer<std::int32_t, par::Cuda>& tn, Triangulation&) {
    auto& ctx = tv.context();
    auto b = allocate<std::int32_t>(&ctx, device, static_cast<I64>(tn.size()));
    if (tn.size())
      GDEL_CUDA_CHECK(cudaMemcpyAsync(b.data(), tn.data(), tn.bytes(), cudaMemcpyDeviceToDevice, ctx.stream()));
    tn.release();
    auto a = allocate<std::int32_t>(&ctx, device, static_cast<I64>(tv.size()));
    if (tv.size())
      GDEL_CUDA_CHECK(cudaMemcpyAsync(a.data(), tv.data(), tv.bytes(), cudaMemcpyDeviceToDevice, ctx.stream()));
    tv.release();
    res->tets = std::move(a);
    res->neighbors = std::move(b);
  }
};

// validate_points() on the device: the first non-finite coordinate (flat index), and the
// smallest non-zero and the largest magnitude, by one reduction.
struct Extent {
  long long first_bad;
  double lo, hi;
};
struct ExtentOf {
  const double* x;
  GDEL_HD Extent operator()(long long i) const {
    const double a = fabs(x[i]);
    if (!(a <= DBL_MAX)) return {i, HUGE_VAL, 0.0};  // Inf or NaN
    return {LLONG_MAX, a != 0 ? a : HUGE_VAL, a};
  }
};
struct MergeExtent {
  GDEL_HD Extent operator()(const Extent& a, const Extent& b) const {
    return {a.first_bad < b.first_bad ? a.first_bad : b.first_bad, a.lo < b.lo ? a.lo : b.lo,
            a.hi > b.hi ? a.hi : b.hi};
  }
};

}  // namespace api::device_detail

DeviceArray<double> copy_to_device(std::span<const double> host, int device) {
  GDEL_CUDA_CHECK(cudaSetDevice(device));
  auto a = api::device_detail::allocate<double>(nullptr, device, static_cast<std::int64_t>(host.size()));
  if (!host.empty()) GDEL_CUDA_CHECK(cudaMemcpy(a.data(), host.data(), host.size_bytes(), cudaMemcpyHostToDevice));
  return a;
}

std::vector<std::int32_t> copy_to_host(const DeviceArray<std::int32_t>& a) {
  std::vector<std::int32_t> h(static_cast<std::size_t>(a.size()));
  if (a.size() > 0) {
    GDEL_CUDA_CHECK(cudaSetDevice(a.device()));
    GDEL_CUDA_CHECK(cudaMemcpy(h.data(), a.data(), h.size() * sizeof(std::int32_t), cudaMemcpyDeviceToHost));
  }
  return h;
}

namespace cuda_backend {

DeviceTriangulation delaunay_device(const DevicePoints& points, const Options& options) {
  using namespace api::device_detail;
  auto t_start = std::chrono::steady_clock::now();
  par::Context<par::Cuda> ctx(points.device);  // sets the current device
  ctx.memory().set_limit(options.device_memory_limit);
  DeviceTriangulation res;
  const I64 n = points.n;
  api::device_memory_precheck(ctx, n, options.algorithm, false);
  const std::size_t count = static_cast<std::size_t>(3 * n);

  // Stream order: gdel's stream waits for what the producer queued on its stream.
  {
    cudaEvent_t ev;
    GDEL_CUDA_CHECK(cudaEventCreateWithFlags(&ev, cudaEventDisableTiming));
    cudaError_t e1 = cudaEventRecord(ev, static_cast<cudaStream_t>(points.stream));
    cudaError_t e2 = e1 == cudaSuccess ? cudaStreamWaitEvent(ctx.stream(), ev, 0) : e1;
    cudaEventDestroy(ev);
    GDEL_CUDA_CHECK(e2);
  }

  // float32 -> float64 on the device (exact).
  par::Buffer<double, par::Cuda> conv(ctx);
  const double* xp = static_cast<const double*>(points.data);
  if (points.float32) {
    conv.resize_discard(count);
    double* cp = conv.data();
    const float* fp = static_cast<const float*>(points.data);
    par::parallel_for(ctx, static_cast<I64>(count), [=] GDEL_LAMBDA(I64 i) { cp[i] = static_cast<double>(fp[i]); });
    xp = cp;
  }

  // Validation: the same checks and messages as validate_points() on the host. The
  // reduction runs here; the decision on the scaling exponent is validate_points() itself,
  // applied to the two extreme magnitudes (it depends on nothing else).
  const Extent ext = thrust::transform_reduce(thrust::cuda::par.on(ctx.stream()), thrust::counting_iterator<long long>(0),
                                              thrust::counting_iterator<long long>(static_cast<long long>(count)),
                                              ExtentOf{xp}, Extent{LLONG_MAX, HUGE_VAL, 0.0}, MergeExtent{});
  if (ext.first_bad != LLONG_MAX) {
    double v = 0;
    GDEL_CUDA_CHECK(cudaMemcpyAsync(&v, xp + ext.first_bad, sizeof(double), cudaMemcpyDeviceToHost, ctx.stream()));
    ctx.synchronize();
    throw InvalidInput("points: row " + std::to_string(ext.first_bad / 3) + " has a non-finite coordinate (" +
                       std::to_string(v) + ")");  // validate_points()'s message
  }
  const double extremes[3] = {ext.hi == 0 ? 0.0 : ext.lo, ext.hi, 0.0};
  const int k = api::validate_points(std::span<const double>(extremes, 3));
  if (k != 0) {  // exact scaling by 2^k into the predicates' range (validate.hpp)
    double* cp;
    if (points.float32) {
      cp = conv.data();
    } else {
      conv.resize_discard(count);
      cp = conv.data();
    }
    const double* src = xp;
    par::parallel_for(ctx, static_cast<I64>(count), [=] GDEL_LAMBDA(I64 i) { cp[i] = ldexp(src[i], k); });
    xp = cp;
  }
  res.points_read = xp;
  res.converted_input = xp != points.data;
  const double validate_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  DeviceOutput sink{&res, points.device};
  Triangulation t = api::delaunay_into(ctx, std::span<const double>(xp, count), options, sink);
  ctx.synchronize();  // the results are complete before anyone reads them
  res.stats = std::move(t.stats);
  res.stats.stages.insert(res.stats.stages.begin(),
                          std::pair<std::string, double>(
                              points.float32 ? "validate (device; float32 converted)" : "validate (device)", validate_s));
  res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return res;
}

}  // namespace cuda_backend
}  // namespace gdel
