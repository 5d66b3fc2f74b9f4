// Exceptions thrown at the gdel API boundary. Every message names the problem in
// terms a user can act on (which row, how many bytes, which CUDA call).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gdel {

// Base class of every gdel error.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Malformed input: NaN/Inf, wrong shape, weights of the wrong length, unreadable file.
class InvalidInput : public Error {
 public:
  using Error::Error;
};

// Input without a 3-D triangulation: fewer than 4 distinct points, or all points
// coplanar / collinear.
class DegenerateInput : public Error {
 public:
  using Error::Error;
};

// Device (or host) memory could not be obtained.
class OutOfDeviceMemory : public Error {
 public:
  OutOfDeviceMemory(const std::string& what, std::size_t needed_bytes, std::size_t free_bytes)
      : Error(what), needed(needed_bytes), available(free_bytes) {}
  std::size_t needed = 0;     // bytes asked for
  std::size_t available = 0;  // bytes free on the device at that moment (0 if unknown)
};

// A CUDA runtime call or kernel launch failed.
class CudaError : public Error {
 public:
  using Error::Error;
};

// The backend asked for is not available in this build or on this machine.
class BackendUnavailable : public Error {
 public:
  using Error::Error;
};

}  // namespace gdel
