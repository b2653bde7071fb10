/*
 * sim_table: how the sim's state is declared. Every struct of the state
 * (struct sim and each struct it holds) lists its fields once, in an
 * X-macro next to the struct, one line a field with the field's comment:
 *
 *   #define SIM_PLAYER_FIELDS(X) \
 *   	X(VAL, fx_t, x, SIM_COORD)           position on the map \
 *   	X(VAL, uint16_t, ammo, SIM_ANY) \
 *   	...
 *   struct sim_player { SIM_PLAYER_FIELDS(SIM_MEMBER) };
 *
 * The struct's members (SIM_MEMBER), the per-tick hash, the snapshot, its
 * restore with the range checks, the snapshot size and the tests' list of
 * fields (sim_visit) are all generated from that one list, in
 * engine/game/sim_hash.c. Adding a field is one line in the list (and a bump
 * of REC_ENGINE_VERSION, input/rec.h: the hashes change). A member written
 * into such a struct outside its list stops the build (SW_CHECK in
 * sim_hash.c; tests/check_state.sh proves it).
 *
 * Why an X-macro and not a table of offsets and sizes: a field's limit is a
 * C expression that may name the fields before it and the whole sim (alive
 * at most num_enemies, a sector of the current map, the letter position in
 * INITIALS); generated code evaluates it in place, where a table of data
 * would need a small interpreter of limits. The compiler also checks each
 * field's type against the walk (a uint16_t is walked as one), which a
 * table of sizes cannot.
 *
 * Entries (KIND first; the others by kind):
 *   X(VAL, type, name, limit)            an integer of type uint8_t, uint16_t,
 *                                        uint32_t, uint64_t, int8_t, int16_t,
 *                                        int32_t, fx_t, ang_t or char
 *   X(ARR, type, name, n, used, limit)   an array of n of those; the
 *                                        elements from `used` on are spare
 *   X(ENUM, type, name, count)           an enum, 4 bytes, 0 .. count - 1 (a
 *                                        restore maps other values to 0)
 *   X(SUB, tag, name)                    a struct tag, which has its own list
 *   X(SUBS, tag, name, n, used)          an array of n of them; spare from used on
 *   X(FN, type, name, fn)                walked by the function fn of
 *                                        sim_hash.c (the borrowed maps)
 *   X(FNS, type, name, n, fn)            the same, an array
 *
 * Spare: a slot at or past its array's count is not state (spawning
 * overwrites it): the snapshot saves it, so a restore gives back the very
 * bytes, but the hash skips it and the restore does not check it. `used` is
 * SIM_ALL for an array whose every slot is state.
 *
 * Limits (what sim_restore accepts; the hash and the snapshot ignore them):
 *   SIM_ANY               every value of the type
 *   SIM_MAX(m)            0 .. m
 *   SIM_RANGE(lo, hi)     lo .. hi
 *   SIM_COORD             a position or height on a map (MAP_COORD_MAX)
 *   SIM_SECTOR            a sector index of the current map
 * In n, used and limits, `p` is the struct being walked, whose earlier
 * fields are already read when a restore gets to this one, and `s` the
 * whole struct sim. 64-bit fields take SIM_ANY.
 *
 * The walk is in list order, which is the members' order: a new field goes
 * where it belongs in the struct, and the hash and snapshot follow it.
 */
#ifndef ARCADED_ENGINE_SIM_TABLE_H
#define ARCADED_ENGINE_SIM_TABLE_H

#include <stdint.h>

/* The members of a struct from its list: struct foo { FOO_FIELDS(SIM_MEMBER) }; */
#define SIM_MEMBER(kind, ...) SIM_MEMBER_##kind(__VA_ARGS__)
#define SIM_MEMBER_VAL(type, name, limit) type name;
#define SIM_MEMBER_ARR(type, name, n, used, limit) type name[n];
#define SIM_MEMBER_ENUM(type, name, count) type name;
#define SIM_MEMBER_SUB(tag, name) struct tag name;
#define SIM_MEMBER_SUBS(tag, name, n, used) struct tag name[n];
#define SIM_MEMBER_FN(type, name, fn) type name;
#define SIM_MEMBER_FNS(type, name, n, fn) type name[n];

/* Limits: a (lo, hi) pair in parentheses, so it stays one macro argument. */
#define SIM_ANY (INT64_MIN, INT64_MAX)
#define SIM_MAX(m) (0, (m))
#define SIM_RANGE(lo, hi) ((lo), (hi))
#define SIM_COORD (-MAP_COORD_MAX, MAP_COORD_MAX)
#define SIM_SECTOR (0, sw_sector_max(s))
#define SIM_LO(lo, hi) (lo)
#define SIM_HI(lo, hi) (hi)

/* `used` of an array whose every slot is state. */
#define SIM_ALL 0x7fffffff

#endif
