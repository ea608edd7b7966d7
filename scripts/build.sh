#!/usr/bin/env bash
# Configures and builds RasterLab (Release) into build/: the programs (build/bin) and the
# test suites. Extra arguments go to CMake and override these defaults; every option is
# passed each time, so one script's choice never lingers in CMake's cache for another.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRASTERLAB_BUILD_TESTS=ON -DRASTERLAB_WERROR=OFF "$@"
cmake --build build --parallel "$(nproc)"
