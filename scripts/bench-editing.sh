#!/usr/bin/env bash
# Editing latency in the window (offscreen, default size, its docks): the time from a light's
# position changed in the Edit dock to the new image painted, over 50 changes, on the goblet
# lesson and on a generated torus of 100,000 triangles. Release build.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh -DRASTERLAB_BUILD_TESTS=ON >/dev/null
export QT_QPA_PLATFORM=offscreen
./build/tests/bench_editing --lesson goblet --changes 50
./build/tests/bench_editing --torus 100000 --changes 50
