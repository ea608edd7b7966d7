#!/usr/bin/env bash
# Installs the Debian 12 packages RasterLab needs to build, run and test, when they are
# missing. Installing needs root: run as root, or as a user who may use sudo.
set -euo pipefail

packages=(
    cmake g++ make                     # the toolchain
    qt6-base-dev                       # Qt 6 Core, Gui, Widgets, Concurrent, Test
    qt6-tools-dev qt6-tools-dev-tools  # Qt's CMake support for Linguist
    qt6-l10n-tools                     # lupdate and lrelease (translations)
    qt6-translations-l10n              # Qt's own dialogs and buttons in Portuguese
    qt6-qpa-plugins                    # platform plugins (xcb for a desktop)
    libglm-dev                         # GLM
    fonts-dejavu-core                  # a font for the window and the offscreen tests
    locales                            # locale data: a test runs the CLI in pt_BR
    clang libclang-rt-14-dev           # Clang and its ThreadSanitizer (scripts/sanitizers.sh)
    librsvg2-bin                       # rsvg-convert: the PNG icons, from the SVG
    dpkg-dev                           # the Debian package: dpkg-shlibdeps finds its dependencies
    lintian                            # and checks it (scripts/check-package.sh)
    desktop-file-utils                 # desktop-file-validate: the menu entry
    appstream                          # appstreamcli: the AppStream metadata
    shared-mime-info                   # update-mime-database: the file types
    file                               # the PNG icons' sizes, checked
    qemu-user                          # other processors' kernels (scripts/other-cpus.sh)
    python3                            # the student renderer of examples/student, and its tests
    gcc default-jdk-headless           # the C and Java students' programs check is tested on
    bubblewrap                         # bwrap: check runs a student's program in a sandbox
)

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done

if ((${#missing[@]} == 0)); then
    echo "setup: all ${#packages[@]} packages are installed"
    exit 0
fi

echo "setup: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
    as_root=()
elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
else
    echo "setup: these packages are missing and installing them needs root or sudo: ${missing[*]}" >&2
    exit 1
fi
"${as_root[@]}" apt-get update
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
