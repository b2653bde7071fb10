#!/bin/sh
# `make deb`: builds the Debian package from the work tree as it is, with
# debhelper (debian/), in a copy under build/deb so the tree's own build/
# is left alone. Prints the .deb's path last.
#
# Version: the upstream version (app/main.c's ARCADED_VERSION) plus
# +gitDATE.COUNT.gHASH of HEAD (commit date, commits since the root), and
# .dirty when the tree has changes; a changelog entry for it is put on top
# of debian/changelog in the copy. Output: build/deb/arcaded_VERSION_ARCH.deb
# and build/deb/lintian.txt (lintian's findings; errors fail the build).
set -eu
cd "$(dirname "$0")/.."
out=${DEB_OUT:-build/deb}

upstream=$(sed -n 's/^#define ARCADED_VERSION "\(.*\)"$/\1/p' app/main.c)
[ -n "$upstream" ] || { echo "deb: no ARCADED_VERSION in app/main.c" >&2; exit 1; }
if git rev-parse --git-dir >/dev/null 2>&1; then
	when=$(git log -1 --format=%cd --date=format:%Y%m%d)
	count=$(git rev-list --count HEAD)
	hash=$(git rev-parse --short=7 HEAD)
	version="$upstream+git$when.$count.g$hash"
	[ -z "$(git status --porcelain --untracked-files=no)" ] || version="$version.dirty"
	stamp=$(git log -1 --format=%cD)
else
	version=$upstream
	stamp=$(date -R)
fi

mkdir -p "$out"
# Only this build's package in $out (older versions would pile up).
rm -f "$out"/arcaded_* "$out"/arcaded-dbgsym_* "$out/arcaded.deb"
src=$out/arcaded-$version
rm -rf "$src"
mkdir -p "$src"
# Tracked files and new ones not ignored: the tree as the developer has it.
git ls-files -z --cached --others --exclude-standard |
	xargs -0 sh -c 'for f; do [ -e "$f" ] && printf "%s\0" "$f"; done' sh |
	tar --null -T - -cf - | tar -xf - -C "$src"

{
	printf 'arcaded (%s) unstable; urgency=medium\n\n' "$version"
	printf '  * Built from git %s by make deb.\n\n' "${hash:-(no git)}"
	printf ' -- %s  %s\n\n' \
		"$(sed -n 's/^Maintainer: //p' debian/control)" "$stamp"
	cat debian/changelog
} > "$src/debian/changelog"

echo "deb: building arcaded $version in $src"
(cd "$src" && dpkg-buildpackage -b -us -uc -j2) > "$out/build.log" 2>&1 ||
	{ tail -n 40 "$out/build.log"; echo "deb: dpkg-buildpackage failed (log: $out/build.log)" >&2; exit 1; }
arch=$(dpkg-architecture -qDEB_HOST_ARCH)
deb=$out/arcaded_${version}_$arch.deb
[ -s "$deb" ] || { echo "deb: $deb was not made" >&2; exit 1; }
rm -rf "$src"

# lintian: errors fail; warnings and the rest are listed.
lintian --info --display-info --tag-display-limit 0 "$deb" > "$out/lintian.txt" 2>&1 || true
cat "$out/lintian.txt"
if grep -q '^E: ' "$out/lintian.txt"; then
	echo "deb: lintian reports errors" >&2
	exit 1
fi
echo "deb: $(grep -c '^W: ' "$out/lintian.txt") lintian warnings, $(du -k "$deb" | cut -f1) KiB"
ln -sf "$(basename "$deb")" "$out/arcaded.deb"
echo "$deb"
