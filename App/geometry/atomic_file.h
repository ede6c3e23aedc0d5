// Writing an output file atomically: the bytes go to a temporary file next to the target,
// which is renamed into place only when complete, so a failure (full disk, crash, bad
// folder) never leaves a half-written or truncated output behind (DESIGN: files are untrusted,
// outputs are written atomically).
#pragma once

#include <string>

namespace holefill {

// Throws holefill::Error naming the path when the folder is missing or not writable.
void writeFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace holefill
