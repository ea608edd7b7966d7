#!/usr/bin/env bash
# What the null probe costs: builds rasterlab-cli twice in Release, as usual (build-probes/,
# the hooks compiled in and switched off by the null probe) and with RASTERLAB_PROBE_HOOKS=OFF
# (build-noprobes/, no hooks at all), then runs `bench` with the two in turn, ROUNDS times per
# scene, and prints each one's median time per frame and the ratio. The machine is shared,
# so only the ratio means much, and only within one run.
# Usage: scripts/probe-cost.sh [ROUNDS]   (default 7; expects setup.sh's packages)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds="${1:-7}"

for variant in probes noprobes; do
    hooks=ON
    [ "$variant" = noprobes ] && hooks=OFF
    cmake -S . -B "build-$variant" -DCMAKE_BUILD_TYPE=Release -DRASTERLAB_BUILD_TESTS=OFF \
        -DRASTERLAB_PROBE_HOOKS="$hooks" >/dev/null
    cmake --build "build-$variant" --parallel "$(nproc)" --target rasterlab-cli >/dev/null
done

median_ms() {  # the median_ms field of bench's JSON
    sed -n 's/.*"median_ms": \([0-9.]*\).*/\1/p'
}

scenes=("full-screen --size 1920x1080 --shading phong --frames 21"
        "full-screen --size 1920x1080 --shading gouraud --frames 21"
        "sphere-100k --size 1920x1080 --shading phong --frames 11"
        "sphere-1m --size 800x800 --shading phong --frames 5")
printf '| scene | null probe, ms | no probes, ms | ratio |\n|---|---|---|---|\n'
for scene in "${scenes[@]}"; do
    with=() without=()
    for ((i = 0; i < rounds; ++i)); do
        # shellcheck disable=SC2086  # the scene's words are options
        with+=("$(build-probes/bin/rasterlab-cli bench --scene $scene --threads 1 --format json | median_ms)")
        # shellcheck disable=SC2086
        without+=("$(build-noprobes/bin/rasterlab-cli bench --scene $scene --threads 1 --format json | median_ms)")
    done
    a=$(printf '%s\n' "${with[@]}" | sort -g | sed -n "$((rounds / 2 + 1))p")
    b=$(printf '%s\n' "${without[@]}" | sort -g | sed -n "$((rounds / 2 + 1))p")
    printf '| %s | %s | %s | %s |\n' "$scene" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", a / b }')"
done
