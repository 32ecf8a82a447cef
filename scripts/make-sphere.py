#!/usr/bin/env python3
"""Writes a unit UV sphere (48 x 96 quads, split into triangles, outward) as
OBJ: the source of the morph scripts' sphere -> mesh runs.

    python3 scripts/make-sphere.py OUT.obj
"""
import math
import sys

rings, sides = 48, 96
with open(sys.argv[1], "w") as out:
    out.write("v 0 0 1\n")
    for i in range(1, rings):
        t = math.pi * i / rings
        for j in range(sides):
            p = 2 * math.pi * j / sides
            out.write(f"v {math.sin(t) * math.cos(p)} {math.sin(t) * math.sin(p)} {math.cos(t)}\n")
    out.write("v 0 0 -1\n")
    bottom = 2 + (rings - 1) * sides
    ring = lambda i, j: 2 + i * sides + j % sides
    for j in range(sides):
        out.write(f"f 1 {ring(0, j)} {ring(0, j + 1)}\n")
        out.write(f"f {ring(rings - 2, j)} {bottom} {ring(rings - 2, j + 1)}\n")
    for i in range(rings - 2):
        for j in range(sides):
            out.write(f"f {ring(i, j)} {ring(i + 1, j)} {ring(i + 1, j + 1)}\n")
            out.write(f"f {ring(i, j)} {ring(i + 1, j + 1)} {ring(i, j + 1)}\n")
