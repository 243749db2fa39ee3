"""examples/bred-tree: the session replays byte for byte, its final plant is
the shipped genome, in at most 40 choices, and `score --json` measures that
genome, at the session's settings, as the example's README says (the
session's measures agree with it).

    python3 tests/breed/bred_tree_example.py MORPHOGEN_EXE SOURCE_DIR [--genome-only]

--genome-only checks the shipped genome's measures and the number of choices
without the replay (seconds, not minutes: the suite runs this part).
"""
import json
import os
import subprocess
import sys
import tempfile

# What the README promises of the genome (docs/fitness-measures.md).
MIN_LIMBS = 3
MAX_FIRST_FORK = 0.6  # the first fork's height over the plant's


def fail(what):
    print("FAILED: " + what)
    sys.exit(1)


def check(ok, what):
    if not ok:
        fail(what)
    print("ok - " + what)


def check_genome(exe, config, genome_path):
    """The shipped genome is a tree by the numbers at the settings it was bred
    under (the session's config); returns score's report."""
    score = subprocess.run([exe, "score", "--json", "--config", config, "--genome", genome_path],
                           capture_output=True, text=True)
    check(score.returncode == 0, "score --json reads the genome")
    report = json.loads(score.stdout)
    a = report["architecture"]
    check(a["limbs"] >= MIN_LIMBS, "%d limbs (at least %d)" % (a["limbs"], MIN_LIMBS))
    fork = a["first_fork_height"] / report["height"]
    check(fork < MAX_FIRST_FORK, "the first fork at %.2f of the height (below %.2f)" % (fork, MAX_FIRST_FORK))
    check(report["fitness_valid"] and report["self_intersecting"] is False, "clean: valid, no self-intersection")
    return report


def main():
    exe, source, name = sys.argv[1], sys.argv[2], sys.argv[3]
    genome_only = sys.argv[4:] == ["--genome-only"]
    example = os.path.join(source, "examples", name)
    session = os.path.join(example, "session")
    with open(os.path.join(example, "tree.genome.json"), "rb") as f:
        genome = f.read()
    with open(os.path.join(session, "choices.jsonl"), "rb") as f:
        choices = f.read()
    lines = choices.decode().splitlines()
    start = json.loads(lines[0])
    check(start["choice"] == "start" and len(lines) - 1 <= 40,
          "the session starts (from %s) and makes %d choices (at most 40)" %
          (start["from"] or "configs/tree.json's random grid", len(lines) - 1))
    report = check_genome(exe, os.path.join(session, "config.json"), os.path.join(example, "tree.genome.json"))
    if genome_only:
        print("passed")
        return
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "replayed")
        run = subprocess.run([exe, "breed", "--replay", session, "--out", out, "--threads", "2"],
                             capture_output=True, text=True)
        check(run.returncode == 0, "breed --replay exits 0 (%s)" % run.stderr.strip())
        with open(os.path.join(out, "choices.jsonl"), "rb") as f:
            check(f.read() == choices, "the replay writes the same choices.jsonl, byte for byte")
        with open(os.path.join(out, "state.json")) as f:
            state = json.load(f)
        grid = state["steps"][state["cursor"]]["grid"]
        same = []
        for pid in grid:
            with open(os.path.join(out, "genomes", pid + ".genome.json"), "rb") as f:
                if f.read() == genome:
                    same.append(pid)
        check(len(same) == 1, "the final grid holds tree.genome.json byte for byte (%s)" % same)
        plant = next(p for p in state["plants"] if p["id"] == same[0])
        measures = plant["measures"]
    a = report["architecture"]
    check([measures["tips"], measures["limbs"]] == [a["tips"], a["limbs"]] and
          abs(measures["first_fork_height"] - a["first_fork_height"]) <= 1e-9 * max(1.0, a["first_fork_height"]),
          "the session's tips, limbs and first fork are score's (%d, %d, %.3f)" %
          (a["tips"], a["limbs"], a["first_fork_height"]))
    print("passed")


if __name__ == "__main__":
    main()
