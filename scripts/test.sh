#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: install what is missing, build,
# then run everything through ctest: GoogleTest (core), CLI, headless FreeCAD and GUI tests.
set -euo pipefail
. "$(dirname "$0")/prepare.sh"
cd "$build"
ctest --output-on-failure --timeout 900 "$@"
