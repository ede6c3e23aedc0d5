// Writing an output file atomically: the bytes go to a temporary file next to the target,
// which is renamed into place only when complete, so a failure (full disk, crash, bad
// folder) never leaves a half-written or truncated output behind (DESIGN: files are untrusted,
// outputs are written atomically). Inside a supervised child (geometry/supervised_child.h)
// the temporary and the finished output are reported to the parent, which removes them if
// the child crashes before the command ends.
#pragma once

#include <string>

namespace holefill {

// Throws holefill::Error naming the path when the folder is missing or not writable.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// For writers that need a file name of their own (OCCT's): the temporary to fill, next to path,
// named after this process and ending in path's own extension (OCCT picks formats by it).
std::string temporaryFileFor(const std::string& path);
// Renames the filled temporary onto path; on failure removes it and returns false.
bool commitTemporaryFile(const std::string& tmp, const std::string& path);

}  // namespace holefill
