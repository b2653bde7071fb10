#!/usr/bin/env python3
"""The special types of a WAD's maps, read straight from the file (a
second reading, not the daemon's), for tests/hostile/run.sh to compare
with `arcaded --print-specials`.

Usage: census.py WAD [MAP]
Prints one line per map and type: "MAP line|sector TYPE COUNT PLAYED", in
the daemon's order (lines first, by type), where PLAYED is 1 when
docs/specials.md says the game plays the type: line specials 1..141 but 78
(vanilla Doom) and 85 (Boom's scroll right); sector specials 1..17 but 6
and 15, and a Boom generalized sector (32 and above) whose low 5 bits are 0
or one of those and that has no friction or wind (bits 8 and up). Then
"total LINES_PLAYED LINES SECTORS_PLAYED SECTORS" over the maps printed.
"""
import struct
import sys

LUMPS = ("THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES")
DOOM_SECTORS = {1, 2, 3, 4, 5, 7, 8, 9, 10, 11, 12, 13, 14, 16, 17}


def line_played(t):
    return (1 <= t <= 141 and t != 78) or t == 85


def sector_played(t):
    low = t & 31
    if t < 32:
        return t in DOOM_SECTORS
    return (low == 0 or low in DOOM_SECTORS) and not t & 0xFF00


def main():
    data = open(sys.argv[1], "rb").read()
    want = sys.argv[2].upper() if len(sys.argv) > 2 else None
    n, off = struct.unpack_from("<ii", data, 4)
    names, lumps = [], []
    for i in range(n):
        pos, size, raw = struct.unpack_from("<ii8s", data, off + 16 * i)
        lumps.append((raw.split(b"\0")[0].decode("ascii", "replace").upper(), pos, size))
    tot = [0, 0, 0, 0]
    for i, (name, _, _) in enumerate(lumps):
        if tuple(l[0] for l in lumps[i + 1:i + 5]) != LUMPS or name in names:
            continue
        names.append(name)
        if want and name != want:
            continue
        lump = {l[0]: l for l in lumps[i + 1:i + 12]}
        count = {}
        _, pos, size = lump["LINEDEFS"]
        for k in range(size // 14):
            t = struct.unpack_from("<H", data, pos + 14 * k + 6)[0]
            if t:
                count[(0, t)] = count.get((0, t), 0) + 1
        _, pos, size = lump["SECTORS"]
        for k in range(size // 26):
            t = struct.unpack_from("<H", data, pos + 26 * k + 22)[0]
            if t:
                count[(1, t)] = count.get((1, t), 0) + 1
        for (kind, t), c in sorted(count.items()):
            played = sector_played(t) if kind else line_played(t)
            print(name, "sector" if kind else "line", t, c, int(played))
            tot[2 * kind + 1] += c
            tot[2 * kind] += c if played else 0
    print("total", *tot)


main()
