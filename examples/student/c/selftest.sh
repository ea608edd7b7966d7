#!/bin/sh
# selftest.sh - build, render calice2 with and without each mistake switch,
# and run RasterLab's check once on the correct program.
# Exits non-zero when the build fails or the correct mode does not pass the check.
#
#   RASTERLAB=/path/to/rasterlab-cli SPEC=/path/to/spec ./selftest.sh

cd "$(dirname "$0")" || exit 1
HERE=$(pwd)
RASTERLAB=${RASTERLAB:-../../../build/bin/rasterlab-cli}
SPEC=${SPEC:-../../../../shared}
S=$SPEC/samples/course/ufpe
OUT=$HERE/out

echo "== build"
cc -std=c11 -O2 -Wall -o stages main.c pipeline.c files.c stages.c -lm || exit 1

mkdir -p "$OUT"
scene="--camera $S/calice2.cfg --lighting $S/iluminacao.txt --object $S/calice2.byu --size 160x120"

echo "== render calice2 160x120"
./stages $scene --output "$OUT/calice2.ppm" 2>/dev/null || { echo "correct render failed"; exit 1; }
echo "correct                       -> out/calice2.ppm"

for sw in --light-in-world --round-screen --normals-crossed --span-unit-steps \
          --span-start-round --span-start-trunc --span-open-end --span-open-start \
          --truncate-terms "--epsilon 0.001" "--skip-small-triangles 1" \
          --n-not-normalised-for-u --double-free-crash; do
    name=$(echo "$sw" | sed 's/^--//; s/ /-/g')
    file="$OUT/calice2-$name.ppm"
    rm -f "$file"
    ./stages $scene $sw --output "$file" 2>/dev/null
    rc=$?
    if [ $rc -ne 0 ]; then
        what="crashed or failed (exit $rc)"
    elif cmp -s "$OUT/calice2.ppm" "$file"; then
        what="same image as the correct one"
    else
        what="image differs"
    fi
    printf '%-30s -> out/calice2-%s.ppm: %s\n' "$sw" "$name" "$what"
done

echo "== --double-free-crash where the object reaches the last column"
./stages --camera tests/calice2-right-edge.cfg --lighting $S/iluminacao.txt \
         --object $S/calice2.byu --size 160x120 --output "$OUT/right-edge.ppm" 2>/dev/null
echo "right-edge camera, correct:           exit $?"
sh -c "./stages --camera tests/calice2-right-edge.cfg --lighting $S/iluminacao.txt \
         --object $S/calice2.byu --size 160x120 --output $OUT/right-edge-crash.ppm \
         --double-free-crash 2>/dev/null" 2>/dev/null
echo "right-edge camera, --double-free-crash: exit $? (134 = abort, 139 = segfault)"
sh -c "./stages --stages --double-free-crash < tests/zbuffer-last-column.txt >/dev/null 2>&1" 2>/dev/null
echo "zbuffer stage, fragment on column 159:  exit $?"
sh -c "./stages --stages --double-free-crash < tests/zbuffer-inside.txt >/dev/null 2>&1" 2>/dev/null
echo "zbuffer stage, no fragment on it:       exit $?"

echo "== rasterlab-cli check (correct mode, default scenes)"
if [ ! -x "$RASTERLAB" ]; then
    echo "no rasterlab-cli at $RASTERLAB (set RASTERLAB)"
    exit 1
fi
"$RASTERLAB" check --program "./stages --stages" --folder "$HERE" > "$OUT/check.txt" 2>&1
rc=$?
tail -n 2 "$OUT/check.txt"
if [ $rc -ne 0 ]; then
    echo "FAIL: the correct mode does not pass (exit $rc), see out/check.txt"
    exit 1
fi
echo "OK"
exit 0
