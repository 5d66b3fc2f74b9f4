// Options shared by the public entry points.
#pragma once

namespace gdel {

// Where the work runs. Auto = CUDA when this build has it and a device is present,
// otherwise the CPU backend (the same algorithms, OpenMP threads).
enum class Backend { Auto, Cpu, Cuda };

const char* to_string(Backend b);

// True when this build has the CUDA backend and a CUDA device is visible.
bool cuda_device_available();

// Resolves Auto; throws BackendUnavailable when Cuda is asked for but absent.
Backend resolve_backend(Backend requested);

}  // namespace gdel
