#!/usr/bin/env python3
"""Compares two run directories byte for byte, apart from what a clock or the
config's format writes: history rows' births_per_s and elapsed_s, the
checkpoint's elapsed_s and its resolved config, log.txt and config.json.
Usage: compare_runs.py DIR_A DIR_B   (exit 0 when equal, 1 with the differences)"""
import json, pathlib, sys

CLOCK_COLUMNS = {"births_per_s", "elapsed_s"}


def history(path):
    lines = path.read_text().splitlines()
    header = lines[0].split(",")
    keep = [i for i, name in enumerate(header) if name not in CLOCK_COLUMNS]
    return [[row.split(",")[i] for i in keep] for row in lines]


def checkpoint(path):
    header, _, genomes = path.read_bytes().partition(b"\n")
    content = json.loads(header)["content"]
    content.pop("config", None)
    content.pop("elapsed_s", None)
    for row in content.get("history", []):
        for key in CLOCK_COLUMNS:
            row.pop(key, None)
    return content, genomes


def compare(a, b):
    problems = []
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.is_file()}
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.is_file()}
    skip = {pathlib.Path("log.txt"), pathlib.Path("config.json"), pathlib.Path("run.lock")}
    for name in sorted((files_a | files_b) - skip):
        if name.parts[0] == "report":
            continue
        if name not in files_a or name not in files_b:
            problems.append(f"{name}: only in {'A' if name in files_a else 'B'}")
        elif name.name == "history.csv":
            if history(a / name) != history(b / name):
                problems.append(f"{name}: rows differ")
        elif name.name == "checkpoint.json":
            if checkpoint(a / name) != checkpoint(b / name):
                problems.append(f"{name}: content differs")
        elif (a / name).read_bytes() != (b / name).read_bytes():
            problems.append(f"{name}: bytes differ")
    return problems


if __name__ == "__main__":
    problems = compare(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]))
    for p in problems:
        print(p)
    sys.exit(1 if problems else 0)
