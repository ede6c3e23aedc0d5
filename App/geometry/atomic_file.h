// Writing an output file atomically: the bytes go to a temporary file next to the target,
// which is renamed into place only when complete, so a failure (full disk, crash, bad
// folder) never leaves a half-written or truncated output behind (DESIGN: files are untrusted,
// outputs are written atomically). Inside a supervised child (geometry/supervised_child.h)
// the temporary and the finished output are reported to the parent, which removes them if
// the child crashes before the command ends.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace holefill {

// Throws holefill::Error naming the path when the folder is missing or not writable.
void writeFileAtomically(const std::string& path, const std::string& bytes);

// For writers that need a file name of their own (OCCT's): the temporary to fill, next to path,
// named after this process and ending in path's own extension (OCCT picks formats by it).
std::string temporaryFileFor(const std::string& path);
// Renames the filled temporary onto path; on failure removes it and returns false.
bool commitTemporaryFile(const std::string& tmp, const std::string& path);

// The files one command writes (a model, its face, a sidecar), all or none: each is written,
// by any writer, to a staged name next to its target (with its extension), and commit()
// renames them into place once all are written. A set left
// uncommitted (the command failed half-way: a bad folder for the second file) removes what it
// staged, and the targets keep what they held.
class OutputSet {
public:
  OutputSet() = default;
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  ~OutputSet();
  // Stages path and has `writer` write the staged name; an error it throws names path instead.
  void write(const std::string& path, const std::function<void(const std::string&)>& writer);
  // Throws holefill::Error naming the target whose rename failed (the rest are removed).
  void commit();

private:
  std::string stage(const std::string& path);
  std::vector<std::pair<std::string, std::string>> staged_;  // (staged name, target)
};

}  // namespace holefill
