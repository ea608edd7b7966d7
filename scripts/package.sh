#!/usr/bin/env bash
# Builds the Debian package build/rasterlab_<version>_amd64.deb with CPack (cmake/Packaging.cmake):
# installs the packages it needs (scripts/setup.sh), builds build/ when it has not been
# configured yet (Release, without the test suites), brings it up to date otherwise, and packs
# what `cmake --install` installs under /usr. Prints the package's path on its last line.
# Install it with: sudo apt install ./build/rasterlab_<version>_amd64.deb
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ ${1:-} != --no-setup ]]; then
    ./scripts/setup.sh
fi
if [[ ! -f build/CMakeCache.txt ]]; then
    ./scripts/build.sh -DRASTERLAB_BUILD_TESTS=OFF
else
    cmake --build build --parallel "$(nproc)"
fi
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' build/CMakeCache.txt)
arch=$(dpkg --print-architecture)
deb="build/rasterlab_${version}_${arch}.deb"
rm -f "$deb"
(cd build && cpack -G DEB >/dev/null)
if [[ ! -s $deb ]]; then
    echo "package: cpack did not write $deb" >&2
    exit 1
fi
echo "$deb"
