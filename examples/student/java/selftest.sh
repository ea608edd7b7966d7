#!/bin/sh
# Self-test: build, render calice2 at 160x120 with no switch and with each switch,
# then run the teacher's check once without switches.
# Exits non-zero when the build fails, the plain render fails, or the check does not pass.
#
# Environment: RASTERLAB (default ../../../build/bin/rasterlab-cli), SPEC (default
# ../../../../shared, the folder holding samples/course), OUT (default ./selftest-out),
# CHECK_MEMORY (megabytes for check's --memory, default 2048).
set -u
cd "$(dirname "$0")"
RASTERLAB=${RASTERLAB:-../../../build/bin/rasterlab-cli}
SPEC=${SPEC:-../../../../shared}
OUT=${OUT:-selftest-out}
CHECK_MEMORY=${CHECK_MEMORY:-2048}
SCENE="$SPEC/samples/course/ufpe"

echo "== build"
rm -rf out
javac -d out *.java || { echo "FAIL: build"; exit 1; }
mkdir -p "$OUT"

status=0
render() {
    name=$1; shift
    if java -cp out Render --camera "$SCENE/calice2.cfg" --lighting "$SCENE/iluminacao.txt" \
            --object "$SCENE/calice2.byu" --size 160x120 --output "$OUT/calice2-$name.png" "$@" \
            2> "$OUT/calice2-$name.log"; then
        echo "   ok     $name -> $OUT/calice2-$name.png"
    else
        echo "   CRASH  $name (see $OUT/calice2-$name.log: $(grep -m1 Exception "$OUT/calice2-$name.log"))"
        [ "$name" = correct ] && status=1
    fi
}

echo "== render calice2 160x120"
render correct
for s in --no-int-cast --specular-without-nl-test --edges-y-ax-b --scan-index-bug --gram-schmidt-float \
         --light-in-place --n-not-normalised=never --n-not-normalised=after --vertex-normals-front-only \
         --floor-screen --ceil-screen; do
    render "${s#--}" "$s"
done

echo "== rasterlab-cli check (no switch, --memory $CHECK_MEMORY)"
if "$RASTERLAB" check --memory "$CHECK_MEMORY" --program "java -cp out Stages" --folder "$(pwd)" \
        > "$OUT/check.txt" 2>&1; then
    tail -n 2 "$OUT/check.txt"
else
    tail -n 2 "$OUT/check.txt"
    echo "FAIL: the correct mode does not pass every stage (see $OUT/check.txt)"
    status=1
fi
[ $status = 0 ] && echo "selftest passed"
exit $status
