#!/usr/bin/env bash
# The bash completion of packaging/trakbox.bash-completion (issue 13): commands, options, the forms
# of --rotator/--radio, and satellite names from the data directory's element file.
set -euo pipefail
src=${TRAKBOX_SOURCE_DIR:-.}
if [ ! -r /usr/share/bash-completion/bash_completion ]; then
  echo "bash_completion.sh: FAILED: bash-completion is not installed"; exit 1
fi
# shellcheck disable=SC1091
source /usr/share/bash-completion/bash_completion
# shellcheck disable=SC1091
source "$src/packaging/trakbox.bash-completion"
export TRAKBOX_DATA="$src/data"
complete_of() {  # complete_of WORD... : the candidates for the last word
  COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMP_LINE="${COMP_WORDS[*]}"; COMP_POINT=${#COMP_LINE}
  COMPREPLY=(); _trakbox trakbox "${COMP_WORDS[-1]}" "${COMP_WORDS[-2]}"
  printf '%s\n' "${COMPREPLY[@]}"
}
fail() { echo "bash_completion.sh: FAILED: $*"; exit 1; }
# has WORDS PATTERN... : the candidates contain a line matching PATTERN (grep -x). The candidates are
# captured first: piping into `grep -q` under pipefail fails at random when grep exits before the
# writer has finished (SIGPIPE), which is what a CI run hit.
has() { local out; out=$(complete_of "${@:1:$#-1}"); grep -qx -- "${!#}" <<<"$out"; }
[ "$(complete_of trakbox pa)" = passes ] || fail "commands: $(complete_of trakbox pa)"
has trakbox --ser --service || fail "--service"
has trakbox --rotator "" 'rotctld:' || fail "--rotator forms"
has trakbox --radio ri 'rigctld' || fail "--radio forms"
has trakbox --uplink-radio ri 'rigctld:' || fail "--uplink-radio forms"
has trakbox passes x.tle --sat IS 'ISS.*' || fail "satellite names: $(complete_of trakbox passes x.tle --sat IS)"
has trakbox schedule --du --dut1 || fail "schedule options"
has trakbox passes x.tle --no- --no-checksum || fail "--no-checksum"
has trakbox el elements || fail "the elements command"
has trakbox ne next || fail "the next command"
has trakbox next ISS --wa --watch || fail "next --watch"
has trakbox elements x.json --to omm-k omm-kvn || fail "--to formats: $(complete_of trakbox elements x.json --to omm-k)"
has trakbox at attach || fail "the attach command"
has trakbox status --j --json || fail "status --json"
has trakbox --on-event l 'los=' || fail "--on-event kinds: $(complete_of trakbox --on-event l)"
has trakbox cal calibrate || fail "the calibrate command"
has trakbox rad radio || fail "the radio command"
has trakbox radio im import || fail "radio import"
has trakbox radio import x --format o oscarwatch || fail "radio --format: $(complete_of trakbox radio import x --format o)"
has trakbox calibrate m moon || fail "calibrate's words: $(complete_of trakbox calibrate m)"
has trakbox calibrate sun --re --reading || fail "calibrate --reading"
echo "bash_completion.sh: passed"
