#!/usr/bin/env bash
# install-deps.sh [run|all]: installs the Debian packages trakbox needs, only those missing.
#   run  what building and running the trakbox program needs (scripts/run.sh)
#   all  that, and what the tests, their independent references and the package checks need
#        (scripts/test.sh, CI); the default
set -euo pipefail
what=${1:-all}
run_pkgs=(
  cmake ninja-build g++ pkg-config
  libncurses-dev libboost-dev libspdlog-dev libfmt-dev nlohmann-json3-dev
  libcurl4-openssl-dev libhamlib-dev libpugixml-dev libcairo2-dev libgps-dev libsqlite3-dev
)
test_pkgs=(
  python3 doctest-dev libbenchmark-dev
  # test peers and independent references
  libhamlib-utils python3-sgp4 python3-skyfield gpredict socat tmux python3-pyftpdlib python3-pyflakes
  # the GPS receiver: gpsd and gpsfake (gpsd-clients) to test against (libgps-dev is a run package)
  gpsd gpsd-clients
  # the web page's browser tests (tests/integration/web_browser.py)
  chromium chromium-driver python3-selenium
  # a real iCalendar reader for passes --ics and /api/v1/passes.ics (tests/integration/passes_calendar.py)
  python3-icalendar
  # TLS in front: the reverse proxy of packaging/nginx-trakbox.conf (tests/integration/web_tls.py)
  nginx openssl
  # the Debian package and its checks (scripts/package-check.sh), the completion test
  dpkg-dev lintian man-db groff-base systemd bash-completion
  # what a one-shot command asks the kernel for (one_shot_ports.py: no bind)
  strace
)
case "$what" in
  run) pkgs=("${run_pkgs[@]}") ;;
  all) pkgs=("${run_pkgs[@]}" "${test_pkgs[@]}") ;;
  *) echo "install-deps.sh: '$what': expected run or all" >&2; exit 2 ;;
esac
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
