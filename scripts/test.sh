#!/usr/bin/env bash
# Sets everything up, builds with warnings as errors, runs every test suite, holds the fast
# paths to the lecture on two other processors (scripts/other-cpus.sh), checks the
# installation and the Debian package (scripts/check-package.sh), then runs the suites again
# under the sanitizers (scripts/sanitizers.sh). Installing missing packages needs root or sudo.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh -DRASTERLAB_WERROR=ON -DRASTERLAB_BUILD_TESTS=ON
(cd build && QT_QPA_PLATFORM=offscreen ctest --output-on-failure --parallel "$(nproc)")
./scripts/other-cpus.sh
./scripts/check-package.sh
./scripts/sanitizers.sh
