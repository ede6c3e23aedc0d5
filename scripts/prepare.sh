# Sourced by demo.sh, test.sh and bench.sh: from the repository root, install what is missing
# and build (incrementally). Sets $root and $build.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
./scripts/setup.sh
./scripts/build.sh
build=${HOLEFILL_BUILD_DIR:-$root/build}
