"""Stubs per 11 children, from configs/tree.json, as a new user meets them:
the fittest plant of the first grid (or, with --from, the given genome) is
bred at strength 0.1, 0.3 and 0.5 and explored around (along the config's
descriptors and along the architecture); a child is a stub when it is
invalid or under half its parent's height.
Usage: measure_grids.py MORPHOGEN OUT_DIR [SEEDS...] [--births N] [--from GENOME]"""
import statistics
import sys

from breed_client import Breed, describe


def stubs(grid, parent_height):
    children = grid[1:]
    return sum(1 for p in children if p["fitness"] is None or p["measures"]["height"] < 0.5 * parent_height)


def main():
    morphogen, out = sys.argv[1], sys.argv[2]
    births = 200
    args = sys.argv[3:]
    if "--births" in args:
        i = args.index("--births")
        births = int(args[i + 1])
        del args[i:i + 2]
    start = []
    if "--from" in args:
        i = args.index("--from")
        start = ["--from", args[i + 1]]
        del args[i:i + 2]
    seeds = [int(s) for s in args] or [1, 2, 3]
    for seed in seeds:
        b = Breed(morphogen, ["configs/tree.json", "--out", "%s/seed%d" % (out, seed), "--threads", "2",
                              "--seed", str(seed), *start])
        grid = b.state()["grid"]
        parent = grid[0] if start else max((p for p in grid if p["fitness"] is not None), key=lambda p: p["fitness"])
        h = parent["measures"]["height"]
        print("seed %d parent %s" % (seed, describe(parent)), flush=True)
        for label, act in [("breed 0.1", lambda: b.breed([parent["id"]], 0.1)),
                           ("breed 0.3", lambda: b.breed([parent["id"]], 0.3)),
                           ("breed 0.5", lambda: b.breed([parent["id"]], 0.5)),
                           ("explore descriptors", lambda: b.explore([parent["id"]], births, "descriptors")),
                           ("explore architecture", lambda: b.explore([parent["id"]], births, "architecture"))]:
            g = act()["grid"]
            kids = g[1:]
            print("  %-21s stubs %2d of %d; limbs %s; first fork %s; slenderness median %.2f" % (
                label, stubs(g, h), len(kids),
                [int(p["measures"].get("limbs", 0)) for p in kids],
                ["%.2f" % p["measures"].get("first_fork", 1) for p in kids],
                statistics.median(p["measures"].get("slenderness", 0) for p in kids)), flush=True)
            b.call("POST", "/api/undo", {})
        b.close()


if __name__ == "__main__":
    main()
