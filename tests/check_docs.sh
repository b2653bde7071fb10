#!/bin/sh
# Checks that the operator's guide (docs/operator.md, or the files given)
# names only what exists:
# - every image and every relative link points at a file that exists, and
#   every link to a heading of the same file (#anchor) at a heading there;
# - every daemon option (--name) is one `arcaded --help` lists, leaving out
#   the options of other programs (lines of systemctl, journalctl, apt, dd,
#   make);
# - every configuration key written section.key is one `arcaded
#   --print-config` prints (file names such as game.md are not keys);
# - every GPIO spec option written name= in a code span is a word of
#   input/in_gpio.c's option parser;
# - every `make TARGET` is a target of the Makefile;
# - every page of the service menu map is a label engine/ui/menu_draw.c
#   draws;
# - every profile row of the encoder table (`VVVV:PPPP` then `FILE.ini`)
#   names a shipped profile whose match line has that VID:PID.
# BIN (default build/arcaded) is the daemon asked. Exit status 0 when all
# hold, 1 otherwise (each fault printed as FILE: reason).
set -u
cd "$(dirname "$0")/.."
BIN=${BIN:-build/arcaded}
[ -x "$BIN" ] || { echo "check-docs: $BIN not built"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() { echo "check-docs: $1: $2"; fail=1; }

"$BIN" --help > "$tmp/help" 2>&1
d=$(mktemp -d -p "$tmp")
"$BIN" --print-config --config-dir "$d" --state-dir "$d" > "$tmp/config" 2>&1 ||
	bad "$BIN" "--print-config failed"
# section.key for every key printed
awk '/^\[/ { gsub(/[][]/, ""); s = $0; next } /=/ { print s "." $1 }' "$tmp/config" > "$tmp/keys"

# GitHub's anchor of a heading: lower case, punctuation dropped, blanks as -.
slugs() {
	grep -E '^#+ ' "$1" | sed -E 's/^#+ //' | tr 'A-Z' 'a-z' |
		sed -E 's/[^a-z0-9 _-]//g; s/ /-/g'
}

# The inline code spans of a file, one per line (code blocks excluded).
spans() {
	awk '/^```/ { inb = !inb; next } !inb' "$1" | grep -oE '`[^`]+`' | tr -d '`'
}

# The lines of code blocks.
blocks() {
	awk '/^```/ { inb = !inb; next } inb' "$1"
}

for doc in ${@:-docs/operator.md}; do
	dir=$(dirname "$doc")
	[ -f "$doc" ] || { bad "$doc" "no such file"; continue; }
	slugs "$doc" > "$tmp/slugs"

	# links and images: ](target)
	grep -oE '\]\([^)]+\)' "$doc" | sed -E 's/^\]\(//; s/\)$//' | sort -u |
	while read -r t; do
		case $t in
		http://* | https://*) ;;
		\#*)
			grep -qxF "${t#\#}" "$tmp/slugs" || echo "no heading for link $t" ;;
		*)
			f=${t%%#*}
			[ -e "$dir/$f" ] || echo "link or image $t: $dir/$f does not exist" ;;
		esac
	done > "$tmp/links"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/links"

	# daemon options, in code spans and code blocks, outside other programs' lines
	{ spans "$doc"; blocks "$doc"; } |
		grep -vE '^(sudo )?(systemctl|journalctl|apt|dd|make|lsblk) ' |
		grep -oE '(^|[ (])--[a-z][a-z-]*' | sed -E 's/^[ (]//' | sort -u |
	while read -r o; do
		grep -qE "^ +$o( |$)" "$tmp/help" || echo "option $o: not in arcaded --help"
	done > "$tmp/opts"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/opts"

	# configuration keys section.key (links to *.md are not keys)
	grep -oE '(^|[^a-z0-9/_.-])(audio|display|game|input|paths|recorder)\.[a-z_]+' "$doc" |
		sed -E 's/^[^a-z]//' | grep -vE '\.(md|png)$' | sort -u |
	while read -r k; do
		grep -qxF "$k" "$tmp/keys" || echo "key $k: not printed by arcaded --print-config"
	done > "$tmp/ckeys"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/ckeys"

	# GPIO spec options name= inside code spans
	spans "$doc" | grep -oE '(^|[;,: ])[a-z_]+=' | sed -E 's/^[;,: ]//; s/=$//' | sort -u |
	while read -r o; do
		grep -qF "\"$o\"" input/in_gpio.c || echo "GPIO option $o=: not in input/in_gpio.c"
	done > "$tmp/gopts"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/gopts"

	# make targets
	{ spans "$doc"; blocks "$doc"; } | grep -oE '(^|[ ])make [a-z][a-z-]*' |
		sed -E 's/^ //; s/^make //' | sort -u |
	while read -r t; do
		grep -qE "^$t:" Makefile || echo "make $t: no such target in the Makefile"
	done > "$tmp/targets"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/targets"

	# the service menu map: lines "├── LABEL  what" / "└── LABEL  what"
	blocks "$doc" | grep -E '^(├|└)── ' | sed -E 's/^(├|└)── //; s/  .*//; s/ +$//' |
	while read -r p; do
		grep -qF "\"$p\"" engine/ui/menu_draw.c || echo "service page $p: not drawn by engine/ui/menu_draw.c"
	done > "$tmp/pages"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/pages"

	# encoder table rows: `VVVV:PPPP` | `profile.ini`
	grep -oE '`[0-9a-f]{4}:[0-9a-f]{4}` \| `[a-z0-9-]+\.ini`' "$doc" | tr -d '`|' |
	while read -r id f; do
		p=config/profiles/$f
		if [ ! -f "$p" ]; then
			echo "profile $f: not in config/profiles"
		elif ! grep -qiE "^match *=.*\b$id\b" "$p"; then
			echo "profile $f: its match line does not name $id"
		fi
	done > "$tmp/profs"
	while read -r l; do bad "$doc" "$l"; done < "$tmp/profs"
done

[ $fail -eq 0 ] && echo "check-docs: ${*:-docs/operator.md}: images, links, options, keys, targets, pages and profiles exist"
exit $fail
