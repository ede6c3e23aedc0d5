// Reading untrusted input files whole, and the small parsing steps every text format here
// shares (meshes, quad cages, JSON lists): lower-case extension, strict number tokens.
#pragma once

#include <cstddef>
#include <string>

namespace holefill {

std::string lowerCase(std::string s);
// The lower-case extension after the last dot of the file name, "" when there is none.
std::string fileExtension(const std::string& path);
// The whole file; Error when it cannot be opened or read or exceeds maxBytes.
std::string readFileBytes(const std::string& path, std::size_t maxBytes = std::size_t(4) << 30);
// The whole token must be the number (no trailing characters); false otherwise.
bool parseDouble(const std::string& token, double& value);
bool parseInt(const std::string& token, long long& value);

}  // namespace holefill
