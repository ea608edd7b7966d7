#!/usr/bin/env bash
# The lecture test of issue 48: is each stage's view readable from the back of the room?
# The goblet lesson at 1280x720 (Xvfb, no window manager), presentation mode (F5), Ctrl+Home,
# then Page Down once per stage: 7 steps. Each step's screenshot, with the menu, stage and
# stepping bars cropped off the top (TOP pixels, so the stage bar's "1 Camera" labels never
# count) and the status bar off the bottom (BOTTOM pixels: a render time, not a stage's
# number), is shrunk to half size (a reader twice as far away) and read by
# `tesseract half.png - --psm 11`.
# The count of a step: the numbers tesseract reads, matching -?[0-9]+([.,][0-9]+)?, of at
# least two characters (a lone digit is as often a misread mark as a number). The full-size
# shot is read too, and its lines with a cut-off "…" (or "...") are counted: only a hint,
# since tesseract often reads a small "…" as "." or not at all; look at the shots
# (OUT/LANG/stepN.png) for text cut off.
# --text-larger N presses Ctrl++ N times after F5 (the teacher's text size; default none).
# usage: scripts/lecture-ocr.sh [--language en|pt_BR] [--bin PATH] [--out DIR] [--display :N]
#                               [--top PX] [--bottom PX] [--text-larger N]
set -euo pipefail
cd "$(dirname "$0")/.."
language=en bin=build/bin/rasterlab out=out/lecture-ocr display=:81 top=124 bottom=28 larger=0
while [ $# -gt 0 ]; do
    case "$1" in
        --language) language=$2; shift 2 ;;
        --bin) bin=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --display) display=$2; shift 2 ;;
        --top) top=$2; shift 2 ;;
        --bottom) bottom=$2; shift 2 ;;
        --text-larger) larger=$2; shift 2 ;;
        *) echo "lecture-ocr: unknown argument $1" >&2; exit 2 ;;
    esac
done
out="$out/$language"
mkdir -p "$out"
lesson=resources/lessons/goblet/goblet.rasterlab
export LANGUAGE=$language LC_ALL=C.UTF-8
# A settings folder of its own, with the language chosen (View > Language) and no saved
# layout of this machine's user.
XDG_CONFIG_HOME=$(mktemp -d)
export XDG_CONFIG_HOME
mkdir -p "$XDG_CONFIG_HOME/RasterLab"
printf '[General]\nlanguage=%s\n' "$language" >"$XDG_CONFIG_HOME/RasterLab/RasterLab.conf"
Xvfb "$display" -screen 0 1280x720x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null || true; rm -rf "$XDG_CONFIG_HOME"' EXIT
app=
sleep 1
export DISPLAY=$display
"$bin" "$lesson" >/dev/null 2>&1 &
app=$!
sleep 4
window=$(xdotool search --onlyvisible --class rasterlab | head -1)
xdotool windowfocus --sync "$window" 2>/dev/null || true
xdotool mousemove 640 100
xdotool key F5
sleep 2
for ((k = 0; k < larger; ++k)); do xdotool key ctrl+plus; sleep 0.3; done
xdotool key ctrl+Home
sleep 1
total=0 lowest=
for i in 0 1 2 3 4 5 6; do
    if [ "$i" -gt 0 ]; then xdotool key Next; sleep 1.5; fi
    import -window root "$out/step$i.png"
    convert "$out/step$i.png" -gravity North -chop "0x$top" -gravity South -chop "0x$bottom" \
        +repage "$out/body$i.png"
    convert "$out/body$i.png" -resize 50% "$out/half$i.png"
    tesseract "$out/half$i.png" - --psm 11 2>/dev/null >"$out/half$i.txt"
    tesseract "$out/step$i.png" - --psm 11 2>/dev/null >"$out/full$i.txt"
    n=$(grep -oE -- '-?[0-9]+([.,][0-9]+)?' "$out/half$i.txt" | awk 'length >= 2' | wc -l || true)
    cut=$(grep -cE '…|\.\.\.' "$out/full$i.txt" || true)
    echo "step $i: $n numbers; $cut line(s) with … at full size"
    total=$((total + n))
    if [ -z "$lowest" ] || [ "$n" -lt "$lowest" ]; then lowest=$n; fi
done
echo "$language: $total numbers in 7 steps, the fewest in a step $lowest"
