#!/usr/bin/env bash
# Stepping speed in the window (offscreen): replay and repaint time per step, scanline by
# scanline, on the course's chalice (calice2, 2,120 triangles) at 800x600 and on a generated
# torus of 46,000 triangles (the size of the largest course models). Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DRASTERLAB_BUILD_TESTS=ON >/dev/null
samples="${RASTERLAB_SAMPLES:-../shared/samples}/course/ufpe"
export QT_QPA_PLATFORM=offscreen
for docks in all image; do
    if [[ -f "$samples/calice2.byu" ]]; then
        ./build/tests/bench_stepping --camera "$samples/calice2.cfg" \
            --lighting "$samples/iluminacao.txt" --object "$samples/calice2.byu" \
            --granularity scanline --steps 300 --docks "$docks"
    else
        echo "bench-stepping: no course samples in $samples: the chalice is left out" >&2
    fi
    ./build/tests/bench_stepping --torus 46000 --granularity scanline --steps 300 --docks "$docks"
done
