#!/usr/bin/env python3
"""Draws examples/floorplan/two_rooms.png, the sample floor plan of the README's walk-through.

A 12 m x 8 m flat at 0.05 m per pixel: outer walls 0.2 m thick, an inner wall with a 1.2 m door
between the two rooms, a 2 m x 1 m table in the left room and a 1 m pillar in the right one.
Black = wall, white = free (the importer's convention for outline plans). Standard library only.
"""
import pathlib
import struct
import zlib

RES = 0.05  # m per pixel
W, H = int(13 / RES), int(9 / RES)  # 0.5 m of white page around the flat


def px(m):
    return int(round(m / RES))


def main():
    img = [[255] * W for _ in range(H)]

    def block(x0, y0, x1, y1):  # metres, y down from the top of the page
        for y in range(px(y0), px(y1)):
            for x in range(px(x0), px(x1)):
                img[y][x] = 0

    ox, oy, t = 0.5, 0.5, 0.2
    block(ox, oy, ox + 12, oy + t)              # north wall
    block(ox, oy + 8 - t, ox + 12, oy + 8)      # south wall
    block(ox, oy, ox + t, oy + 8)               # west wall
    block(ox + 12 - t, oy, ox + 12, oy + 8)     # east wall
    block(ox + 6, oy, ox + 6 + t, oy + 3.4)     # inner wall, north part
    block(ox + 6, oy + 4.6, ox + 6 + t, oy + 8) # inner wall, south part (door 3.4-4.6 m)
    block(ox + 2, oy + 3.5, ox + 4, oy + 4.5)   # table
    block(ox + 8.5, oy + 5.0, ox + 9.5, oy + 6.0)  # pillar

    raw = b"".join(b"\x00" + bytes(row) for row in img)
    chunk = lambda tag, data: (struct.pack(">I", len(data)) + tag + data +
                               struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 0, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    out = pathlib.Path(__file__).with_name("two_rooms.png")
    out.write_bytes(png)
    print(f"wrote {out} ({W} x {H} px, {RES} m/px)")


if __name__ == "__main__":
    main()
