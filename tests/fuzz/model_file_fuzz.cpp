// A model file through readShape, the path of every door that reads a file: the first byte picks
// BREP or STEP, the rest is the file. Outside a supervised child readShape reads in a throwaway
// child first, so a kernel that hangs or crashes on the bytes costs that child only.
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "brep/shape_io.h"
#include "fuzz_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  char path[] = "/tmp/holefill_fuzz_model_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) return 0;
  close(fd);
  const std::string file = std::string(path) + (data[0] % 2 ? ".step" : ".brep");
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  holefill::fuzz::guarded([&] { holefill::readShape(file, 10.0); });
  std::remove(file.c_str());
  std::remove(path);
  return 0;
}
