#include "learn/learn_backend.h"

#ifdef HOLEFILL_HAVE_TORCH
#include <torch/torch.h>
#include <torch/version.h>
#endif

namespace holefill::learn {

std::string backendInfo() {
#ifdef HOLEFILL_HAVE_TORCH
  try {
    const torch::Tensor a = torch::arange(4, torch::kFloat32);
    const float s = a.dot(a).item<float>();  // 0+1+4+9
    if (s != 14.0f) return "unavailable: libtorch returned a wrong result";
    return std::string("libtorch ") + TORCH_VERSION + " (" + std::to_string(torch::get_num_threads()) + " threads)";
  } catch (const std::exception& e) {
    return std::string("unavailable: ") + e.what();
  }
#else
  return "unavailable: built without libtorch";
#endif
}

}  // namespace holefill::learn
