#!/usr/bin/env python3
"""Writes a recording of N ticks of random cabinet input for the soak test:
coins now and then, start presses, movement, turning, strafing and fire held
for random spans, so the game cycles through attract, play, game over and
initials. The header (bytes 0..39, format 1) is taken from a recording the
daemon made of the same content (its map hash, engine version, settings),
so the daemon accepts it.
Usage: gen.py TEMPLATE.rec OUT.rec TICKS SEED"""
import random
import struct
import sys

tmpl, out, ticks, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
hdr = bytearray(open(tmpl, 'rb').read(40))
hdr[8:10] = struct.pack('<H', 1)          # format version 1: commands only
hdr[12:16] = struct.pack('<I', 40)        # header size
hdr[32:36] = struct.pack('<I', ticks)     # command count
rng = random.Random(seed)
FIRE, USE, START, SERVICE = 1, 2, 4, 8
buf = bytearray()
fwd = side = turn = 0
span = 0
for t in range(ticks):
    if span == 0:
        span = rng.randrange(1, 120)
        fwd = rng.choice((0, 0, 127, 127, -127))
        side = rng.choice((0, 0, 0, 127, -127))
        turn = rng.choice((0, 0, 384, -384, 200, -200))
    span -= 1
    buttons = 0
    if rng.randrange(12) == 0:
        buttons |= FIRE
    if t % 997 in (5, 6):
        buttons |= START
    coins = 1 if t % 2999 == 3 else 0
    buf += struct.pack('<bbhBB', fwd, side, turn, buttons, coins)
with open(out, 'wb') as f:
    f.write(hdr)
    f.write(buf)
