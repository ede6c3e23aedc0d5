#!/usr/bin/env bash
# Configure (once) and build HoleFill in ./build (Release, incremental on re-runs). The compiler's
# lines go to build/build.log and show only when the build fails (demo.sh prints our lines only);
# HOLEFILL_BUILD_VERBOSE=1 shows them as they come.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HOLEFILL_BUILD_DIR:-$root/build}
mkdir -p "$build"
log="$build/build.log"
steps() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$build" -j "$(nproc)"
}
if [ "${HOLEFILL_BUILD_VERBOSE:-0}" = 1 ]; then
  steps
elif ! steps >"$log" 2>&1; then
  tail -n 60 "$log" >&2
  echo "[build] failed; the whole log is $log" >&2
  exit 1
fi
grep -h "^-- \(FreeCAD\|OCCT\)" "$log" 2>/dev/null | sed 's/^-- /[build] /' || true
echo "[build] built in $build"
