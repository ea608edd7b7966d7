#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz: the object, camera, lighting and command-file
# readers, each rendering what it accepts) with Clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-fuzz/, and runs each for SECONDS (default 600) on a
# corpus grown from tests/fuzz/corpus. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
# A crash, leak, timeout (10 s) or memory blow-up (2 GB) stops that target with its input in
# build-fuzz/artifacts/; the run's figures are in build-fuzz/logs/. Expects setup.sh's packages.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_course_object fuzz_camera fuzz_lighting fuzz_hw2)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DRASTERLAB_BUILD_TESTS=OFF -DRASTERLAB_BUILD_FUZZERS=ON \
    -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" >/dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]}"

declare -A seeds=([fuzz_course_object]=object [fuzz_camera]=camera [fuzz_lighting]=lighting [fuzz_hw2]=hw2)
mkdir -p build-fuzz/artifacts build-fuzz/logs
status=0
for target in "${targets[@]}"; do
    corpus="build-fuzz/corpus/${seeds[$target]}"
    mkdir -p "$corpus"
    cp -n tests/fuzz/corpus/"${seeds[$target]}"/* "$corpus"/
    log="build-fuzz/logs/$target.log"
    if ! UBSAN_OPTIONS=print_stacktrace=1 ./build-fuzz/fuzz/"$target" "$corpus" \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
        -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/"$target"- >"$log" 2>&1; then
        echo "$target: FAILED (see $log and build-fuzz/artifacts/)"
        status=1
    fi
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 || true)
    echo "$target: $runs executions in ${seconds} s, ${cov:-cov: ?}, corpus $(ls "$corpus" | wc -l) inputs"
done
exit $status
