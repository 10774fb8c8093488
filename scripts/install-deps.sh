#!/usr/bin/env bash
# Installs the Debian packages trakbox needs to build, run and test. Installs only what is missing.
set -euo pipefail
pkgs=(
  cmake ninja-build g++ pkg-config python3
  libncurses-dev libboost-dev libspdlog-dev libfmt-dev nlohmann-json3-dev doctest-dev
  libcurl4-openssl-dev libhamlib-dev libbenchmark-dev libpugixml-dev
  # test peers and independent references
  libhamlib-utils python3-sgp4 python3-skyfield gpredict socat tmux python3-pyftpdlib
  # the GPS receiver: libgps to build, gpsd and gpsfake (gpsd-clients) to test against
  libgps-dev gpsd gpsd-clients
  # the Debian package and its checks (scripts/package-check.sh), the completion test
  dpkg-dev lintian man-db groff-base systemd bash-completion
)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
