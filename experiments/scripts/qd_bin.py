#!/usr/bin/env python3
"""Bins runs' lineage.csv into one MAP-Elites grid (experiments/, from
2026-11-23-map-elites-vs-ga.md on).

Every run written with a `descriptors` list (MAP-Elites always; a GA when its
config declares them) records each birth's descriptor values in lineage.csv
(docs/evolution.md). This bins every valid birth into the grid of a config's
`descriptors` (bin = floor((x - min) / (max - min) * bins), clamped to the
edge cells, as evolution/archives/archive.cpp does) and keeps the best fitness per
cell: what a MAP-Elites archive over all of the run's births would hold.

  qd_bin.py table --grid-from CONFIG [--budget B] [--qd-offset O] METHOD/SEED=RUN_DIR...
      a markdown table: coverage (occupied / all cells), QD-score (sum over
      occupied cells of fitness - offset) and best fitness per run, and the
      means per method
  qd_bin.py heatmap --grid-from CONFIG --png OUT.png TITLE=RUN_DIR...
      the runs' best-fitness-per-cell maps side by side on one colour scale
      (blue low .. yellow high, as `morphogen archive --png`), empty cells grey
  qd_bin.py union --grid-from CONFIG [--qd-offset O] RUN_DIR...
      the best fitness per cell over the births of all the runs together: the
      most of the grid any of them reached, a bound on what a method can
      claim from this evidence (coverage and QD-score)
  qd_bin.py parents RUN_DIR...
      selection pressure: the share of bred births (those with a parent) whose
      first parent was within 10 % of the best fitness born before them

Standard library only (the PNG is written with zlib).
"""
import argparse
import csv
import json
import math
import struct
import sys
import zlib


def fail(message):
    sys.exit(f"qd_bin.py: {message}")


def read_grid(config_path):
    try:
        with open(config_path) as f:
            descriptors = json.load(f)["descriptors"]
    except (OSError, ValueError, KeyError, TypeError) as e:
        fail(f"{config_path}: cannot read its descriptors ({e})")
    grid = []
    for i, d in enumerate(descriptors):
        try:
            grid.append((d["measure"], float(d["min"]), float(d["max"]), int(d.get("bins", 10))))
        except (KeyError, TypeError, ValueError) as e:
            fail(f"{config_path}: descriptors[{i}]: {e}")
    return grid


def bin_of(x, lo, hi, bins):
    t = math.floor((x - lo) / (hi - lo) * bins)
    return 0 if not t > 0 else int(min(t, bins - 1))


def bin_run(run_dir, grid):
    """(best fitness per cell as {cell tuple: fitness}, best fitness, births, valid births)."""
    path = f"{run_dir}/lineage.csv"
    try:
        f = open(path, newline="")
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    with f:
        reader = csv.reader(f)
        header = next(reader, None)
        if header is None or header[:5] != ["id", "birth", "parent1", "parent2", "fitness"]:
            fail(f"{path}: not a lineage.csv (header {header})")
        try:
            columns = [header.index(name) for name, _, _, _ in grid]
        except ValueError:
            fail(f"{path}: no column for every descriptor of the grid {[g[0] for g in grid]} "
                 f"(header {','.join(header)}): give the run's config a `descriptors` list")
        cells, best, births, valid = {}, None, 0, 0
        for row in reader:
            births += 1
            if len(row) != len(header):
                fail(f"{path}: row {births} has {len(row)} cells, the header {len(header)}")
            if not row[4]:
                continue
            fitness = float(row[4])
            valid += 1
            best = fitness if best is None else max(best, fitness)
            if any(not row[c] for c in columns):
                continue  # a GA birth whose measures could not be taken
            cell = tuple(bin_of(float(row[c]), lo, hi, bins) for c, (_, lo, hi, bins) in zip(columns, grid))
            if cell not in cells or fitness > cells[cell]:
                cells[cell] = fitness
    return cells, best, births, valid


def n_cells(grid):
    return math.prod(g[3] for g in grid)


def table(args):
    grid = read_grid(args.grid_from)
    total = n_cells(grid)
    results = []  # (method, seed, coverage, qd, best, births, cells with fitness > offset)
    for spec in args.runs:
        name, sep, run_dir = spec.partition("=")
        method, _, seed = name.partition("/")
        if not sep or not run_dir:
            fail(f"{spec!r}: expected METHOD/SEED=RUN_DIR")
        cells, best, births, _ = bin_run(run_dir, grid)
        if args.budget and births != args.budget:
            print(f"qd_bin.py: warning: {run_dir} has {births} births, not the budget {args.budget}", file=sys.stderr)
        qd = sum(f - args.qd_offset for f in cells.values())
        results.append((method, seed, len(cells) / total, qd, best, births,
                        sum(1 for f in cells.values() if f > args.qd_offset)))

    names = " x ".join(f"{n} [{lo:g}, {hi:g}] in {b} bins" for n, lo, hi, b in grid)
    print(f"Grid: {names} ({total} cells); QD-score offset {args.qd_offset:g}.\n")
    print(f"| method | seed | births | coverage | cells scoring > {args.qd_offset:g} | QD-score | best canopy |")
    print("|---|---|---|---|---|---|---|")
    for method, seed, coverage, qd, best, births, scoring in results:
        best_text = "—" if best is None else f"{best:.1f}"
        print(f"| {method} | {seed} | {births} | {coverage:.4f} ({round(coverage * total)} cells) | {scoring} | {qd:.0f} | "
              f"{best_text} |")
    print()
    methods = list(dict.fromkeys(r[0] for r in results))
    means = {}
    for m in methods:
        rows = [r for r in results if r[0] == m]
        bests = [r[4] for r in rows if r[4] is not None]
        means[m] = (sum(r[2] for r in rows) / len(rows), sum(r[3] for r in rows) / len(rows),
                    sum(bests) / len(bests) if bests else None, len(rows))
    reference = args.reference if args.reference in means else methods[0]
    print(f"| method (mean of seeds) | coverage | QD-score | best canopy | coverage / {reference}'s | "
          f"QD-score / {reference}'s | best / {reference}'s |")
    print("|---|---|---|---|---|---|---|")
    rc, rq, rb, _ = means[reference]
    for m in methods:
        c, q, b, n = means[m]
        ratio = lambda x, y: f"{x / y:.2f}" if x is not None and y else "—"
        print(f"| {m} ({n} seeds) | {c:.4f} | {q:.0f} | {'—' if b is None else f'{b:.1f}'} | {ratio(c, rc)} | "
              f"{ratio(q, rq)} | {ratio(b, rb)} |")


def union(args):
    grid = read_grid(args.grid_from)
    pooled = {}
    for run_dir in args.runs:
        cells, _, _, _ = bin_run(run_dir, grid)
        for cell, fitness in cells.items():
            if cell not in pooled or fitness > pooled[cell]:
                pooled[cell] = fitness
    qd = sum(f - args.qd_offset for f in pooled.values())
    total = n_cells(grid)
    print(f"union of {len(args.runs)} runs: coverage {len(pooled) / total:.4f} ({len(pooled)} of {total} cells), "
          f"QD-score {qd:.0f}, best {max(pooled.values()) if pooled else float('nan'):.1f}")


# A 3x5 pixel font (upper case, digits, a few signs) for the heatmap's labels.
FONT = {
    "0": "111101101101111", "1": "010110010010111", "2": "111001111100111", "3": "111001111001111",
    "4": "101101111001001", "5": "111100111001111", "6": "111100111101111", "7": "111001001001001",
    "8": "111101111101111", "9": "111101111001111", "A": "010101111101101", "B": "110101110101110",
    "C": "011100100100011", "D": "110101101101110", "E": "111100110100111", "F": "111100110100100",
    "G": "011100101101011", "H": "101101111101101", "I": "111010010010111", "J": "001001001101010",
    "K": "101101110101101", "L": "100100100100111", "M": "101111111101101", "N": "110101101101101",
    "O": "010101101101010", "P": "110101110100100", "Q": "010101101110011", "R": "110101110101101",
    "S": "011100010001110", "T": "111010010010010", "U": "101101101101111", "V": "101101101101010",
    "W": "101101111111101", "X": "101101010101101", "Y": "101101010010010", "Z": "111001010100111",
    "-": "000000111000000", ".": "000000000000010", ",": "000000000010100", "(": "010100100100010",
    ")": "010001001001010", ":": "000010000010000", "=": "000111000111000", "/": "001001010100100",
    "%": "101001010100101", " ": "000000000000000", "_": "000000000000111", "+": "000010111010000",
}


class Canvas:
    def __init__(self, width, height):
        self.width, self.height = width, height
        self.rgb = bytearray([255]) * (width * height * 3)

    def rect(self, x0, y0, w, h, colour):
        for y in range(max(0, y0), min(self.height, y0 + h)):
            start = (y * self.width + max(0, x0)) * 3
            n = max(0, min(self.width, x0 + w) - max(0, x0))
            self.rgb[start:start + 3 * n] = bytes(colour) * n

    def text(self, x, y, text, scale=2, colour=(0, 0, 0)):
        for ch in text.upper():
            glyph = FONT.get(ch, FONT[" "])
            for i, bit in enumerate(glyph):
                if bit == "1":
                    self.rect(x + (i % 3) * scale, y + (i // 3) * scale, scale, scale, colour)
            x += 4 * scale

    @staticmethod
    def text_width(text, scale=2):
        return max(0, 4 * scale * len(text) - scale)

    def write_png(self, path):
        raw = b"".join(b"\0" + bytes(self.rgb[y * self.width * 3:(y + 1) * self.width * 3]) for y in range(self.height))

        def chunk(kind, data):
            return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

        png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", self.width, self.height, 8, 2, 0, 0, 0)) +
               chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
        try:
            with open(path, "wb") as f:
                f.write(png)
        except OSError as e:
            fail(f"{path}: cannot write ({e.strerror})")


def heat_colour(t):
    """Blue (low) to yellow (high), through green: app/cmd_archive.cpp's scale."""
    t = min(1.0, max(0.0, t))
    return (int(40 + 215 * t * t), int(50 + 180 * t), int(150 * (1 - t) + 30))


def heatmap(args):
    grid = read_grid(args.grid_from)
    if len(grid) != 2:
        fail(f"{args.grid_from}: the heatmap needs exactly 2 descriptors, the grid has {len(grid)}")
    (yname, ylo, yhi, rows), (xname, xlo, xhi, cols) = grid
    panels = []
    for spec in args.runs:
        title, sep, run_dir = spec.partition("=")
        if not sep or not run_dir:
            fail(f"{spec!r}: expected TITLE=RUN_DIR")
        cells, best, _, _ = bin_run(run_dir, grid)
        panels.append((title, cells, best))
    values = [f for _, cells, _ in panels for f in cells.values()]
    lo, hi = (min(values), max(values)) if values else (0.0, 1.0)
    size = args.cell
    left, top, gap, bottom = 70, 64, 70, 110
    pw, ph = cols * size, rows * size
    canvas = Canvas(left + len(panels) * pw + (len(panels) - 1) * gap + 30, top + ph + bottom)
    total = rows * cols
    for k, (title, cells, best) in enumerate(panels):
        x0 = left + k * (pw + gap)
        canvas.text(x0, 8, title, 3)
        qd = sum(cells.values())
        canvas.text(x0, 34, f"{len(cells) / total:.1%} of cells, QD {qd:.0f}, best {best if best is None else round(best)}", 2)
        for r in range(rows):
            for c in range(cols):
                f = cells.get((r, c))
                colour = (225, 225, 225) if f is None else heat_colour((f - lo) / (hi - lo) if hi > lo else 1.0)
                canvas.rect(x0 + c * size, top + (rows - 1 - r) * size, size, size, colour)
        for r in range(rows + 1):
            canvas.rect(x0, top + min(r * size, ph - 1), pw, 1, (190, 190, 190))
        for c in range(cols + 1):
            canvas.rect(x0 + min(c * size, pw - 1), top, 1, ph, (190, 190, 190))
        # ticks: min, middle, max of each range
        for frac in (0.0, 0.5, 1.0):
            label = f"{ylo + frac * (yhi - ylo):g}"
            y = top + ph - int(frac * ph) - 5
            canvas.text(x0 - Canvas.text_width(label) - 6, min(max(y, top), top + ph - 10), label, 2, (40, 40, 40))
            label = f"{xlo + frac * (xhi - xlo):g}"
            x = x0 + int(frac * pw) - Canvas.text_width(label) // 2
            canvas.text(min(max(x, x0), x0 + pw - Canvas.text_width(label)), top + ph + 6, label, 2, (40, 40, 40))
        canvas.text(x0 + pw // 2 - Canvas.text_width(xname) // 2, top + ph + 24, xname, 2)
        if k == 0:
            canvas.text(4, top - 16, yname, 2)
    # the colour scale
    bar_x, bar_y, bar_w = left, top + ph + 56, min(400, canvas.width - left - 30)
    for i in range(bar_w):
        canvas.rect(bar_x + i, bar_y, 1, 14, heat_colour(i / max(1, bar_w - 1)))
    canvas.text(bar_x, bar_y + 20, f"best fitness per cell: {lo:.0f}", 2)
    label = f"{hi:.0f}"
    canvas.text(bar_x + bar_w - Canvas.text_width(label), bar_y + 20, label, 2)
    canvas.write_png(args.png)
    print(f"wrote {args.png}", file=sys.stderr)


def parents(args):
    print("| run | bred births | first parent within 10 % of the best so far |")
    print("|---|---|---|")
    for run_dir in args.runs:
        path = f"{run_dir}/lineage.csv"
        try:
            with open(path, newline="") as f:
                rows = list(csv.DictReader(f))
        except OSError as e:
            fail(f"{path}: {e.strerror}")
        fitness, best, bred, near = {}, None, 0, 0
        for row in rows:
            if row["parent1"]:
                bred += 1
                p = fitness.get(int(row["parent1"]))
                near += 1 if p is not None and best is not None and p >= 0.9 * best else 0
            if row["fitness"]:
                fitness[int(row["id"])] = float(row["fitness"])
                best = fitness[int(row["id"])] if best is None else max(best, fitness[int(row["id"])])
        print(f"| {run_dir} | {bred} | {near / bred if bred else 0:.1%} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    t = sub.add_parser("table", help="coverage, QD-score and best per run, as markdown")
    t.add_argument("--grid-from", required=True, help="a config whose `descriptors` give the grid")
    t.add_argument("--budget", type=int, default=0, help="warn about runs with another number of births")
    t.add_argument("--qd-offset", type=float, default=0.0, help="QD-score sums fitness minus this (default 0)")
    t.add_argument("--reference", default="ga", help="the method the ratios are against (default ga)")
    t.add_argument("runs", nargs="+", metavar="METHOD/SEED=RUN_DIR")
    h = sub.add_parser("heatmap", help="best fitness per cell of runs side by side, as a PNG")
    h.add_argument("--grid-from", required=True, help="a config whose `descriptors` give the grid (2 of them)")
    h.add_argument("--png", required=True)
    h.add_argument("--cell", type=int, default=16, help="pixels per cell (default 16)")
    h.add_argument("runs", nargs="+", metavar="TITLE=RUN_DIR")
    u = sub.add_parser("union", help="best fitness per cell over all the runs' births together")
    u.add_argument("--grid-from", required=True, help="a config whose `descriptors` give the grid")
    u.add_argument("--qd-offset", type=float, default=0.0, help="QD-score sums fitness minus this (default 0)")
    u.add_argument("runs", nargs="+", metavar="RUN_DIR")
    p = sub.add_parser("parents", help="how often a bred birth's first parent was near the best so far")
    p.add_argument("runs", nargs="+", metavar="RUN_DIR")
    args = parser.parse_args()
    {"table": table, "heatmap": heatmap, "union": union, "parents": parents}[args.command](args)


if __name__ == "__main__":
    main()
