#!/usr/bin/env python3
"""How busy T threads stay under a birth schedule (docs/algorithm.md §8.4),
simulated from measured evaluation times.

Usage: experiments/scripts/pipeline_efficiency.py SUMMARY.csv [--threads 2,16] [--population 100]
                                       [--births 4000] [--seed 1]

SUMMARY.csv is a `morphogen gallery --config ... --format none` summary: its
time_ms column is the measured cost of growing and scoring each genome. The
simulation draws births' costs from it at random and replays the run: a birth
is conceived when its source state is reached, queued FIFO to T threads, and
inserted in birth order (instantly: rank 0's and insertion's own costs are
left out). Efficiency = total evaluation time / (T x makespan): 1.0 means no
thread ever waited. It prints one row per schedule.
"""
import argparse
import csv
import heapq
import random


def source(kind, width, P, birth):
    if kind == "batch":
        start = birth - birth % P
        return start + (birth - start) // width * width
    if birth < P:
        return 0
    return max(birth + 1 - width, P)


def simulate(costs, kind, width, P, T):
    n = len(costs)
    ready_at = [0.0] * n           # when each birth's evaluation ends
    free = [0.0] * T               # heap of times threads become free
    heapq.heapify(free)
    inserted_at = [0.0] * (n + 1)  # time the state with k births exists
    next_birth = 0
    done_time = 0.0
    # Births are conceived in order; birth j can start once its source state exists.
    for k in range(n + 1):
        if k > 0:
            inserted_at[k] = max(inserted_at[k - 1], ready_at[k - 1])
        while next_birth < n and source(kind, width, P, next_birth) <= k:
            j = next_birth
            t_free = heapq.heappop(free)
            start = max(t_free, inserted_at[source(kind, width, P, j)])
            ready_at[j] = start + costs[j]
            heapq.heappush(free, ready_at[j])
            next_birth += 1
        done_time = inserted_at[k]
    return sum(costs) / (T * done_time)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("summary")
    ap.add_argument("--threads", default="2,16")
    ap.add_argument("--population", type=int, default=100)
    ap.add_argument("--births", type=int, default=4000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    times = [float(r["time_ms"]) for r in csv.DictReader(open(a.summary)) if r.get("time_ms")]
    rng = random.Random(a.seed)
    costs = [rng.choice(times) for _ in range(a.births)]
    threads = [int(t) for t in a.threads.split(",")]
    mean = sum(times) / len(times)
    print(f"{len(times)} measured evaluations, mean {mean:.1f} ms, max {max(times):.1f} ms "
          f"({max(times) / mean:.1f}x the mean)")
    print("| schedule | " + " | ".join(f"{t} threads" for t in threads) + " |")
    print("|---|" + "---|" * len(threads))
    for kind, width in [("batch", 32), ("batch", 128), ("batch", 512), ("pipeline", 16), ("pipeline", 32),
                        ("pipeline", 64), ("pipeline", 128), ("pipeline", 256)]:
        row = [simulate(costs, kind, width, a.population, t) for t in threads]
        name = f"batch {width}" if kind == "batch" else f"pipeline, lag {width}"
        print(f"| {name} | " + " | ".join(f"{e:.3f}" for e in row) + " |")


if __name__ == "__main__":
    main()
