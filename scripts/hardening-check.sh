#!/usr/bin/env bash
# hardening-check.sh DEB|BINARY: says which of Debian's hardening features the trakbox binary has
# and fails when one is missing (build with -DTRAKBOX_HARDENING=ON; docs/install.md):
#   PIE (ELF type DYN), RELRO (a GNU_RELRO segment), bind now (BIND_NOW / NOW), the stack protector
#   (__stack_chk_fail), fortified libc calls (__*_chk), libstdc++'s assertions (GCC 12's
#   __replacement_assert message, or GCC 13's std::__glibcxx_assert_fail).
set -euo pipefail
arg=${1:?usage: hardening-check.sh DEB|BINARY}
bin=$arg
if [[ "$arg" == *.deb ]]; then
  tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
  dpkg-deb -x "$arg" "$tmp"
  bin=$tmp/usr/bin/trakbox
fi
failed=0
have() {  # NAME, then a command that succeeds when the feature is there
  local name=$1; shift
  if "$@" >/dev/null 2>&1; then echo "hardening: $name: yes"; else echo "hardening: $name: MISSING"; failed=1; fi
}
have "PIE" grep -q 'Type: *DYN' <(readelf -h "$bin")
have "RELRO" grep -q 'GNU_RELRO' <(readelf -lW "$bin")
have "bind now" grep -Eq 'BIND_NOW|FLAGS_1.*NOW' <(readelf -dW "$bin")
have "stack protector" grep -q '__stack_chk_fail' <(readelf -sW --dyn-syms "$bin")
have "fortify" grep -Eq '__[a-z_]+_chk(@|$| )' <(readelf -sW --dyn-syms "$bin")
have "_GLIBCXX_ASSERTIONS" grep -Eq "Assertion '%s' failed|__glibcxx_assert_fail" <(strings -a "$bin"; readelf -sW --dyn-syms "$bin")
[ "$failed" -eq 0 ] || { echo "hardening-check: $bin lacks the features marked MISSING"; exit 1; }
