// Prints the learned-model backend and fails unless libtorch computes in this build.
#include <cstdio>
#include <string>

#include "learn/torch/learn_backend.h"

int main() {
  const std::string info = holefill::learn::backendInfo();
  std::printf("learn backend: %s\n", info.c_str());
  return info.rfind("libtorch ", 0) == 0 ? 0 : 1;
}
