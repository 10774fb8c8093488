#!/usr/bin/env bash
# Fetches David Vallado's SGP4 C++ (SGP4.cpp, SGP4.h) as python-sgp4 ships it, at a pinned commit,
# checks its SHA-256, and puts it in DIR (default: ../vallado-sgp4 beside the checkout). It is the
# baseline of bench/vallado/bench_vs_vallado.cpp and is not part of trakbox:
#   scripts/fetch-vallado.sh /tmp/vallado
#   cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAKBOX_VALLADO_DIR=/tmp/vallado
#   ninja -C build-release bench_vs_vallado && python3 scripts/bench_ratios.py build-release/bench/bench_vs_vallado
set -euo pipefail
dir=${1:-$(dirname "$0")/../../vallado-sgp4}
commit=20a13b4022fce80b40084ab0001fa5453d6e85e6
base=https://raw.githubusercontent.com/brandon-rhodes/python-sgp4/$commit/extension
mkdir -p "$dir"
for f in SGP4.cpp SGP4.h; do
  curl -fsSL -o "$dir/$f" "$base/$f"
done
(cd "$dir" && sha256sum -c - <<'SUMS'
2ee7ad0e8f201e8251894083fe21e33a7aace2f43c871bf04357eb44a891b06e  SGP4.cpp
2a5ec44e059a52b3173d78d9a28bda8142b4f6497c1eb16febc2cea4b5006b0c  SGP4.h
SUMS
)
echo "Vallado's SGP4 in $dir; configure with -DTRAKBOX_VALLADO_DIR=$(cd "$dir" && pwd)"
