# Sourced by fuzz.sh and test.sh --sanitize: configure (once) and build the instrumented tree in
# ./build-fuzz with clang: ASan+UBSan on all of HoleFill's code, libFuzzer's coverage on the core,
# no libtorch (its networks are not fuzzed; Debian's libtorch is not instrumented either).
# Builds the targets named in $@. Sets $fuzz_build.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
HOLEFILL_EXTRA_PKGS="clang libclang-rt-14-dev ${HOLEFILL_EXTRA_PKGS:-}" "$root/scripts/setup.sh"
fuzz_build=${HOLEFILL_FUZZ_BUILD_DIR:-$root/build-fuzz}
if [ ! -f "$fuzz_build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DPYTHON_EXECUTABLE=/usr/bin/python3 -DHOLEFILL_WITH_TORCH=OFF -DHOLEFILL_SANITIZE=ON -DHOLEFILL_FUZZ=ON
fi
cmake --build "$fuzz_build" -j "$(nproc)" --target "$@"
# OCCT keeps caches and handles alive past exit on purpose: leak reports would bury real findings.
# UBSan prints its stack; both stop the run on the first report.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
