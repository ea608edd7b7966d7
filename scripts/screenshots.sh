#!/usr/bin/env bash
# The program's screenshots of itself (the window, every dock, presentation mode, a command
# file) in English and in Brazilian Portuguese, into DIR (default docs/images/tour).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/images/tour}"
./scripts/build.sh -DRASTERLAB_BUILD_TESTS=ON >/dev/null
samples="${RASTERLAB_SAMPLES:-../shared/samples}"
for language in en pt_BR; do
    QT_QPA_PLATFORM=offscreen ./build/tests/screenshot_tour --out "$out" --language "$language" \
        --samples "$samples"
done
