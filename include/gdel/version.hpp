#pragma once
namespace gdel {
// The library version, "major.minor.patch".
const char* version();
// True when this build contains the CUDA backend (a device may still be absent).
bool built_with_cuda();
}  // namespace gdel
