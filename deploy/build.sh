#!/usr/bin/env bash
# Configures and builds Kontakt (Release) into ./build; used by both quick-start commands.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release ${KONTAKT_CMAKE_ARGS:-} >/dev/null
cmake --build build -j"$(nproc)"
