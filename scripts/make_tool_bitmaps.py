#!/usr/bin/env python3
"""Draws Klueng's shipped tool bitmaps (SPEC 11) into resources/tools/*.bmp.

Each tool is drawn as it appears in the X-up lathe drawing above the centre
line, at 2 pixels per millimetre: black = holder, white = empty, gold = the
insert (cutting edge). Shapes are polygons in millimetres (x to the right,
y DOWN, as in the image); a pixel takes a shape's colour when at least half of
it is covered (4 x 4 samples). Inserts are drawn after holders, so they win.

The insert's corner sits where the offset's tip number says (SPEC 9 grid):
  01 outside turning tool        tip 3 (bottom-left)
  02 outside left-hand tool      tip 4 (bottom-right)
  03 60-degree threading tool    tip 8 (bottom middle)
  04 grooving tool, 3 mm         tip 3
  05 boring bar                  tip 2 (top-left)
  06 drill 10 mm                 tip 7 (left middle = the drill point on the axis)
  07 parting tool, 3 mm          tip 3
  08 inside threading tool       tip 6 (top middle)

It also draws the tool library (resources/tools/library/*.png, listed in
library.cfg) at 10 pixels per millimetre, so their flank angles are true.

Plain Python 3, no third-party modules:
  python3 scripts/make_tool_bitmaps.py [--out resources/tools] [--preview DIR]
"""
import argparse
import math
import os
import struct
import zlib

PX_PER_MM = 2
SAMPLES = 4
WHITE = (255, 255, 255)
BLACK = (0, 0, 0)
GOLD = (0xE0, 0xA0, 0x00)


def rhombus(tip, first_deg, second_deg, side):
    """Rhombic insert with its cutting corner at `tip`; the two edges leave the
    corner at the given angles (degrees, measured with y UP, as in the lathe view)."""
    tx, ty = tip
    a = (tx + side * math.cos(math.radians(first_deg)), ty - side * math.sin(math.radians(first_deg)))
    b = (tx + side * math.cos(math.radians(second_deg)), ty - side * math.sin(math.radians(second_deg)))
    c = (a[0] + b[0] - tx, a[1] + b[1] - ty)
    return [tip, a, c, b]


def mirror_x(poly, width):
    return [(width - x, y) for x, y in poly]


def mirror_y(poly, height):
    return [(x, height - y) for x, y in poly]


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def inside(poly, x, y):
    result = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]
        x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y):
            if x < x1 + (y - y1) * (x2 - x1) / (y2 - y1):
                result = not result
    return result


def render(width_mm, height_mm, shapes, ppm=PX_PER_MM):
    """shapes: list of (colour, polygon); later shapes are drawn over earlier ones."""
    w, h = int(round(width_mm * ppm)), int(round(height_mm * ppm))
    pixels = [[WHITE] * w for _ in range(h)]
    step = 1.0 / (ppm * SAMPLES)
    for colour, poly in shapes:
        xs = [p[0] for p in poly]
        ys = [p[1] for p in poly]
        px0, px1 = max(0, int(min(xs) * ppm) - 1), min(w, int(max(xs) * ppm) + 2)
        py0, py1 = max(0, int(min(ys) * ppm) - 1), min(h, int(max(ys) * ppm) + 2)
        for py in range(py0, py1):
            for px in range(px0, px1):
                hits = 0
                for sy in range(SAMPLES):
                    for sx in range(SAMPLES):
                        x = px / ppm + (sx + 0.5) * step
                        y = py / ppm + (sy + 0.5) * step
                        hits += inside(poly, x, y)
                if hits * 2 >= SAMPLES * SAMPLES:
                    pixels[py][px] = colour
    return pixels


def bmp_bytes(pixels):
    h, w = len(pixels), len(pixels[0])
    stride = (w * 3 + 3) & ~3
    data = bytearray()
    for row in reversed(pixels):  # bottom-up
        line = bytearray()
        for r, g, b in row:
            line += bytes((b, g, r))
        line += b"\0" * (stride - len(line))
        data += line
    header = struct.pack("<2sIHHI", b"BM", 54 + len(data), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 24, 0, len(data), 3780, 3780, 0, 0)
    return header + info + bytes(data)


def png_bytes(pixels, scale=4, ppm=PX_PER_MM, grid=True):
    """A scaled-up PNG preview with a grey grid every 5 mm, for looking at the tools
    (grid=False, scale=1: the tool itself, as the library ships it)."""
    h, w = len(pixels), len(pixels[0])
    raw = bytearray()
    for y in range(h * scale):
        raw.append(0)
        for x in range(w * scale):
            colour = pixels[y // scale][x // scale]
            on_grid = (x % (5 * ppm * scale) == 0) or (y % (5 * ppm * scale) == 0)
            if colour == WHITE and on_grid and grid:
                colour = (200, 200, 200)
            raw += bytes(colour)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    ihdr = struct.pack(">IIBBBBB", w * scale, h * scale, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")


# ---------------------------------------------------------------- the tools


def outside_turning():
    """PCLNR-style holder, 25 mm shank, 80-degree rhombic insert (CNMG 12), 95-degree
    approach: the main edge nearly square to Z, the corner bottom-left (tip 3)."""
    width, height = 36.0, 62.0
    tip = (2.0, 60.0)
    insert = rhombus(tip, 85.0, 5.0, 12.0)
    shank = rect(9.0, 0.0, 34.0, 42.0)
    head = [(3.5, 38.0), (34.0, 38.0), (34.0, 48.0), (16.5, 58.2), (9.0, 53.0), (3.6, 48.5)]
    return width, height, [(BLACK, shank), (BLACK, head), (GOLD, insert)]


def outside_left_hand():
    width, height, shapes = outside_turning()
    return width, height, [(c, mirror_x(p, width)) for c, p in shapes]


def threading_outside():
    """20 mm shank, laydown 60-degree insert, point at the bottom middle (tip 8)."""
    width, height = 30.0, 62.0
    cx, tip_y = 15.0, 60.0
    flank = 10.0 * math.tan(math.radians(30.0))
    insert = [(cx, tip_y), (cx + flank, tip_y - 10.0), (cx + 7.0, tip_y - 16.0),
              (cx - 7.0, tip_y - 16.0), (cx - flank, tip_y - 10.0)]
    shank = rect(5.0, 0.0, 25.0, 40.0)
    head = [(5.0, 38.0), (25.0, 38.0), (25.0, 44.0), (21.0, 47.0), (9.0, 47.0), (5.0, 44.0)]
    return width, height, [(BLACK, shank), (BLACK, head), (GOLD, insert)]


def grooving():
    """3 mm grooving insert at the left edge of a 20 mm shank, corner bottom-left (tip 3);
    the blade behind the insert is narrower for side clearance."""
    width, height = 32.0, 64.0
    x0, tip_y = 2.0, 62.0
    insert = [(x0, tip_y), (x0 + 3.0, tip_y), (x0 + 3.0, tip_y - 7.0), (x0 + 0.2, tip_y - 8.0)]
    blade = rect(x0 + 0.3, tip_y - 22.0, x0 + 2.7, tip_y - 6.0)
    gusset = [(x0 + 2.7, tip_y - 22.0), (30.0, tip_y - 22.0), (30.0, tip_y - 16.0), (x0 + 2.7, tip_y - 8.0)]
    shank = rect(x0, 0.0, 30.0, tip_y - 21.0)
    return width, height, [(BLACK, shank), (BLACK, blade), (BLACK, gusset), (GOLD, insert)]


def boring_bar():
    """16 mm boring bar along Z going right, 80-degree insert at its left end with the
    corner at the top-left (tip 2): the tool as it sits inside a bore above the centre line."""
    width, height = 110.0, 22.0
    tip = (2.0, 2.0)
    insert = rhombus(tip, -85.0, -5.0, 9.6)
    bar = rect(8.0, 5.0, 110.0, 21.0)
    head = [(3.6, 12.0), (3.6, 5.0), (14.0, 5.0), (14.0, 21.0), (8.0, 21.0), (3.6, 14.0)]
    return width, height, [(BLACK, bar), (BLACK, head), (GOLD, insert)]


def drill():
    """10 mm twist drill along Z, 118-degree point at the left (tip 7: the middle of the
    left edge, which is the drill point on the spindle axis). The fluted body counts as
    cutting edge; the shank and its holder are black."""
    width, height = 100.0, 30.0
    cy = 15.0
    cone = 5.0 / math.tan(math.radians(59.0))
    body = [(0.0, cy), (cone, cy - 5.0), (55.0, cy - 5.0), (55.0, cy + 5.0), (cone, cy + 5.0)]
    shank = rect(55.0, cy - 5.0, 75.0, cy + 5.0)
    holder = rect(70.0, 0.0, 100.0, 30.0)
    return width, height, [(BLACK, shank), (BLACK, holder), (GOLD, body)]


def parting():
    """3 mm parting insert on a long 2.6 mm blade held in a block, corner bottom-left (tip 3)."""
    width, height = 36.0, 58.0
    x0, tip_y = 2.0, 56.0
    insert = [(x0, tip_y), (x0 + 3.0, tip_y), (x0 + 3.0, tip_y - 6.0), (x0 + 0.2, tip_y - 7.0)]
    blade = rect(x0 + 0.2, 14.0, x0 + 2.8, tip_y - 5.0)
    block = rect(x0, 0.0, 34.0, 22.0)
    return width, height, [(BLACK, blade), (BLACK, block), (GOLD, insert)]


def threading_inside():
    """16 mm bar along Z going right, 60-degree insert at its left end, point up (tip 6)."""
    width, height = 100.0, 26.0
    cx, tip_y = 8.0, 1.0
    flank = 9.0 * math.tan(math.radians(30.0))
    insert = [(cx, tip_y), (cx + flank, tip_y + 9.0), (cx + 6.0, tip_y + 13.0),
              (cx - 6.0, tip_y + 13.0), (cx - flank, tip_y + 9.0)]
    bar = rect(3.0, 10.0, 100.0, 25.0)
    return width, height, [(BLACK, bar), (GOLD, insert)]


TOOLS = [
    ("01-outside-turning.bmp", outside_turning),
    ("02-outside-left-hand.bmp", outside_left_hand),
    ("03-threading-60.bmp", threading_outside),
    ("04-grooving-3mm.bmp", grooving),
    ("05-boring-bar.bmp", boring_bar),
    ("06-drill-10mm.bmp", drill),
    ("07-parting-3mm.bmp", parting),
    ("08-inside-threading.bmp", threading_inside),
]


# ---------------------------------------------------------------- the library
# resources/tools/library/: the tools a school lathe has, drawn at 10 px/mm so
# that their flank angles are true (a 35-degree VNMG corner is 35 degrees to
# well under a degree over its edge length). library.cfg lists them
# (docs/tools.md); the nose radius there is modelled exactly by the simulator.

LIB_PPM = 10


def turning_insert(included_deg, lead_deg, side, tip=(2.0, 60.0)):
    """Outside turning holder with a rhombic insert: the main edge leaves the corner
    (bottom-left, tip 3) at lead_deg from +Z (87 = 93-degree approach), the trailing
    edge at lead_deg - included_deg."""
    width, height = 40.0, tip[1] + 2.0
    insert = rhombus(tip, lead_deg, lead_deg - included_deg, side)
    _, a, _, b = insert
    trailing = math.tan(math.radians(lead_deg - included_deg))

    def below_trailing(x, margin):  # y (down) of the trailing edge's line, raised by margin
        return tip[1] - (x - tip[0]) * trailing - margin

    # Near the insert the head stays above the trailing edge's line (it clears a profile
    # the insert can follow); further right it keeps 8 mm above the tip, as a real holder.
    head = [(a[0] + 1.0, a[1] - 2.0), (38.0, a[1] - 2.0), (38.0, tip[1] - 8.0),
            (b[0] + 0.5, min(b[1], below_trailing(b[0] + 0.5, 0.0)) - 1.5)]
    shank = rect(12.0, 0.0, 37.0, a[1] - 1.0)
    return width, height, [(BLACK, shank), (BLACK, head), (GOLD, insert)]


def lib_cnmg():
    return turning_insert(80.0, 87.0, 12.9)


def lib_dnmg():
    return turning_insert(55.0, 87.0, 15.5)


def lib_vnmg():
    return turning_insert(35.0, 87.0, 16.6)


def lib_drill(diameter, body_len=None, cone_deg=118.0, colour=GOLD):
    """Twist drill along Z, point on the left (tip 7), fluted body = cutting edge."""
    r = diameter / 2.0
    body_len = body_len or max(40.0, 5.0 * diameter)
    height = max(2.0 * r + 10.0, 30.0)
    cy = height / 2.0
    cone = r / math.tan(math.radians(cone_deg / 2.0))
    body = [(0.0, cy), (cone, cy - r), (body_len, cy - r), (body_len, cy + r), (cone, cy + r)]
    shank = rect(body_len, cy - r, body_len + 20.0, cy + r)
    holder = rect(body_len + 15.0, 0.0, body_len + 45.0, height)
    return body_len + 45.0, height, [(BLACK, shank), (BLACK, holder), (colour, body)]


def lib_centre_drill():
    """A3.15 centre drill: 3.15 mm pilot, 60-degree countersink, 8 mm body."""
    height, cy = 30.0, 15.0
    pilot_r, pilot_len, body_r = 3.15 / 2.0, 3.6, 4.0
    tip = pilot_r / math.tan(math.radians(59.0))
    sink = (body_r - pilot_r) / math.tan(math.radians(30.0))
    x1, x2 = tip + pilot_len, tip + pilot_len + sink
    edge = [(0.0, cy), (tip, cy - pilot_r), (x1, cy - pilot_r), (x2, cy - body_r), (x2 + 3.0, cy - body_r),
            (x2 + 3.0, cy + body_r), (x2, cy + body_r), (x1, cy + pilot_r), (tip, cy + pilot_r)]
    body = rect(x2 + 3.0, cy - body_r, 45.0, cy + body_r)
    holder = rect(35.0, 0.0, 70.0, height)
    return 70.0, height, [(BLACK, body), (BLACK, holder), (GOLD, edge)]


def lib_threading_od():
    width, height, shapes = threading_outside()
    return width, height, shapes


def lib_threading_id():
    return threading_inside()


def lib_blade(width_mm):
    """Grooving/parting blade: insert width_mm wide, corner bottom-left (tip 3)."""
    width, height = 36.0, 58.0
    x0, tip_y = 2.0, 56.0
    w = width_mm
    insert = [(x0, tip_y), (x0 + w, tip_y), (x0 + w, tip_y - 6.0), (x0 + 0.15, tip_y - 7.0)]
    blade = rect(x0 + 0.2, 14.0, x0 + w - 0.2, tip_y - 5.0)
    block = rect(x0, 0.0, 34.0, 22.0)
    return width, height, [(BLACK, blade), (BLACK, block), (GOLD, insert)]


def lib_grooving():
    width, height = 32.0, 40.0
    x0, tip_y = 2.0, 38.0
    insert = [(x0, tip_y), (x0 + 3.0, tip_y), (x0 + 3.0, tip_y - 7.0), (x0 + 0.15, tip_y - 8.0)]
    blade = rect(x0 + 0.2, tip_y - 20.0, x0 + 2.8, tip_y - 6.0)
    gusset = [(x0 + 2.8, tip_y - 20.0), (30.0, tip_y - 20.0), (30.0, tip_y - 14.0), (x0 + 2.8, tip_y - 8.0)]
    shank = rect(x0, 0.0, 30.0, tip_y - 19.0)
    return width, height, [(BLACK, shank), (BLACK, blade), (BLACK, gusset), (GOLD, insert)]


def lib_boring_bar(bar_mm=16.0):
    """Boring bar of bar_mm, 80-degree insert with the corner top-left (tip 2), 95-degree
    approach. The 16 mm bar is the drawing; a slimmer bar is the same drawing scaled about
    the insert's corner (a smaller insert on a smaller head), its bar as long."""
    k = bar_mm / 16.0
    tip = (2.0, 2.0)

    def s(p):
        return (tip[0] + (p[0] - tip[0]) * k, tip[1] + (p[1] - tip[1]) * k)

    width, height = 120.0, math.ceil(2.0 + 20.0 * k)
    insert = rhombus(tip, -85.0, -5.0, 9.6 * k)
    bar = rect(s((8.0, 5.0))[0], s((8.0, 5.0))[1], 120.0, s((8.0, 21.0))[1])
    head = [s(p) for p in [(3.6, 12.0), (3.6, 5.0), (14.0, 5.0), (14.0, 21.0), (8.0, 21.0), (3.6, 14.0)]]
    return width, height, [(BLACK, bar), (BLACK, head), (GOLD, insert)]


LIBRARY = [
    ("cnmg-80-r08.png", lib_cnmg),
    ("cnmg-80-r04.png", lib_cnmg),
    ("dnmg-55-r04.png", lib_dnmg),
    ("vnmg-35-r02.png", lib_vnmg),
    ("threading-60.png", lib_threading_od),
    ("threading-60-id.png", lib_threading_id),
    ("grooving-3mm.png", lib_grooving),
    ("parting-3mm.png", lambda: lib_blade(3.0)),
    ("centre-drill-a3.png", lib_centre_drill),
    ("drill-6mm.png", lambda: lib_drill(6.0)),
    ("drill-10mm.png", lambda: lib_drill(10.0)),
    ("drill-16mm.png", lambda: lib_drill(16.0)),
    ("drill-20mm.png", lambda: lib_drill(20.0)),
    # Sizes shops name in comments (issue 26): metric, and 1/2" and 1" drills.
    ("drill-8mm.png", lambda: lib_drill(8.0)),
    ("drill-12mm.png", lambda: lib_drill(12.0)),
    ("drill-12.7mm.png", lambda: lib_drill(12.7)),
    ("drill-14mm.png", lambda: lib_drill(14.0)),
    ("drill-18mm.png", lambda: lib_drill(18.0)),
    ("drill-22mm.png", lambda: lib_drill(22.0)),
    ("drill-25mm.png", lambda: lib_drill(25.0)),
    ("drill-25.4mm.png", lambda: lib_drill(25.4)),
    ("boring-bar-16.png", lib_boring_bar),
    # A slimmer bar for small bores (issue 26: a guessed bar that touches is tried slimmer).
    ("boring-bar-10.png", lambda: lib_boring_bar(10.0)),
]


def write_tool(folder, name, draw, ppm, preview):
    width, height, shapes = draw()
    pixels = render(width, height, shapes, ppm)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(png_bytes(pixels, 1, ppm, grid=False) if name.endswith(".png") else bmp_bytes(pixels))
    if preview:
        os.makedirs(preview, exist_ok=True)
        with open(os.path.join(preview, name.replace(".bmp", ".png").replace(".png", "-preview.png")), "wb") as f:
            f.write(png_bytes(pixels, 4 if ppm <= 2 else 1, ppm))
    print(f"{name}: {len(pixels[0])} x {len(pixels)} px at {ppm} px/mm")


def main():
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(top, "resources", "tools"))
    parser.add_argument("--preview", help="also write scaled PNG previews into this folder")
    parser.add_argument("--only", choices=["seed", "library"], help="draw only one of the two sets")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.only != "library":
        for name, draw in TOOLS:
            write_tool(args.out, name, draw, PX_PER_MM, args.preview)
    if args.only != "seed":
        lib = os.path.join(args.out, "library")
        os.makedirs(lib, exist_ok=True)
        for name, draw in LIBRARY:
            write_tool(lib, name, draw, LIB_PPM, args.preview)


if __name__ == "__main__":
    main()
