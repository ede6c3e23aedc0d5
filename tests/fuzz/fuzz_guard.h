// What a fuzz harness may let through: exactly what the doors turn into a clear message (the CLI's
// one line, the Python door's HoleFillError). Everything else — a signal, an ASan or UBSan report,
// an exception of another kind, a run past libFuzzer's -timeout — stops the fuzzer as a bug.
#pragma once

#include <Standard_Failure.hxx>

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "geometry/error.h"

namespace holefill::fuzz {

template <class F>
void guarded(F&& f) {
  try {
    f();
  } catch (const Error&) {
  } catch (const Standard_Failure&) {
  } catch (const std::exception&) {
  }
}

inline std::string text(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A verb's harness takes two inputs in one file, split at the first line "---".
inline std::pair<std::string, std::string> split(const std::string& all) {
  const std::size_t k = all.find("\n---\n");
  if (k == std::string::npos) return {all, std::string()};
  return {all.substr(0, k + 1), all.substr(k + 5)};
}

}  // namespace holefill::fuzz
