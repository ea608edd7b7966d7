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
# One screen of a projector's 1600x1000: presentation mode (full screen) sizes its text and
# places its docks for the screen it is on.
screens=$(mktemp --suffix=.json)
trap 'rm -f "$screens"' EXIT
echo '{"screens": [{"name": "projector", "x": 0, "y": 0, "width": 1600, "height": 1000}]}' \
    >"$screens"
for language in en pt_BR; do
    QT_QPA_PLATFORM="offscreen:configfile=$screens" ./build/tests/screenshot_tour --out "$out" \
        --language "$language" --docs docs "${images[@]}"
done
