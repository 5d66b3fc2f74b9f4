// Array plumbing between nanobind ndarrays (numpy, or any DLPack producer in host
// memory) and the spans the public C++ API takes, and back to numpy arrays that own
// the vectors the API returned (no copy: the vector moves into a capsule).
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gdel/delaunay.hpp"

namespace gdel_py {

namespace nb = nanobind;

// Any array in any memory: the checks below give the error messages.
using AnyArray = nb::ndarray<nb::ro>;

// DLPack device types whose memory the host can read directly.
inline bool host_accessible(int device_type) {
  return device_type == nb::device::cpu::value || device_type == nb::device::cuda_host::value;
}

inline std::string dtype_name(nb::dlpack::dtype dt) {
  using code = nb::dlpack::dtype_code;
  std::string base;
  switch (static_cast<code>(dt.code)) {
    case code::Int: base = "int"; break;
    case code::UInt: base = "uint"; break;
    case code::Float: base = "float"; break;
    case code::Bfloat: base = "bfloat"; break;
    case code::Complex: base = "complex"; break;
    case code::Bool: return "bool";
    default: base = "dlpack-code-" + std::to_string(dt.code) + "-"; break;
  }
  std::string s = base + std::to_string(dt.bits);
  if (dt.lanes != 1) s += "x" + std::to_string(dt.lanes);
  return s;
}

inline std::string shape_string(const AnyArray& a) {
  std::string s = "(";
  for (std::size_t i = 0; i < a.ndim(); ++i) {
    if (i) s += ", ";
    s += std::to_string(a.shape(i));
  }
  if (a.ndim() == 1) s += ",";
  return s + ")";
}

// Element (row, col) of a 1-D (col ignored) or 2-D host array as U, via strides.
template <class Src, class U>
void gather(const AnyArray& a, U* out) {
  const auto* base = static_cast<const Src*>(
      static_cast<const void*>(static_cast<const std::uint8_t*>(a.data_handle()) + a.byte_offset()));
  const std::int64_t rows = static_cast<std::int64_t>(a.shape(0));
  if (a.ndim() == 1) {
    const std::int64_t s0 = a.stride(0);
    for (std::int64_t i = 0; i < rows; ++i) out[i] = static_cast<U>(base[i * s0]);
    return;
  }
  const std::int64_t cols = static_cast<std::int64_t>(a.shape(1));
  const std::int64_t s0 = a.stride(0), s1 = a.stride(1);
  for (std::int64_t i = 0; i < rows; ++i)
    for (std::int64_t j = 0; j < cols; ++j) out[i * cols + j] = static_cast<U>(base[i * s0 + j * s1]);
}

// A host array read as contiguous values of T: a view of the caller's memory when it
// already is contiguous T, otherwise one converted copy.
template <class T>
struct Contiguous {
  std::span<const T> view;
  std::vector<T> owned;  // non-empty when a conversion happened
  bool converted = false;
};

// Whether `a` (1-D or 2-D) is C-contiguous.
inline bool c_contiguous(const AnyArray& a) {
  std::int64_t expect = 1;
  for (std::size_t k = a.ndim(); k-- > 0;) {
    if (a.shape(k) != 1 && a.stride(k) != expect) return false;
    expect *= static_cast<std::int64_t>(a.shape(k));
  }
  return true;
}

// Calls f(T{}) with the C++ type of a real numeric dtype (float32/64, 8..64-bit
// signed and unsigned integers); false for any other dtype.
template <class F>
bool visit_real_dtype(nb::dlpack::dtype dt, F&& f) {
  if (dt == nb::dtype<double>()) return f(double{}), true;
  if (dt == nb::dtype<float>()) return f(float{}), true;
  if (dt == nb::dtype<std::int64_t>()) return f(std::int64_t{}), true;
  if (dt == nb::dtype<std::int32_t>()) return f(std::int32_t{}), true;
  if (dt == nb::dtype<std::int16_t>()) return f(std::int16_t{}), true;
  if (dt == nb::dtype<std::int8_t>()) return f(std::int8_t{}), true;
  if (dt == nb::dtype<std::uint64_t>()) return f(std::uint64_t{}), true;
  if (dt == nb::dtype<std::uint32_t>()) return f(std::uint32_t{}), true;
  if (dt == nb::dtype<std::uint16_t>()) return f(std::uint16_t{}), true;
  if (dt == nb::dtype<std::uint8_t>()) return f(std::uint8_t{}), true;
  return false;
}

template <class T>
const T* typed_data(const AnyArray& a) {
  return static_cast<const T*>(
      static_cast<const void*>(static_cast<const std::uint8_t*>(a.data_handle()) + a.byte_offset()));
}

// Reads `a` as doubles. Accepts float32/float64 and integer dtypes; integers must be
// exactly representable (|x| < 2^53). `what` names the argument in messages. Runs
// without the GIL (throws std exceptions only).
inline Contiguous<double> as_doubles(const AnyArray& a, const char* what) {
  Contiguous<double> r;
  const auto dt = a.dtype();
  const std::size_t count = a.size();
  if (dt == nb::dtype<double>() && c_contiguous(a)) {
    r.view = {typed_data<double>(a), count};
    return r;
  }
  r.owned.resize(count);
  r.converted = true;
  bool exact = true;
  std::size_t bad = 0;
  const bool known = visit_real_dtype(dt, [&](auto tag) {
    using T = decltype(tag);
    gather<T>(a, r.owned.data());
    if constexpr (std::is_integral_v<T> && sizeof(T) == 8) {
      constexpr double limit = 9007199254740992.0;  // 2^53: larger integers may round
      for (std::size_t i = 0; i < count && exact; ++i)
        if (!(r.owned[i] < limit && r.owned[i] > -limit)) exact = false, bad = i;
    }
  });
  if (!known)
    throw std::invalid_argument(std::string(what) + ": expected float32 or float64 values (or integers), got dtype " +
                                dtype_name(dt));
  if (!exact)
    throw std::invalid_argument(std::string(what) + ": integer value at flat index " + std::to_string(bad) +
                                " is not exactly representable as float64 (|x| must be below 2^53)");
  r.view = r.owned;
  return r;
}

// Reads `a` as int32 vertex ids. Accepts any integer dtype; values outside int32
// cannot be vertex ids and are an error. Runs without the GIL.
inline Contiguous<std::int32_t> as_int32(const AnyArray& a, const char* what) {
  Contiguous<std::int32_t> r;
  const auto dt = a.dtype();
  const std::size_t count = a.size();
  if (dt == nb::dtype<std::int32_t>() && c_contiguous(a)) {
    r.view = {typed_data<std::int32_t>(a), count};
    return r;
  }
  r.owned.resize(count);
  r.converted = true;
  std::string error;
  const bool known = visit_real_dtype(dt, [&](auto tag) {
    using T = decltype(tag);
    if constexpr (std::is_floating_point_v<T>) {
      error = std::string(what) + ": expected an integer array (int32), got dtype " + dtype_name(dt);
    } else {
      std::vector<T> raw(count);
      gather<T>(a, raw.data());
      for (std::size_t i = 0; i < count; ++i) {
        if (!std::in_range<std::int32_t>(raw[i])) {
          error = std::string(what) + ": value " + std::to_string(raw[i]) + " at flat index " + std::to_string(i) +
                  " does not fit a vertex id (int32)";
          return;
        }
        r.owned[i] = static_cast<std::int32_t>(raw[i]);
      }
    }
  });
  if (!known) error = std::string(what) + ": expected an integer array (int32), got dtype " + dtype_name(dt);
  if (!error.empty()) throw std::invalid_argument(error);
  r.view = r.owned;
  return r;
}

// A numpy array that owns `v` (moved into a capsule: no copy). `shape` multiplies to v.size().
template <class T>
nb::object to_numpy(std::vector<T>&& v, std::initializer_list<std::size_t> shape) {
  auto holder = std::make_unique<std::vector<T>>(std::move(v));
  T* data = holder->data();
  nb::capsule owner(holder.get(), [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  holder.release();  // the capsule owns it now
  return nb::cast(nb::ndarray<nb::numpy, T>(data, shape, owner));
}

// An int32 array of `framework` ("torch" or "cupy") on CUDA device a.device() that takes
// over a's memory (no copy): a capsule owns the DeviceArray, whose destructor frees it
// with cudaFree when the framework drops its last reference. None for an empty array
// (the Python layer makes empty arrays itself: DLPack consumers differ on null data).
inline nb::object to_device_framework(gdel::DeviceArray<std::int32_t>&& a, std::size_t rows, std::size_t cols,
                                      const std::string& framework) {
  if (a.size() == 0) return nb::none();
  const int device = a.device();
  auto holder = std::make_unique<gdel::DeviceArray<std::int32_t>>(std::move(a));
  std::int32_t* data = holder->data();
  nb::capsule owner(holder.get(), [](void* p) noexcept { delete static_cast<gdel::DeviceArray<std::int32_t>*>(p); });
  holder.release();  // the capsule owns it now
  const bool two_d = cols != 0;
  const std::size_t shape2[2] = {rows, cols};
  const std::size_t shape1[1] = {rows};
  const std::size_t ndim = two_d ? 2 : 1;
  const std::size_t* shape = two_d ? shape2 : shape1;
  if (framework == "torch")
    return nb::cast(nb::ndarray<nb::pytorch, std::int32_t, nb::device::cuda>(
        data, ndim, shape, owner, nullptr, nb::dtype<std::int32_t>(), nb::device::cuda::value, device));
  if (framework == "cupy")
    return nb::cast(nb::ndarray<nb::cupy, std::int32_t, nb::device::cuda>(
        data, ndim, shape, owner, nullptr, nb::dtype<std::int32_t>(), nb::device::cuda::value, device));
  throw std::invalid_argument("device results: unsupported framework '" + framework + "' (torch or cupy)");
}

}  // namespace gdel_py
