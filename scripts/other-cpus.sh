#!/usr/bin/env bash
# The fast paths' kernels are built three times (pipeline/core/multiversion.h) and the
# machine running the tests picks one; the suites test it at both of the kernels' widths. This
# runs the suites that hold the fast paths to the lecture's stages bit for bit (tst_kernels,
# tst_fast_paths) under qemu-user as two other processors: Haswell (AVX2, no AVX-512: the
# x86-64-v3 kernels) and Nehalem (the baseline kernels), after checking with the bench that
# each picks the kernels expected, and their width (eight pixels at a time with AVX2, four with
# the baseline).
# Usage: scripts/other-cpus.sh [BUILD_DIR] (default build). Expects setup.sh's packages and
# a build with the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
if [[ "$(uname -m)" != x86_64 ]]; then
    echo "other-cpus: not an x86-64 machine, nothing to check"
    exit 0
fi

# Runs a program as processor $1. qemu warns of the host's system features it does not
# emulate (pcid, x2apic, rtm ...): those lines are left out, any about the kernels' own
# instructions (AVX, FMA, BMI, F16C, MOVBE) are kept.
as_cpu() {
    local cpu="$1"
    shift
    qemu-x86_64 -cpu "$cpu" "$@" 2> >(grep -v -E \
        "TCG doesn't support requested feature: CPUID[^ ]*\.(pcid|x2apic|tsc-deadline|hle|invpcid|rtm) " >&2)
}

declare -A expected=([Haswell]="x86-64-v3 (AVX2)" [Nehalem]="x86-64")
declare -A lanes=([Haswell]=8 [Nehalem]=4)
for cpu in Haswell Nehalem; do
    status=0
    bench=$(as_cpu "$cpu" "$build/bin/rasterlab-cli" bench --scene sphere-1k --size 64x48 \
        --frames 1 --format json) || status=$?
    kernels=$(grep -o '"kernels": "[^"]*", "kernel_lanes": [0-9]*' <<<"$bench" || true)
    want="\"kernels\": \"${expected[$cpu]}\", \"kernel_lanes\": ${lanes[$cpu]}"
    if ((status != 0)) || [[ "$kernels" != "$want" ]]; then
        echo "other-cpus: the bench as $cpu (exit $status) printed ${kernels:-no kernels}," \
            "expected $want" >&2
        exit 1
    fi
    for suite in tst_kernels tst_fast_paths; do
        if ! QT_QPA_PLATFORM=offscreen as_cpu "$cpu" "$build/tests/$suite" -silent; then
            echo "other-cpus: $suite failed as $cpu" >&2
            exit 1
        fi
    done
    echo "other-cpus: $cpu (${expected[$cpu]} kernels): tst_kernels and tst_fast_paths pass"
done
