#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 or 13 machine: install what is missing, build,
# then run everything through ctest: GoogleTest (core), CLI, headless FreeCAD and GUI tests.
#   ./scripts/test.sh --sanitize   the core's GoogleTest suite and the CLI tests under ASan+UBSan
#                                  instead (clang, ./build-fuzz; docs/fuzzing.md says how long)
set -euo pipefail
if [ "${1:-}" = "--sanitize" ]; then
  shift
  . "$(dirname "$0")/sanitized_build.sh" holefill_tests holefill holefill_step
  cd "$fuzz_build"
  # FreeCAD cannot load an instrumented module, and libtorch is left out of this build: the
  # core's tests and the CLI's are what runs, less those of the learned models' inference.
  export HOLEFILL_TEST_NO_LEARN=1
  ctest --output-on-failure --timeout 1800 -L 'core|cli' -E '^(Bidgcn|Uvtran)Inference\.' "$@"
  exit
fi
. "$(dirname "$0")/prepare.sh"
cd "$build"
ctest --output-on-failure --timeout 900 "$@"
