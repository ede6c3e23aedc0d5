// Optional parts of HoleFill that live in their own shared libraries and are loaded on first use
// (dlopen): the learned models (libholefill_learn.so, the only code linked to libtorch) and the
// STEP translator (libholefill_step.so, the only code linked to OCCT's five STEP libraries). A
// process that never uses them does not pay their load time, and a missing library is a clear
// error, not a failed start.
#pragma once

#include <string>

namespace holefill {

// Opens `fileName` (e.g. "libholefill_step.so") from, in order: the path in the environment
// variable `envVariable`, the folder of the binary or module holding this code, `buildPath`
// (the build tree's copy; may be null). Returns the dlopen handle and sets `path`; returns null
// and sets `tried` to where it looked and why when none opens.
void* openPluginLibrary(const std::string& fileName, const char* envVariable, const char* buildPath, std::string& path,
                        std::string& tried);

// The folder of the binary or shared module holding this code ("." when unknown).
std::string thisModuleDirectory();

bool fileExists(const std::string& path);
std::string directoryOf(const std::string& path);  // "." for a bare file name

}  // namespace holefill
