#!/bin/sh
# Proves that a field of the sim's state cannot live outside its struct's
# field list (engine/game/sim_table.h): on a copy of engine/, a member is
# written into a state struct by hand, and engine/game/sim_hash.c must then
# fail to compile (SW_CHECK, or the missing walk of a struct without a
# list). The unchanged copy must compile. Checked with each compiler found
# (CC, cc, clang), with no warning flags: the check must not depend on them.
# Places: the end of struct sim_player, the start of struct g_enemy (an
# array element), the end of struct g_entry (into its tail padding, where
# sizeof does not change), the end of struct sim, and a struct without a
# list held by g_game.
set -u
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
ran=0

compile() { # $1 compiler, $2 tree: prints the first error
	"$1" -std=c11 -fsyntax-only -I"$2" "$2/engine/game/sim_hash.c" 2>"$tmp/err"
	rc=$?
	grep -m 1 'error' "$tmp/err" | sed 's/^[^:]*:[0-9]*:[0-9]*: //'
	return $rc
}

# plant NAME FILE SED-SCRIPT: a copy of engine/ with FILE changed by the script
plant() {
	rm -rf "$tmp/t"
	mkdir -p "$tmp/t"
	cp -r engine "$tmp/t/"
	sed -i "$3" "$tmp/t/$2"
	if cmp -s "engine/${2#engine/}" "$tmp/t/$2"; then
		echo "FAIL $1: the plant did not change $2 (the struct moved?)"; fail=1; return 1
	fi
}

ccs=""
for c in ${CC:-} cc clang; do
	command -v "$c" >/dev/null 2>&1 || continue
	case " $ccs " in *" $c "*) ;; *) ccs="$ccs $c" ;; esac
done

for c in $ccs; do
	rm -rf "$tmp/t"; mkdir -p "$tmp/t"; cp -r engine "$tmp/t/"
	if compile "$c" "$tmp/t" >/dev/null; then
		echo "PASS $c: the tree as it is compiles"
	else
		echo "FAIL $c: the unchanged tree does not compile:"; cat "$tmp/err"; fail=1; continue
	fi
	while IFS='|' read -r name file script; do
		[ -n "$name" ] || continue
		plant "$name" "$file" "$script" || continue
		ran=$((ran + 1))
		if err=$(compile "$c" "$tmp/t"); then
			echo "FAIL $c: $name compiles: the hand-written member is not caught"; fail=1
		else
			echo "PASS $c: $name is refused: $err"
		fi
	done <<'EOF'
a member after sim_player's list|engine/game/sim.h|s/^\tSIM_PLAYER_FIELDS(SIM_MEMBER)$/&\n\tuint8_t planted;/
a member before g_enemy's list|engine/game/g_game.h|s/^\tG_ENEMY_FIELDS(SIM_MEMBER)$/\tuint8_t planted;\n&/
a member in g_entry's tail padding|engine/game/g_game.h|s/^\tG_ENTRY_FIELDS(SIM_MEMBER)$/&\n\tuint8_t planted;/
a member after sim's list|engine/game/sim.h|s/^\tSIM_FIELDS(SIM_MEMBER)$/&\n\tuint32_t planted;/
a struct without a list in g_game|engine/game/g_game.h|s/^#define G_GAME_FIELDS(X) \\$/struct g_planted { int a; };\n&\n\tX(SUB, g_planted, planted) \\/
EOF
done
if [ -z "$ccs" ]; then
	echo "FAIL no C compiler found"; fail=1
elif [ "$ran" -eq 0 ]; then
	echo "FAIL nothing was planted"; fail=1
fi
[ "$fail" -eq 0 ] && echo "check-state: $ran planted members refused"
exit "$fail"
