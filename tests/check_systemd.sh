#!/bin/sh
# Checks the systemd integration files in systemd/ without installing
# anything on this machine (`make check-systemd`; no arguments):
#   - the unit passes `systemd-analyze verify` with no message at all, once
#     @BINDIR@ points at a stand-in executable in a temporary directory;
#   - its `systemd-analyze security --offline` exposure is at most MAX_EXPOSURE;
#   - the boot waits neither for a framebuffer nor for READY=1, and libusb
#     can hear udev (AF_NETLINK, no private network namespace, no IP);
#   - the sysusers.d and tmpfiles.d entries apply to an empty temporary root
#     (users, then directories with their owners and modes);
#   - the udev rules are well-formed (udevadm of systemd 252 has no verify,
#     and `udevadm test` would change the live /dev, so a small lint here);
#   - unit, rules, sysusers and tmpfiles agree with each other (user, group,
#     state directory, devices).
# Prints PASS/FAIL/SKIP per check; exits 1 if any failed.
set -u

MAX_EXPOSURE=2.0

cd "$(dirname "$0")/.." || exit 2
UNIT=systemd/arcaded.service
RULES=systemd/70-arcaded.rules
SYSUSERS=systemd/arcaded.sysusers
TMPFILES=systemd/arcaded.tmpfiles

failed=0
pass() { echo "PASS: $*"; }
fail() { echo "FAIL: $*"; failed=1; }
skip() { echo "SKIP: $*"; }

tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT INT TERM

# Value of KEY= in the unit (last assignment wins, as in systemd).
unit_get() {
	sed -n "s/^$1=//p" "$UNIT" | tail -n 1
}

# --- unit: systemd-analyze verify -------------------------------------------
mkdir -p "$tmp/bin" "$tmp/unit"
printf '#!/bin/sh\nexit 0\n' > "$tmp/bin/arcaded"
chmod 0755 "$tmp/bin/arcaded"
if ! grep -q '^ExecStart=@BINDIR@/arcaded$' "$UNIT"; then
	fail "verify: $UNIT must have ExecStart=@BINDIR@/arcaded (make install replaces @BINDIR@)"
fi
sed "s|@BINDIR@|$tmp/bin|g" "$UNIT" > "$tmp/unit/arcaded.service"
if grep -q '@[A-Z]*@' "$tmp/unit/arcaded.service"; then
	fail "verify: placeholders other than @BINDIR@ left in $UNIT"
fi
out=$(systemd-analyze verify --man=no "$tmp/unit/arcaded.service" 2>&1)
rc=$?
if [ $rc -eq 0 ] && [ -z "$out" ]; then
	pass "systemd-analyze verify $UNIT"
else
	fail "systemd-analyze verify $UNIT (exit $rc):"
	printf '%s\n' "$out" | sed 's/^/    /'
fi

# --- unit: security exposure ------------------------------------------------
out=$(systemd-analyze security --offline=true --no-pager "$tmp/unit/arcaded.service" 2>&1)
line=$(printf '%s\n' "$out" | grep 'Overall exposure level')
score=$(printf '%s\n' "$line" | sed -n 's/.*: \([0-9][0-9.]*\) .*/\1/p')
if [ -z "$score" ]; then
	fail "systemd-analyze security: no score in its output:"
	printf '%s\n' "$out" | tail -n 5 | sed 's/^/    /'
else
	echo "security: $line"
	if awk -v s="$score" -v m="$MAX_EXPOSURE" 'BEGIN { exit !(s <= m) }'; then
		pass "security exposure $score <= $MAX_EXPOSURE"
	else
		fail "security exposure $score > $MAX_EXPOSURE; the items that cost:"
		printf '%s\n' "$out" | grep '✗' | sed 's/   */  /g; s/^/    /'
	fi
fi

# --- unit: what the daemon's design needs of it -----------------------------
# The boot never waits for a display (it may never come: nomodeset), and
# READY=1, sent after the first frame on one, does not hold multi-user
# (DefaultDependencies=no, the service's usual dependencies spelled out)
# nor time out the start.
ok=1
for dep in Wants After Requires BindsTo; do
	if unit_get "$dep" | grep -q 'dev-fb[0-9]*\.device'; then
		ok=0; echo "    $dep= names a framebuffer device unit: the boot would wait for it"
	fi
done
[ "$(unit_get DefaultDependencies)" = no ] || { ok=0; echo "    DefaultDependencies=no missing: multi-user.target would wait for READY=1"; }
[ "$(unit_get TimeoutStartSec)" = infinity ] || { ok=0; echo "    TimeoutStartSec=infinity missing: a cabinet without a display would be killed at start"; }
grep -q '^Requires=sysinit.target$' "$UNIT" && grep -q '^After=sysinit.target basic.target$' "$UNIT" &&
	grep -q '^Conflicts=shutdown.target$' "$UNIT" && grep -q '^Before=shutdown.target$' "$UNIT" ||
	{ ok=0; echo "    the usual service dependencies (sysinit, basic, shutdown) are not all spelled out"; }
if [ $ok -eq 1 ]; then
	pass "the boot does not wait for the display or for READY=1; the start does not time out"
else
	fail "display and start-up dependencies (above)"
fi
# libusb's hotplug needs udev's netlink messages: the host's network
# namespace and AF_NETLINK; IP is denied outright.
ok=1
[ "$(unit_get PrivateNetwork)" != yes ] || { ok=0; echo "    PrivateNetwork=yes: udev's netlink messages never reach libusb"; }
fams=$(unit_get RestrictAddressFamilies | tr ' ' '\n' | sort | tr '\n' ' ')
[ "$fams" = "AF_NETLINK AF_UNIX " ] || { ok=0; echo "    RestrictAddressFamilies=$fams (want AF_UNIX AF_NETLINK only)"; }
[ "$(unit_get IPAddressDeny)" = any ] || { ok=0; echo "    IPAddressDeny=any missing"; }
if [ $ok -eq 1 ]; then
	pass "network: AF_UNIX and AF_NETLINK (udev's messages for libusb) only, IP denied"
else
	fail "network settings (above)"
fi

# --- sysusers ---------------------------------------------------------------
root="$tmp/root"
mkdir -p "$root/etc"
out=$(systemd-sysusers --dry-run --root="$tmp/empty-root" - < "$SYSUSERS" 2>&1)
if [ $? -eq 0 ]; then
	pass "systemd-sysusers --dry-run $SYSUSERS"
else
	fail "systemd-sysusers --dry-run $SYSUSERS:"
	printf '%s\n' "$out" | sed 's/^/    /'
fi
if [ "$(id -u)" = 0 ]; then
	out=$(systemd-sysusers --root="$root" - < "$SYSUSERS" 2>&1)
	rc=$?
	pw=$(grep '^arcaded:' "$root/etc/passwd" 2>/dev/null)
	gr=$(grep '^arcaded:' "$root/etc/group" 2>/dev/null)
	uid=$(printf '%s' "$pw" | cut -d: -f3)
	gid=$(printf '%s' "$gr" | cut -d: -f3)
	if [ $rc -eq 0 ] && [ -n "$uid" ] && [ -n "$gid" ] &&
	   [ "$(printf '%s' "$pw" | cut -d: -f4)" = "$gid" ] &&
	   [ "$(printf '%s' "$pw" | cut -d: -f6)" = /var/lib/arcaded ] &&
	   [ "$(printf '%s' "$pw" | cut -d: -f7)" = /usr/sbin/nologin ]; then
		pass "sysusers creates user arcaded ($uid) in group arcaded ($gid), home /var/lib/arcaded, no login"
	else
		fail "sysusers in a temporary root: passwd '$pw', group '$gr'"
		printf '%s\n' "$out" | sed 's/^/    /'
	fi

	# --- tmpfiles (needs the users above, and root for chown) ---------------
	out=$(systemd-tmpfiles --create --root="$root" - < "$TMPFILES" 2>&1)
	rc=$?
	st=$(stat -c '%a %u %g' "$root/var/lib/arcaded" 2>/dev/null)
	et=$(stat -c '%a %u %g' "$root/etc/arcaded" 2>/dev/null)
	if [ $rc -eq 0 ] && [ "$st" = "750 $uid $gid" ] && [ "$et" = "755 0 0" ]; then
		pass "tmpfiles creates /var/lib/arcaded 0750 arcaded:arcaded and /etc/arcaded 0755 root:root"
	else
		fail "tmpfiles in a temporary root: /var/lib/arcaded '$st', /etc/arcaded '$et' (exit $rc)"
		printf '%s\n' "$out" | sed 's/^/    /'
	fi
else
	skip "sysusers/tmpfiles in a temporary root need root (chown); dry run only"
fi

# --- udev rules lint --------------------------------------------------------
out=$(awk '
	/^[ \t]*(#|$)/ { next }
	{
		n = split($0, tok, /,[ \t]*/)
		for (i = 1; i <= n; i++) {
			t = tok[i]
			if (t !~ /^[A-Z]+(\{[A-Za-z0-9_]+\})?(==|!=|=|\+=|:=)"[^"]*"$/) {
				printf "%d: malformed \"%s\"\n", NR, t; bad = 1; continue
			}
			key = t; sub(/[=!+:].*/, "", key)
			val = t; sub(/^[^"]*"/, "", val); sub(/"$/, "", val)
			op = t; sub(/^[A-Z{}A-Za-z0-9_]*/, "", op); sub(/".*/, "", op)
			if (key !~ /^(SUBSYSTEM|KERNEL|GROUP|MODE|OWNER|ATTRS|ATTR|ENV|TAG)$/) {
				printf "%d: unexpected key %s\n", NR, key; bad = 1
			}
			if ((key == "SUBSYSTEM" || key == "KERNEL") && op != "==" && op != "!=") {
				printf "%d: %s must be matched (==), not assigned\n", NR, key; bad = 1
			}
			if ((key == "GROUP" || key == "MODE") && op != "=" && op != ":=") {
				printf "%d: %s must be assigned (=)\n", NR, key; bad = 1
			}
			if (key == "MODE" && val !~ /^0[0-7][0-7][0-7]$/) {
				printf "%d: MODE \"%s\" is not an octal mode\n", NR, val; bad = 1
			}
		}
	}
	END { exit bad }' "$RULES" 2>&1)
if [ $? -eq 0 ]; then
	pass "udev rules $RULES well-formed"
else
	fail "udev rules $RULES:"
	printf '%s\n' "$out" | sed 's/^/    /'
fi

# --- consistency ------------------------------------------------------------
user=$(unit_get User)
group=$(unit_get Group)
ok=1
[ "$user" = arcaded ] && [ "$group" = arcaded ] || { ok=0; echo "    unit User=$user Group=$group"; }
grep -q "^u $user -:$group " "$SYSUSERS" || { ok=0; echo "    $SYSUSERS has no 'u $user -:$group'"; }
grep -q "^g $group " "$SYSUSERS" || { ok=0; echo "    $SYSUSERS has no 'g $group'"; }
if grep -o 'GROUP="[^"]*"' "$RULES" | grep -v "GROUP=\"$group\"" >/dev/null; then
	ok=0; echo "    $RULES gives a group other than $group"
fi
# The rules give group $group every node of its own; ALSA's shared ones
# (the timer dmix needs) stay group audio, the one extra group.
if [ "$(unit_get SupplementaryGroups)" != audio ]; then
	ok=0; echo "    SupplementaryGroups=$(unit_get SupplementaryGroups): only audio expected (ALSA's shared nodes)"
fi
state="$(unit_get StateDirectory) $(unit_get StateDirectoryMode)"
[ "$state" = "arcaded 0750" ] || { ok=0; echo "    unit StateDirectory/Mode: $state"; }
grep -q "^d /var/lib/arcaded 0750 $user $group -$" "$TMPFILES" ||
	{ ok=0; echo "    $TMPFILES: /var/lib/arcaded differs from StateDirectory=arcaded 0750 $user:$group"; }
conf="$(unit_get ConfigurationDirectory) $(unit_get ConfigurationDirectoryMode)"
[ "$conf" = "arcaded 0755" ] || { ok=0; echo "    unit ConfigurationDirectory/Mode: $conf"; }
grep -q '^d /etc/arcaded 0755 root root -$' "$TMPFILES" ||
	{ ok=0; echo "    $TMPFILES: /etc/arcaded differs from ConfigurationDirectory=arcaded 0755"; }
# Every device the unit allows has a rule giving it to the group, and back.
for pair in 'char-fb:KERNEL=="fb' 'char-drm:KERNEL=="card' 'char-input:KERNEL=="event' \
	    'char-hidraw:KERNEL=="hidraw' 'char-gpiochip:KERNEL=="gpiochip' \
	    'char-alsa:KERNEL=="pcmC' 'char-alsa:KERNEL=="controlC' '/dev/tty0:KERNEL=="tty0"'; do
	allow=${pair%%:*}
	match=${pair#*:}
	grep -q "^DeviceAllow=$allow " "$UNIT" || { ok=0; echo "    unit lacks DeviceAllow=$allow"; }
	grep -F "$match" "$RULES" | grep -q "GROUP=\"$group\"" ||
		{ ok=0; echo "    $RULES lacks a $match rule for group $group"; }
done
nallow=$(grep -c '^DeviceAllow=' "$UNIT")
[ "$nallow" -eq 7 ] || { ok=0; echo "    unit has $nallow DeviceAllow= lines, the rules cover 7"; }
if [ $ok -eq 1 ]; then
	pass "unit, udev rules, sysusers and tmpfiles agree (user, group, directories, devices)"
else
	fail "unit, udev rules, sysusers and tmpfiles disagree (above)"
fi

if [ $failed -ne 0 ]; then
	echo "check-systemd: FAILED"
	exit 1
fi
echo "check-systemd: all passed"
