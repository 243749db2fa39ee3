#!/usr/bin/env python3
"""Loads a morphogen report from file:// in headless Chromium (Debian
`chromium`, driven over its DevTools pipe with python3's standard library) and
checks what a person would see: no console errors or failed loads, the plots,
a 3-D viewer canvas that is not blank in a screenshot, and optionally the
growth animation playing and the archive heatmap.

usage: check_report.py REPORT_DIR [--expect-viewer shown|none] [--expect-growth playing|none]
                       [--expect-heatmap] [--screenshot PNG] [--chromium PATH]
Exit 0: all checks passed; 1: a check failed (each failure printed);
77: chromium is absent (CTest counts it as skipped)."""
import argparse
import base64
import os
import shutil
import struct
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cdp import Browser  # noqa: E402

SKIP = 77


def decode_png(data):
    """8-bit RGB(A) non-interlaced PNG (what Chromium writes) -> (width, height, channels, rows)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, "unexpected PNG layout"
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def canvas_pixels(browser, selector):
    """Screenshot of an element: (distinct colours, share of pixels unlike the most common colour)."""
    browser.evaluate(f"document.querySelector('{selector}').scrollIntoView()")
    rect = browser.evaluate(f"(() => {{ const r = document.querySelector('{selector}').getBoundingClientRect();"
                            " return {x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width, height: r.height}; })()")
    browser.pump(0.3)  # a frame drawn where it now is
    shot = browser.send("Page.captureScreenshot", {"format": "png", "clip": dict(rect, scale=1)})
    png = base64.b64decode(shot["data"])
    width, height, channels, rows = decode_png(png)
    counts = {}
    for line in rows:
        for x in range(0, width * channels, channels):
            key = bytes(line[x:x + 3])
            counts[key] = counts.get(key, 0) + 1
    background = max(counts.values())
    return len(counts), 1 - background / (width * height), png


def save(path, png):
    if path:
        with open(path, "wb") as f:
            f.write(png)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("report")
    parser.add_argument("--expect-viewer", default="shown")
    parser.add_argument("--expect-growth", default=None)
    parser.add_argument("--expect-heatmap", action="store_true")
    parser.add_argument("--screenshot", help="PNG of the page's top")
    parser.add_argument("--viewer-shot", help="PNG of the viewer canvas")
    parser.add_argument("--chromium", default=os.environ.get("MORPHOGEN_CHROMIUM", ""))
    args = parser.parse_args()
    chromium = args.chromium or shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIPPED: chromium is not installed (Debian package chromium; scripts/setup.sh installs it)")
        return SKIP
    index = os.path.abspath(os.path.join(args.report, "index.html"))
    if not os.path.isfile(index):
        print(f"FAIL: {index} does not exist")
        return 1

    failures = []
    browser = Browser(chromium, height=1100)
    try:
        browser.open_page()
        browser.send("Page.navigate", {"url": "file://" + index})
        # Wait for the page to settle: the viewer and the growth leave 'pending'.
        deadline = time.monotonic() + 30
        state = {}
        while time.monotonic() < deadline:
            browser.pump(0.25)
            state = browser.evaluate("window.morphogenStatus || null") or {}
            if state and state.get("viewer") != "pending" and state.get("growth") != "pending":
                break
            if (state and state.get("errors")) or browser.problems():
                break
        browser.pump(0.5)  # a few frames drawn
        print("page status:", state)
        if not state:
            failures.append("report.js did not run (no window.morphogenStatus)")
        for problem in browser.problems():
            failures.append(problem)
        for error in state.get("errors", []):
            failures.append("section failed: " + error)
        charts = browser.evaluate("document.querySelectorAll('#plot-grid canvas.chart').length")
        if state.get("plots", 0) < 4 or charts < 4:
            failures.append(f"expected at least 4 plots, found {charts}")
        if state.get("viewer") != args.expect_viewer:
            failures.append(f"viewer is {state.get('viewer')!r}, expected {args.expect_viewer!r}")
        if args.expect_viewer == "shown":
            colours, covered, png = canvas_pixels(browser, "#viewer")
            save(args.viewer_shot, png)
            print(f"viewer canvas: {colours} colours, {covered:.1%} of pixels not background")
            if colours < 20 or covered < 0.01:
                failures.append(f"the viewer canvas looks blank ({colours} colours, {covered:.2%} covered)")
        if args.expect_growth and state.get("growth") != args.expect_growth:
            failures.append(f"growth is {state.get('growth')!r}, expected {args.expect_growth!r}")
        if args.expect_growth == "playing":
            colours, covered, _ = canvas_pixels(browser, "#growth")
            print(f"growth canvas: {colours} colours, {covered:.1%} covered")
            if colours < 20 or covered < 0.005:
                failures.append("the growth canvas looks blank")
            start = browser.evaluate("window.morphogenStatus.growthTime || 0")
            browser.pump(1.0)
            later = browser.evaluate("window.morphogenStatus.growthTime || 0")
            print(f"growth animation time: {start:.2f} s, a second later {later:.2f} s")
            if not later > start:
                failures.append("the growth animation does not advance")
        if args.expect_heatmap:
            if not state.get("heatmap"):
                failures.append("no heatmap cells drawn")
        if args.screenshot:
            browser.evaluate("window.scrollTo(0, 0)")
            shot = browser.send("Page.captureScreenshot", {"format": "png"})
            with open(args.screenshot, "wb") as f:
                f.write(base64.b64decode(shot["data"]))
    finally:
        browser.close()
    for f in failures:
        print("FAIL:", f)
    if not failures:
        print(f"OK: no console errors or failed loads; plots; viewer {args.expect_viewer}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
