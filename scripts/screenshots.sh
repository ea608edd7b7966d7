#!/usr/bin/env bash
# The program's screenshots of itself (the window, every dock, presentation mode, a command
# file), all on the lessons it ships and docs/examples, in English and in Brazilian
# Portuguese, into DIR (default docs/images/tour); with the default DIR also the README's and
# docs/accuracy.md's pictures in docs/images. Fails when a shot shows a path of this machine.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs/images/tour}"
images=()
[ $# -eq 0 ] && images=(--images docs/images)
./scripts/build.sh -DRASTERLAB_BUILD_TESTS=ON >/dev/null
for language in en pt_BR; do
    QT_QPA_PLATFORM=offscreen ./build/tests/screenshot_tour --out "$out" --language "$language" \
        --docs docs "${images[@]}"
done
