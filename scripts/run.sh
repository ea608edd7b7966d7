#!/usr/bin/env bash
# Sets everything up and runs RasterLab on its embedded default scene: the window when a
# display is available; otherwise a headless render of the same scene to a PNG, whose
# path is printed. Installing missing packages needs root or sudo.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh -DRASTERLAB_BUILD_TESTS=OFF
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
    exec ./build/bin/rasterlab "$@"
fi
echo "run: no display found (DISPLAY and WAYLAND_DISPLAY are unset): rendering headless"
mkdir -p out
exec ./build/bin/rasterlab-cli render --output out/default-scene.png "$@"
