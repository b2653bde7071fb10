#!/usr/bin/env python3
"""Writes a file framebuffer (xrgb8888, little-endian: bytes B, G, R, X)
as an RGB PNG, so that a person can look at a frame tests/script/regen.sh
stores the hash of.
Usage: fb2png.py FB WIDTH HEIGHT OUT.png"""
import struct
import sys
import zlib

fb, w, h, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
px = open(fb, 'rb').read()
if len(px) < w * h * 4:
    sys.exit('fb2png.py: %s holds %d bytes, not %dx%dx4' % (fb, len(px), w, h))
rows = bytearray()
for y in range(h):
    rows.append(0)
    row = px[y * w * 4:(y + 1) * w * 4]
    for x in range(w):
        b, g, r = row[4 * x], row[4 * x + 1], row[4 * x + 2]
        rows += bytes((r, g, b))


def chunk(kind, data):
    return (struct.pack('>I', len(data)) + kind + data +
            struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff))


png = b'\x89PNG\r\n\x1a\n'
png += chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0))
png += chunk(b'IDAT', zlib.compress(bytes(rows), 6))
png += chunk(b'IEND', b'')
open(out, 'wb').write(png)
