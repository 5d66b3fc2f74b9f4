#include "gdel/version.hpp"

namespace gdel {
const char* version() { return "0.1.0"; }
bool built_with_cuda() {
#if defined(GDEL_HAVE_CUDA)
  return true;
#else
  return false;
#endif
}
}  // namespace gdel
