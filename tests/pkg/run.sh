#!/bin/sh
# The package's life cycle in a clean Debian 12 chroot (make test-pkg;
# docs/packaging.md): a minimal system with systemd and udev made by
# mmdebstrap (cached), then, inside it:
#   install  `apt-get install ./arcaded_*.deb` pulls the dependencies from
#            the archive; the service is enabled (systemctl is-enabled and
#            the wants link), user and group arcaded exist, /var/lib/arcaded
#            is arcaded's with mode 0750, unit, udev rules, sysusers,
#            tmpfiles, /etc/arcaded and the man page are in place;
#   start    the daemon, as the service's user, runs headless from the
#            installed configuration for 120 ticks and stops, leaving its
#            bookkeeping in /var/lib/arcaded (a chroot has no systemd
#            running: starting and stopping through systemd is what the
#            image test's boots show);
#   remove   program, unit and rules are gone (the enablement link is
#            left dangling until purge, as debhelper does); the
#            configuration (conffiles) and the state stay (Debian policy);
#   purge    the configuration and the state go too; then with the
#            dependencies removed again (apt-get autoremove --purge) the
#            file tree equals the one before the install, except the user
#            and group arcaded, which stay (as Debian does with system
#            users: files elsewhere may still carry their IDs).
# usage: tests/pkg/run.sh ARCADED.deb
# Environment: ARCADED_IMAGE_CACHE (where the chroot and the downloaded
# packages are kept, shared with scripts/image.sh), ARCADED_IMAGE_SOURCES.
set -u
cd "$(dirname "$0")/../.."
deb=$(realpath "$1")
cache=${ARCADED_IMAGE_CACHE:-${XDG_CACHE_HOME:-${HOME:-/root}/.cache}/arcaded-image}
sources=${ARCADED_IMAGE_SOURCES:-}
if [ -z "$sources" ]; then
	for f in /etc/apt/sources.list.d/debian.sources /etc/apt/sources.list; do
		[ -s "$f" ] && { sources=$f; break; }
	done
fi
passed=0
failed=0
check() { # name detail condition...
	n=$1 d=$2
	shift 2
	if "$@"; then echo "PASS $n: $d"; passed=$((passed + 1)); else
		echo "FAIL $n: $d"; failed=$((failed + 1)); fi
}
die() { echo "pkg-test: FAIL: $*"; exit 1; }
[ "$(id -u)" = 0 ] || die "needs root (chroot)"
mkdir -p "$cache/debs"

# Keyed by what makes it: the suite, the packages and the sources.
inc=systemd,systemd-sysv,udev
key=$( (echo "bookworm minbase $inc"; cat "$sources") | sha256sum | cut -c1-16)
base=$cache/chroot-$key.tar
if [ ! -s "$base" ]; then
	echo "pkg-test: making the clean chroot (mmdebstrap)"
	find "$cache" -maxdepth 1 -name 'chroot-*.tar' -delete
	mmdebstrap --variant=minbase --mode=root --include="$inc" \
		--skip=download/empty --skip=essential/unlink \
		--setup-hook='mkdir -p "$1/var/cache/apt/archives"' \
		--setup-hook="cp -a '$cache/debs/.' \"\$1/var/cache/apt/archives/\"" \
		--customize-hook="cp -a \"\$1/var/cache/apt/archives/.\" '$cache/debs/'" \
		--customize-hook='rm -f "$1"/var/cache/apt/archives/*.deb' \
		bookworm "$base.tmp.tar" "$sources" < /dev/null > "$cache/chroot.log" 2>&1 ||
		{ tail -n 20 "$cache/chroot.log"; die "mmdebstrap"; }
	mv "$base.tmp.tar" "$base"
fi
T=$(mktemp -d "${TMPDIR:-/tmp}/arcaded-pkg.XXXXXX")
trap 'rm -rf "$T"' EXIT
R=$T/root
L=$T/out
mkdir "$R" "$L"
tar -xf "$base" -C "$R" || die "unpacking the chroot"
# The packages apt would download again (dependencies of arcaded).
cp -a "$cache/debs/." "$R/var/cache/apt/archives/"
# Each command in the chroot runs in a mount namespace of its own with /proc
# mounted (systemd-tmpfiles needs it), which goes away with the command.
inr() {
	unshare -m --propagation private sh -c 'mount -t proc proc "$0/proc" && exec chroot "$0" "$@"' "$R" "$@"
}
apt() { inr env DEBIAN_FRONTEND=noninteractive apt-get -q -y -o Dpkg::Use-Pty=0 "$@"; }
# The tree as type, mode, owner and path; what apt and dpkg keep about
# themselves, caches and logs left out.
tree() {
	(cd "$R" && find . -xdev \( -path ./var/cache -o -path ./var/lib/apt -o -path ./var/lib/dpkg \
		-o -path ./var/log -o -path ./tmp -o -path ./proc -o -path ./dev -o -path ./sys \
		-o -path ./etc/ld.so.cache \) -prune -o -printf '%y %m %U:%G %p\n' | sort)
}
apt update > /dev/null 2>&1 || die "apt-get update in the chroot"
tree > "$L/before"
inr getent passwd arcaded > /dev/null && die "the clean chroot already has a user arcaded"

cp "$deb" "$R/tmp/arcaded.deb"
apt install --no-install-recommends /tmp/arcaded.deb > "$L/install.log" 2>&1
check install "apt-get install ./$(basename "$deb"): $(grep -c '^Setting up' "$L/install.log") packages set up" \
	inr dpkg-query -W -f='${Status}' arcaded | grep -q 'install ok installed'
[ -s "$L/install.log" ] && grep -E '^(E:|dpkg: error)' "$L/install.log"
check enabled "systemctl is-enabled: $(inr systemctl is-enabled arcaded.service 2>&1)" \
	sh -c '[ "$(chroot "$1" systemctl is-enabled arcaded.service 2>&1)" = enabled ] &&
		[ "$(readlink "$1/etc/systemd/system/multi-user.target.wants/arcaded.service")" = /lib/systemd/system/arcaded.service ]' sh "$R"
check user "$(inr getent passwd arcaded)" sh -c 'chroot "$1" getent passwd arcaded | grep -q ":/var/lib/arcaded:" && chroot "$1" getent group arcaded > /dev/null' sh "$R"
sd=$(inr stat -c '%U:%G %a' /var/lib/arcaded 2>&1)
check state-dir "/var/lib/arcaded $sd" test "$sd" = "arcaded:arcaded 750"
missing=""
for f in usr/bin/arcaded usr/lib/arcaded/arcaded-gl.so lib/systemd/system/arcaded.service \
	lib/udev/rules.d/70-arcaded.rules usr/lib/sysusers.d/arcaded.conf usr/lib/tmpfiles.d/arcaded.conf \
	etc/arcaded/arcaded.ini etc/arcaded/bindings.ini usr/share/man/man1/arcaded.1.gz \
	usr/share/arcaded/profiles/dragonrise-0079-0006.ini; do
	[ -s "$R/$f" ] || missing="$missing $f"
done
check files "installed:${missing:+ missing$missing}${missing:- all in place}" test -z "$missing"
grep -q '^ExecStart=/usr/bin/arcaded$' "$R/lib/systemd/system/arcaded.service"
check unit-execstart "$(grep '^ExecStart' "$R/lib/systemd/system/arcaded.service")" \
	grep -q '^ExecStart=/usr/bin/arcaded$' "$R/lib/systemd/system/arcaded.service"

# Start and stop: the installed daemon as the service's user, with the
# installed configuration and state directory (what the unit passes).
out=$(inr env STATE_DIRECTORY=/var/lib/arcaded setpriv --reuid=arcaded --regid=arcaded --init-groups \
	/usr/bin/arcaded --display null --set input.evdev=none --set input.hid=none --ticks 120 2>&1)
rc=$?
check start-stop "exit $rc; $(echo "$out" | grep -c .) log lines; state: $(ls "$R/var/lib/arcaded" | tr '\n' ' ')" \
	sh -c '[ "$1" = 0 ] && [ "$2" = arcaded ]' sh "$rc" "$(inr stat -c %U /var/lib/arcaded/books 2>&1)"

apt remove arcaded > "$L/remove.log" 2>&1
gone=""
for f in usr/bin/arcaded usr/lib/arcaded lib/systemd/system/arcaded.service lib/udev/rules.d/70-arcaded.rules \
	usr/lib/sysusers.d/arcaded.conf usr/lib/tmpfiles.d/arcaded.conf; do
	[ -e "$R/$f" ] && gone="$gone $f"
done
# The wants link stays, dangling, until purge: debhelper keeps the
# administrator's enablement for a reinstall (systemd ignores the link).
check remove "program, unit, rules gone${gone:+; left:$gone}; service $(inr systemctl is-enabled arcaded.service 2>&1)" \
	sh -c '[ -z "$1" ] && [ ! -e "$2/etc/systemd/system/multi-user.target.wants/arcaded.service" ]' sh "$gone" "$R"
check remove-keeps "kept: $(ls "$R/etc/arcaded" | tr '\n' ' ')and /var/lib/arcaded: $(ls "$R/var/lib/arcaded" | tr '\n' ' ')" \
	sh -c '[ -s "$1/etc/arcaded/arcaded.ini" ] && [ -s "$1/var/lib/arcaded/books" ]' sh "$R"

apt purge arcaded > "$L/purge.log" 2>&1
check purge "/etc/arcaded and /var/lib/arcaded gone" sh -c '[ ! -e "$1/etc/arcaded" ] && [ ! -e "$1/var/lib/arcaded" ]' sh "$R"
apt autoremove --purge > "$L/autoremove.log" 2>&1
tree > "$L/after"
left=$(diff "$L/before" "$L/after" | grep '^[<>]' |
	grep -v -E ' \./etc/(passwd|group|shadow|gshadow)-?$')
check purge-leaves-nothing "tree after purge and autoremove = tree before, but for the user and group kept${left:+; differs: $(echo "$left" | head -n 10 | tr '\n' ';')}" test -z "$left"
check user-kept "$(inr getent passwd arcaded)" sh -c 'chroot "$1" getent passwd arcaded > /dev/null' sh "$R"
rm -f "$R".before "$R".after "$R".*.log
echo "pkg-test: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
