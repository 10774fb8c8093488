#!/usr/bin/env bash
# pyflakes over the Python of the tests and scripts: an unused import or variable, a name that is
# not defined, is a test that may not check what it says. Without pyflakes: a skip (77), but in CI
# (CI=true, every tool installed by install-deps.sh) a failure.
set -uo pipefail
cd "$(dirname "$0")/.."
for py in python3 /usr/bin/python3; do
  if "$py" -c "import pyflakes" 2>/dev/null; then
    exec "$py" -m pyflakes tests/integration scripts
  fi
done
if [[ "${CI:-}" != "" && "${CI:-}" != "0" && "${CI:-}" != "false" ]]; then
  echo "lint-python: pyflakes is not installed (CI=true: scripts/install-deps.sh installs python3-pyflakes)"
  exit 1
fi
echo "SKIPPED: pyflakes is not installed (apt-get install python3-pyflakes)"
exit 77
