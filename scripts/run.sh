#!/usr/bin/env bash
# Installs what is missing, builds, and starts trakbox on the simulated station with the shipped data.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh build
exec build/trakbox "$@"
