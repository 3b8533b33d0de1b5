#!/usr/bin/env python3
# Usage: make_soup_stl.py W H OUT.stl (docs/repair.md: the 2M and 10M soups are 1000 1000 and 2500 2000).
# A W x H grid of squares, each cut into two triangles, as binary STL: every triangle its own
# three corners (an unwelded soup); welded by exact position it is one sheet with one hole.
import struct, sys
w, h, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
n = 2 * w * h
s = struct.Struct('<12fH')
with open(out, 'wb') as f:
    f.write(b'\0' * 80 + struct.pack('<I', n))
    for y in range(h):
        row = bytearray(100 * w)
        for x in range(w):
            s.pack_into(row, 100 * x, 0, 0, 1, x, y, 0, x + 1, y, 0, x + 1, y + 1, 0, 0)
            s.pack_into(row, 100 * x + 50, 0, 0, 1, x, y, 0, x + 1, y + 1, 0, x, y + 1, 0, 0)
        f.write(row)
