#!/usr/bin/env bash
# The test suites again under the sanitizers: every suite built with AddressSanitizer and
# UndefinedBehaviorSanitizer (GCC) in build-asan/, and the threaded rendering tests
# (tst_fast_paths: every stage on 1, 2, 3 and 5 threads; tst_accuracy: the threaded
# reference and renders) built with ThreadSanitizer (Clang) in build-tsan/. Any report fails the run. Expects the packages of setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRASTERLAB_BUILD_TESTS=ON \
    -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake --build build-asan --parallel "$jobs"
(cd build-asan &&
    QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --output-on-failure --parallel "$jobs")

CC=clang CXX=clang++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DRASTERLAB_BUILD_TESTS=ON -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread"
cmake --build build-tsan --parallel "$jobs" --target tst_fast_paths tst_accuracy
# Only a report inside Qt's QWaitCondition is suppressed (tests/tsan.supp says why).
tsan="halt_on_error=1 suppressions=$PWD/tests/tsan.supp"
(cd build-tsan &&
    QT_QPA_PLATFORM=offscreen TSAN_OPTIONS="$tsan" ./tests/tst_fast_paths &&
    QT_QPA_PLATFORM=offscreen TSAN_OPTIONS="$tsan" ./tests/tst_accuracy)
echo "sanitizers: ASan+UBSan suites and the TSan threaded tests passed"
