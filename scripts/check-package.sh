#!/usr/bin/env bash
# Checks what `cmake --install` and the Debian package deliver, from the build in build/
# (scripts/test.sh runs it after the test suites; under a minute):
#   - installs into a staging folder (DESTDIR) and looks for every file a desktop needs;
#   - runs the staged rasterlab-cli (--version, and render: a non-empty PNG) and the staged
#     window offscreen on a staged lesson, with the desktop entry's own Exec command;
#   - validates the desktop entry (desktop-file-validate), the AppStream metadata
#     (appstreamcli validate --no-net) and the MIME types (update-mime-database);
#   - builds the package (scripts/package.sh) and runs lintian on it, failing on any error.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stage=$work/stage
fail() { echo "check-package: $*" >&2; exit 1; }

cmake --build build --parallel "$(nproc)" >/dev/null
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' build/CMakeCache.txt)
DESTDIR=$stage cmake --install build --prefix /usr >/dev/null
usr=$stage/usr
echo "check-package: installed into a staging folder ($(find "$usr" -type f | wc -l) files)"

for file in bin/rasterlab bin/rasterlab-cli \
    share/rasterlab/translations/rasterlab_pt_BR.qm share/rasterlab/translations/rasterlab_en.qm \
    share/rasterlab/lessons/goblet/goblet.rasterlab \
    share/doc/rasterlab/guide.en.md share/doc/rasterlab/guide.pt_BR.md \
    share/doc/rasterlab/images/tour/window-en.png share/doc/rasterlab/examples/crossing.txt \
    share/doc/rasterlab/copyright share/doc/rasterlab/changelog.gz \
    share/man/man1/rasterlab.1.gz share/man/man1/rasterlab-cli.1.gz \
    share/applications/org.rasterlab.RasterLab.desktop \
    share/metainfo/org.rasterlab.RasterLab.metainfo.xml share/mime/packages/rasterlab.xml \
    share/icons/hicolor/scalable/apps/rasterlab.svg; do
    [[ -s $usr/$file ]] || fail "missing or empty: /usr/$file"
done
zcat "$usr/share/doc/rasterlab/changelog.gz" | head -n 1 | grep -qF "rasterlab ($version)" ||
    fail "the changelog's latest entry (data/debian/changelog.in) is not for version $version"
for size in 16 32 48 64 128 256; do
    png=$usr/share/icons/hicolor/${size}x${size}/apps/rasterlab.png
    [[ -s $png ]] || fail "missing icon: $png"
    file -b "$png" | grep -q "PNG image data, $size x $size" || fail "not a ${size}px PNG: $png"
done

# The staged programs, away from the build folder: they must find their files in the stage.
cd "$work"
mkdir -m 0700 "$work/runtime"
[[ $("$usr/bin/rasterlab-cli" --version) == "rasterlab-cli $version" ]] ||
    fail "rasterlab-cli --version does not say $version"
"$usr/bin/rasterlab-cli" render --output "$work/default.png"
[[ $(head -c 8 "$work/default.png" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
    fail "rasterlab-cli render did not write a PNG"
echo "check-package: staged rasterlab-cli $version rendered $(stat -c %s "$work/default.png") bytes"

desktop=$usr/share/applications/org.rasterlab.RasterLab.desktop
exec_line=$(sed -n 's/^Exec=//p' "$desktop")
lesson=$usr/share/rasterlab/lessons/goblet/goblet.rasterlab
command=${exec_line/\%f/$lesson}
read -r -a words <<<"$command"
[[ ${words[0]} == rasterlab ]] || fail "the desktop entry runs '${words[0]}', not rasterlab"
words[0]=$usr/bin/rasterlab
[[ $("${words[0]}" --version) == "RasterLab $version" ]] || fail "rasterlab --version does not say $version"
QT_QPA_PLATFORM=offscreen XDG_CONFIG_HOME=$work/config XDG_RUNTIME_DIR=$work/runtime "${words[@]}" --quit-after 1500 ||
    fail "the staged window did not open $lesson"
echo "check-package: staged window opened the goblet lesson offscreen ($exec_line)"

desktop-file-validate "$desktop"
appstreamcli validate --no-net "$usr/share/metainfo/org.rasterlab.RasterLab.metainfo.xml" >/dev/null ||
    { appstreamcli validate --no-net "$usr/share/metainfo/org.rasterlab.RasterLab.metainfo.xml"; fail "appstreamcli"; }
mkdir -p "$work/mime/packages"
cp "$usr/share/mime/packages/rasterlab.xml" "$work/mime/packages/"
update-mime-database "$work/mime" >/dev/null 2>&1 || fail "update-mime-database rejects rasterlab.xml"
grep -q 'application/x-rasterlab-lesson:\*\.rasterlab' "$work/mime/globs2" || fail "no *.rasterlab glob"
grep -q 'model/x-movie-byu:\*\.byu' "$work/mime/globs2" || fail "no *.byu glob"
echo "check-package: desktop entry, AppStream metadata and MIME types are valid"

cd "$root"
deb=$(./scripts/package.sh --no-setup | tail -n 1)
lintian --fail-on error --tag-display-limit 0 "$deb" || fail "lintian found errors in $deb"
echo "check-package: $deb passes lintian"
