#!/bin/sh
# Sound heard as the cabinet plays it, on this machine:
#  1. coins dropped in attract mode (tests/sound/attract.scr), the daemon
#     writing what it plays with --audio wav:FILE at the default 48000 Hz:
#     the coin's sound, found by correlation with its own samples
#     (build/tests/sndfind, score at least 0.9), begins at the first frame
#     of exactly each coin's tick (tick * 800), the credit's chime 12 ticks
#     (G_CREDIT_DELAY) later, and the file holds 800 frames for every
#     tick (ticks 0..600: 601 * 800 frames).
#  2. the same through ALSA to a real sound card when this machine has
#     one (/proc/asound/cards): the daemon opens it and reports no error;
#     without a card this part is SKIPPED (not passed).
# Through a sound card under the installed unit is the vm step's (the kms
# boot: QEMU's Intel HDA card recorded with -audiodev wav, docs/vm.md).
# Exit 0 when everything that ran passed (a part that did not run prints a
# line starting "SKIP ", which tests/run_all.sh counts as skipped, never
# passed: docs/testing.md), 1 on a failure.
# Usage: tests/sound/run.sh path/to/arcaded
set -u
BIN=$(realpath "$1")
FIND=$(dirname "$BIN")/tests/sndfind
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pass=0 fail=0 skip=0
ok() { echo "PASS $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1"; fail=$((fail + 1)); }
common="--config-dir $tmp/etc --state-dir $tmp/state"

# ---- 1. coins in attract, into a WAV file --------------------------------
coins="200 310 450"
end=600
"$BIN" $common --script tests/sound/attract.scr --audio wav:"$tmp/a.wav" >"$tmp/out" 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 0 ] || [ ! -x "$FIND" ]; then
	bad "attract coins: exit status $rc or $FIND missing (make tests builds it): $(tail -n 1 "$tmp/err")"
else
	"$FIND" --min 0.9 "$tmp/a.wav" COIN >"$tmp/coin" 2>&1
	"$FIND" --min 0.9 "$tmp/a.wav" CREDIT >"$tmp/credit" 2>&1
	got=$(awk '$1 == "found" { printf "%s ", $2 }' "$tmp/coin")
	want=$(for t in $coins; do printf '%s ' $((t * 800)); done)
	scores=$(awk '$1 == "found" { printf "%s ", $3 }' "$tmp/coin")
	[ "$got" = "$want" ] && ok "attract: the coin heard at frames $got(scores $scores)" ||
		bad "attract: the coin found at frames '$got', dropped at '$want'"
	got=$(awk '$1 == "found" { printf "%s ", $2 }' "$tmp/credit")
	want=$(for t in $coins; do printf '%s ' $(((t + 12) * 800)); done)
	[ "$got" = "$want" ] && ok "attract: the credit's chime 12 ticks after each coin, at frames $got" ||
		bad "attract: the credit's chime found at frames '$got', due at '$want'"
	frames=$(sed -n 's/.*frames \([0-9]*\),.*/\1/p' "$tmp/coin")
	[ "$frames" = $(((end + 1) * 800)) ] && ok "attract: $frames frames for $((end + 1)) ticks (800 a tick)" ||
		bad "attract: $frames frames, not $(((end + 1) * 800))"
fi

# ---- 2. a real sound card through ALSA -----------------------------------
if [ -s /proc/asound/cards ] && ! grep -q "no soundcards" /proc/asound/cards; then
	"$BIN" $common --script tests/sound/attract.scr --audio alsa >"$tmp/out" 2>"$tmp/err"
	rc=$?
	if [ "$rc" -eq 0 ] && ! grep -q "no sound card" "$tmp/err"; then
		ok "alsa: played on $(head -n 1 /proc/asound/cards | sed 's/^ *//')"
	else
		bad "alsa: exit $rc: $(grep -m1 sound "$tmp/err")"
	fi
else
	echo "SKIP alsa: this machine has no sound card (/proc/asound/cards)"; skip=$((skip + 1))
fi

echo "sound: $pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ] && [ "$pass" -gt 0 ]
