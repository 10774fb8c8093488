#!/bin/bash
# The device registries from the command line: `trakbox --radio list` and `trakbox --rotator list`
# print their tables (every form --radio / --rotator takes) and exit 0; a bad --radio names what is
# wrong and lists the registry's names, exit 2, before anything starts.
# Environment: TRAKBOX_BIN.
set -u
BIN=${TRAKBOX_BIN:?set TRAKBOX_BIN to the trakbox program}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fails=0
bad() { fails=$((fails + 1)); echo "FAIL: $*"; }

out=$("$BIN" --radio list) || bad "--radio list exits non-zero"
for form in 'ic9700:DEVICE[:BAUD][:maindown|:mainup]' 'ic9100:DEVICE' 'ic910h:DEVICE' 'ts2000:DEVICE[:BAUD]' \
            'ft847:DEVICE[:BAUD]' 'ft817:DEVICE[:BAUD]' 'ft818:DEVICE[:BAUD]' 'ic705:DEVICE' 'icom:DEVICE' \
            'yaesu:DEVICE' 'hamlib:MODEL:DEVICE[:BAUD][:split|:mainsub]' 'rigctld[:HOST[:PORT]]' \
            'gqrx[:HOST[:PORT]]' 'sdrpp[:HOST[:PORT]]'; do
  grep -qF -- "$form" <<<"$out" || bad "--radio list lacks $form"
done
grep -A1 '^ic9700:' <<<"$out" | grep -qE '^  Icom IC-9700 .* A2h +19200 +3081$' ||
  bad "--radio list: the IC-9700's address, speed and Hamlib number under its spec"
# 80 columns: a phone's terminal or a serial console shows both lists without wrapping.
wide=$(awk 'length > 80' <<<"$out")
[ -z "$wide" ] || bad "--radio list has lines over 80 columns: $wide"

out=$("$BIN" --rotator list) || bad "--rotator list exits non-zero"
for form in simulated 'hamlib:MODEL:DEVICE[:BAUD]' 'rotctld:HOST[:PORT]' 'satrak:HOST[:PORT]' \
            'easycomm3:DEVICE[:BAUD]' 'easycomm2:DEVICE[:BAUD]' 'pstrotator:HOST[:PORT]' 'GS-232B 603' 'Easycomm I 201, II 202, III 204'; do
  grep -qF -- "$form" <<<"$out" || bad "--rotator list lacks $form"
done
wide=$(awk 'length > 80' <<<"$out")
[ -z "$wide" ] || bad "--rotator list has lines over 80 columns: $wide"

err=$("$BIN" --state "$TMP/s" --radio ic9800:/dev/ttyUSB0 </dev/null 2>&1 >/dev/null)
code=$?
[ "$code" -eq 2 ] || bad "a bad --radio exits $code, expected 2"
grep -qF 'unknown radio "ic9800"; expected one of sim, cat, icom,' <<<"$err" || bad "a bad --radio says: $err"
err=$("$BIN" --state "$TMP/s" --radio hamlib:IC-9701:/dev/ttyUSB0 </dev/null 2>&1 >/dev/null)
grep -qF 'Icom IC-9700 (3081)' <<<"$err" || bad "a Hamlib name not found lists the near ones: $err"

[ "$fails" -eq 0 ] && echo "device_lists: passed" || exit 1
