#include "geometry/text_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>

#include "geometry/error.h"

namespace holefill {

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string fileExtension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lowerCase(path.substr(dot + 1));
}

std::string readFileBytes(const std::string& path, std::size_t maxBytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw Error("cannot open '" + path + "': check that it exists and is readable");
  const std::streamoff size = in.tellg();
  if (size < 0 || static_cast<std::size_t>(size) > maxBytes)
    throw Error("'" + path + "' is larger than " + std::to_string(maxBytes >> 20) + " MiB");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(bytes.data(), size);
  if (!in) throw Error("cannot read '" + path + "'");
  return bytes;
}

bool parseDouble(const std::string& tok, double& v) {
  if (tok.empty()) return false;
  char* end = nullptr;
  v = std::strtod(tok.c_str(), &end);
  return end == tok.c_str() + tok.size();
}

bool parseInt(const std::string& tok, long long& v) {
  if (tok.empty()) return false;
  char* end = nullptr;
  errno = 0;
  v = std::strtoll(tok.c_str(), &end, 10);
  // Out of range is no number either: strtoll would clamp "4888…8" to 2^63 − 1 (found by fuzzing).
  return end == tok.c_str() + tok.size() && errno != ERANGE;
}

}  // namespace holefill
