#!/usr/bin/env bash
# Quick start 2 (and CI): install dependencies, build, and run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
KONTAKT_CMAKE_ARGS="-DKONTAKT_WARNINGS_AS_ERRORS=ON" bash deploy/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 1500
bash deploy/test-sanitized.sh
