#!/usr/bin/env bash
# Configure (once) and build HoleFill in ./build (Release, incremental on re-runs).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HOLEFILL_BUILD_DIR:-$root/build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$(nproc)"
