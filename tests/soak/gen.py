#!/usr/bin/env python3
"""Writes a recording of N ticks of cabinet input for the soak test. It
starts with the commands of TEMPLATE.rec, a recording the daemon made of
the same content (tests/script/game/flow.scr: the whole arcade flow, which
a random player does not finish: a new high score and its initials), then
random input: coins now and then, start presses, movement, turning,
strafing and fire held for random spans, so the game cycles through
attract, play and game over. The header (bytes 0..39, format 1) is the
template's (its map hash, engine version, settings; the pacing settings
at its bytes 37 and 38 must be the defaults, which format 1 stores as 0),
so the daemon accepts it.
Usage: gen.py TEMPLATE.rec OUT.rec TICKS SEED"""
import random
import struct
import sys

tmpl, out, ticks, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
raw = open(tmpl, 'rb').read()
hdr = bytearray(raw[:40])
# the template's commands: records after its header, each the 6-byte
# command, then 8 bytes per hash its flags say it stores (input/rec.h)
version = struct.unpack_from('<H', raw, 8)[0]
hsize = struct.unpack_from('<I', raw, 12)[0]
count = struct.unpack_from('<I', raw, 32)[0]
flags = raw[44] if version >= 2 else 0
rsize = 6 + 8 * bin(flags & 0x0b).count('1')  # state 1, frame 2, audio 8 (format 3)
if flags & 4 or count == 0xffffffff:
    sys.exit('gen.py: %s starts from a snapshot or was not finished' % tmpl)
prefix = [raw[hsize + i * rsize:hsize + i * rsize + 6] for i in range(count)]
if len(prefix) != count or any(len(c) != 6 for c in prefix) or count > ticks:
    sys.exit('gen.py: %s: %d records, bad or more than %d ticks' % (tmpl, count, ticks))
hdr[8:10] = struct.pack('<H', 1)          # format version 1: commands only
hdr[12:16] = struct.pack('<I', 40)        # header size
hdr[32:36] = struct.pack('<I', ticks)     # command count
# Format 1 has no room for the format 3 settings kept in bytes 37 and 38
# (stage_time, idle_out): they are reserved (0) there, which reads back as
# the defaults, the template's own settings.
if hdr[37] not in (0, 5) or hdr[38] != 0:
    sys.exit('gen.py: %s: stage_time %d, idle_out %d are not the defaults' % (tmpl, hdr[37], hdr[38]))
hdr[37:40] = bytes(3)
rng = random.Random(seed)
FIRE, USE, START, SERVICE = 1, 2, 4, 8
buf = bytearray(b''.join(prefix))
fwd = side = turn = 0
span = 0
for t in range(count, ticks):
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
