#!/usr/bin/env python3
"""Writes the small PNG files the vtkshadow-metrics CLI tests read.

Run from this directory; the outputs are committed. Uses only zlib, an
encoder independent of vshm_png.c, so the tests also check that the reader
decodes files it did not write itself.

The 8x8 case: reference shadowed in columns 0-3, lit in 4-7; mask valid
everywhere except row 0; test shadowed in columns 0-4 (edge one pixel
right). Expected: 56 valid pixels, 7 wrong (column 4, rows 1-7), so
wrong_pct = false_shadow_pct = 12.5, vis_mae = 0.125, edge_px = 1; with
--band 1 columns 3 and 4 leave: 42 compared, wrong_pct 0, edge_px still 1.
"""
import struct
import zlib


def chunk(kind, data):
    c = struct.pack(">I", len(data)) + kind + data
    return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png(rows, depth, color_type, channels):
    w, h = len(rows[0]) // channels, len(rows)
    raw = b""
    for row in rows:
        raw += b"\x00"  # filter type 0
        for s in row:
            raw += struct.pack(">H", s) if depth == 16 else bytes([s])
    ihdr = struct.pack(">IIBBBBB", w, h, depth, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr)
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def write(name, data):
    with open(name, "wb") as f:
        f.write(data)


W = H = 8
ref = [[0 if x < 4 else 65535 for x in range(W)] for y in range(H)]
test = [[0 if x < 5 else 65535 for x in range(W)] for y in range(H)]
mask = [[0 if y == 0 else 255 for x in range(W)] for y in range(H)]
write("ref16.png", png(ref, 16, 0, 1))
write("test16.png", png(test, 16, 0, 1))
write("mask8.png", png(mask, 8, 0, 1))
# exclude: the whole right half (all of the test's error is at x = 4)
write("exclude_right8.png",
      png([[255 if x >= 4 else 0 for x in range(W)] for y in range(H)], 8, 0, 1))
write("mask_empty8.png", png([[0] * W for y in range(H)], 8, 0, 1))
write("small8x6.png", png([[0] * W for y in range(6)], 16, 0, 1))
write("rgb8.png", png([[128] * (3 * W) for y in range(H)], 8, 2, 3))
write("gray_alpha8.png", png([[128, 255] * W for y in range(H)], 8, 4, 2))
whole = png(ref, 16, 0, 1)
write("truncated.png", whole[:len(whole) // 2])
write("not_png.png", b"this is a text file, not a PNG\n")
# Colour files for --reflection: reference (64, 128, 192) everywhere; test
# 16-bit RGBA (alpha dropped), equal but for red 51 levels higher (0.2) in
# columns 4-7. With mask8.png (56 mirror pixels), 28 pixels are off by
# 0.2 / 3: reflection_mae = 1/30; excluding the right half gives 0.
write("ref_rgb8.png", png([[64, 128, 192] * W for y in range(H)], 8, 2, 3))
write("test_rgba16.png",
      png([sum(([(64 + (51 if x >= 4 else 0)) * 257, 128 * 257, 192 * 257, 65535]
                for x in range(W)), []) for y in range(H)], 16, 6, 4))
