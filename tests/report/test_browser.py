#!/usr/bin/env python3
"""End-to-end checks of `morphogen report` pages in headless Chromium (CTest
"report: browser"): a small GA run's report, a run with no exported meshes,
a MAP-Elites run (a click on a heatmap cell opens its elite in the viewer);
the GA report's growth viewer must play its animated glTF (grow --animate's).

usage: test_browser.py MORPHOGEN_EXE
Exit 0: passed; 1: failed; 77: skipped (no chromium)."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import check_report  # noqa: E402
from cdp import Browser  # noqa: E402

CONFIG = {
    "network": {"outputs": 4, "hidden": [5]},
    "growth": {"steps": 30, "max_vertices": 400},
    "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
    "evolution": {"population": 12, "batch": 4, "mutation_rate": 0.2},
    "run": {"seed": 5, "generations": 4, "export_every": 1},
}


def morphogen(exe, *args):
    result = subprocess.run([exe, *args], capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit(f"FAIL: morphogen {' '.join(args)} exited {result.returncode}: {result.stderr}")
    return result


def make_run(exe, tmp, name, config):
    path = os.path.join(tmp, name + ".json")
    with open(path, "w") as f:
        json.dump(config, f)
    run = os.path.join(tmp, name)
    morphogen(exe, "evolve", path, "--out", run, "--no-report", "--threads", "1")
    morphogen(exe, "report", run)
    return os.path.join(run, "report")


def check(report, *args):
    print(f"--- {report} {' '.join(args)}", flush=True)
    sys.argv = ["check_report.py", report, *args]
    return check_report.main()


def click_heatmap(chromium, report):
    """Clicks the first grown elite's cell; the viewer must then show it."""
    print(f"--- heatmap click in {report}", flush=True)
    browser = Browser(chromium, height=1100)
    try:
        browser.open_page()
        browser.send("Page.navigate", {"url": "file://" + os.path.abspath(os.path.join(report, "index.html"))})
        deadline = time.monotonic() + 30
        status = {}
        while time.monotonic() < deadline and status.get("viewer") in (None, "pending"):
            browser.pump(0.25)
            status = browser.evaluate("window.morphogenStatus || {}")
        target = status.get("heatmapTarget")
        if not target:
            print("FAIL: no grown elite on the heatmap")
            return 1
        browser.evaluate("document.getElementById('heatmap').scrollIntoView()")
        browser.pump(0.3)
        rect = browser.evaluate("(() => { const c = document.getElementById('heatmap'), r = c.getBoundingClientRect();"
                                " return {x: r.left, y: r.top, sx: r.width / c.width, sy: r.height / c.height}; })()")
        x, y = rect["x"] + target["x"] * rect["sx"], rect["y"] + target["y"] * rect["sy"]
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            browser.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1})
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and status.get("shown") != target["key"]:
            browser.pump(0.25)
            status = browser.evaluate("window.morphogenStatus")
        problems = browser.problems()
    finally:
        browser.close()
    if status.get("shown") != target["key"] or problems:
        print(f"FAIL: after clicking {target['key']} the viewer shows {status.get('shown')!r}; problems: {problems}")
        return 1
    print(f"OK: clicking {target['key']} opened it in the viewer")
    return 0


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    exe = os.path.abspath(sys.argv[1])
    chromium = os.environ.get("MORPHOGEN_CHROMIUM") or shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIPPED: chromium is not installed (Debian package chromium; scripts/setup.sh installs it)")
        return check_report.SKIP
    failed = 0
    with tempfile.TemporaryDirectory(prefix="morphogen_report_browser_") as tmp:
        report = make_run(exe, tmp, "ga", CONFIG)
        failed += check(report, "--expect-viewer", "shown", "--expect-growth", "playing") != 0

        os.environ["MORPHOGEN_THREE_DIR"] = os.path.join(tmp, "no-three")  # three.js not installed
        failed += check(make_run(exe, tmp, "nothree", CONFIG), "--expect-viewer", "none", "--expect-growth", "none") != 0
        del os.environ["MORPHOGEN_THREE_DIR"]

        no_meshes = dict(CONFIG, run=dict(CONFIG["run"], export_every=0))
        failed += check(make_run(exe, tmp, "nomesh", no_meshes), "--expect-viewer", "shown") != 0

        elites = dict(CONFIG, evolution=dict(CONFIG["evolution"], algorithm="map_elites"),
                      descriptors=[{"measure": "height", "min": 0, "max": 3, "bins": 6},
                                   {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
                      archive={"type": "grid", "qd_offset": -1})
        elite_report = make_run(exe, tmp, "elites", elites)
        failed += check(elite_report, "--expect-viewer", "shown", "--expect-heatmap") != 0
        failed += click_heatmap(chromium, elite_report) != 0

        cvt = dict(elites, descriptors=[{"measure": "height", "min": 0, "max": 3},
                                        {"measure": "footprint", "min": 0, "max": 10}],
                   archive={"type": "cvt", "cells": 16})
        failed += check(make_run(exe, tmp, "cvt", cvt), "--expect-viewer", "shown", "--expect-heatmap") != 0
    print("FAILED" if failed else "PASSED", f"({failed} failing)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
