#!/usr/bin/env bash
# The sanitized stage of CI (issue 10), after deploy/test-all.sh's build: clang with
# AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer coverage, building only the deck
# reader, the daemon's API side and their tests (-O0: half the compile time of -O1; the long
# fuzz run uses -O1, tests/fuzz/README.md). Runs the reader's and the daemon's unit tests
# sanitized (their job processes are the regular build's kontaktd) and each fuzz harness for
# KONTAKT_FUZZ_SECONDS (default 20).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${KONTAKT_SANITIZED_BUILD:-build-sanitized}
cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Sanitized -DCMAKE_UNITY_BUILD=ON \
  -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_C_FLAGS_SANITIZED="${KONTAKT_SANITIZED_FLAGS:--O0 -g1}" \
  -DCMAKE_CXX_FLAGS_SANITIZED="${KONTAKT_SANITIZED_FLAGS:--O0 -g1}" \
  -DKONTAKT_SANITIZE=address,undefined -DKONTAKT_FUZZ=ON -DKONTAKT_WARNINGS_AS_ERRORS=ON \
  -DKONTAKT_TEST_WORKER="$PWD/build/server/kontaktd" >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target test_inp test_server \
  fuzz_deck_text fuzz_deck_zip fuzz_submission fuzz_router
export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
"$BUILD/tests/unit/inp/test_inp" --gtest_brief=1
"$BUILD/tests/unit/server/test_server" --gtest_brief=1
/usr/bin/python3 tests/fuzz/run_fuzzers.py --build "$BUILD" --seconds "${KONTAKT_FUZZ_SECONDS:-20}"
