#!/usr/bin/env python3
"""CMA-ME on the sphere linear-projection benchmark, run by the papers' own code.

The CMA-MAE authors' repository (github.com/icaros-usc/cma_mae) vendors the
pyribs 0.4 that produced the published QD-scores (experiments/
2026-11-24-emitters-sphere-benchmark.md). This script runs its CMA-ME setting
(15 ImprovementEmitters, batch 36, sigma0 0.5, x0 = 0, "mu" parents, "basic"
restarts, a 100 x 100 grid over [-256, 256]^2, a passive elitist archive for
the QD-score) with the benchmark of docs/algorithm.md section 9.10, so that
`build/morphogen-bench-qd --covariance pyribs` can be compared with the code it
imitates. It needs numpy (Debian: python3-numpy, run with /usr/bin/python3)
and a checkout of that repository; the repository's other dependencies
(numba, pandas, scipy, ...) are replaced by stand-ins that run its code as
plain Python, so a run of 10,000 iterations takes some 8 minutes.

usage: /usr/bin/python3 experiments/scripts/pyribs_sphere.py CMA_MAE_CHECKOUT [--iterations N] [--seeds S...]
prints one line per 1,000 iterations and per seed: QD-score (sum of the
elites' objectives / 10,000 cells), coverage in percent, restarts.
"""
import argparse
import os
import sys
import tempfile
import time


def write_stand_ins(folder):
    """Modules the vendored ribs imports but CMA-ME on a grid never uses (or,
    for numba, uses only to compile): plain-Python replacements."""
    files = {
        "numba.py": (
            "def jit(*args, **kwargs):\n"
            "    if len(args) == 1 and callable(args[0]) and not kwargs:\n"
            "        return args[0]\n"
            "    return lambda f: f\n"
            "njit = jit\n"
            "class _Types:\n"
            "    b1 = bool\n"
            "    def __getattr__(self, name):\n"
            "        return object\n"
            "types = _Types()\n"),
        "decorator.py": (
            "import functools\n"
            "def decorator(caller):\n"
            "    def deco(func):\n"
            "        @functools.wraps(func)\n"
            "        def wrapper(*a, **k):\n"
            "            return caller(func, *a, **k)\n"
            "        return wrapper\n"
            "    return deco\n"),
        "threadpoolctl.py": (
            "import contextlib\n"
            "@contextlib.contextmanager\n"
            "def threadpool_limits(*a, **k):\n"
            "    yield\n"),
        "pandas.py": "DataFrame = None\n",
        "toml.py": "",
        "sortedcontainers.py": "SortedList = None\n",
        "scipy/__init__.py": "",
        "scipy/spatial.py": "cKDTree = None\n",
        "sklearn/__init__.py": "",
        "sklearn/cluster.py": "k_means = None\n",
    }
    for name, text in files.items():
        path = os.path.join(folder, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)


def sphere(np, x):
    """algorithm.md 9.10: 100 (s - w) / (0 - w), s = sum (x_i - 2.048)^2."""
    n = x.shape[1]
    worst = n * (-5.12 - 2.048) ** 2
    return (np.sum(np.square(x - 2.048), axis=1) - worst) / (0.0 - worst) * 100.0


def measures(np, x):
    """The sums of clip(x_i) over each half; clip(x) = x inside [-5.12, 5.12], else 5.12 / x."""
    n = x.shape[1]
    with np.errstate(divide="ignore"):  # x0 = 0: 5.12 / 0 is computed, never used
        c = np.where(np.abs(x) <= 5.12, x, 5.12 / x)
    return np.stack((c[:, :n // 2].sum(axis=1), c[:, n // 2:].sum(axis=1)), axis=1)


def run(np, ribs, iterations, seed):
    n, cells = 100, 100
    bound = n / 2 * 5.12
    bounds = [(-bound, bound), (-bound, bound)]
    archive = ribs.archives.GridArchive((cells, cells), bounds, seed=seed)
    passive = ribs.archives.GridArchive((cells, cells), bounds, seed=seed)
    passive.initialize(n)
    emitters = [ribs.emitters.ImprovementEmitter(archive, np.zeros(n), 0.5, restart_rule="basic",
                                                 selection_rule="mu", batch_size=36, seed=s)
                for s in range(seed, seed + 15)]
    optimizer = ribs.optimizers.Optimizer(archive, emitters)
    start = time.time()
    for it in range(1, iterations + 1):
        x = optimizer.ask()
        f, m = sphere(np, x), measures(np, x)
        optimizer.tell(f, m)
        for k in range(len(x)):
            passive.add(x[k], f[k], m[k])
        if it % 1000 == 0 or it == iterations:
            objectives = passive.data()[1]
            print(f"seed {seed} iteration {it}: QD-score {sum(objectives) / cells**2:.2f}, "
                  f"coverage {100.0 * len(objectives) / cells**2:.2f} %, "
                  f"restarts {sum(e._restarts for e in emitters)}, {time.time() - start:.0f} s", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("checkout", help="a checkout of github.com/icaros-usc/cma_mae")
    parser.add_argument("--iterations", type=int, default=10000)
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    args = parser.parse_args()
    try:
        import numpy as np
    except ImportError:
        sys.exit("pyribs_sphere.py: needs numpy (apt install python3-numpy; run with /usr/bin/python3)")
    if not os.path.isdir(os.path.join(args.checkout, "ribs")):
        sys.exit(f"pyribs_sphere.py: {args.checkout}: no ribs/ folder (not a checkout of icaros-usc/cma_mae)")
    with tempfile.TemporaryDirectory() as stand_ins:
        write_stand_ins(stand_ins)
        sys.path[:0] = [stand_ins, args.checkout]
        import ribs  # noqa: E402  (the checkout's, after the stand-ins)
        import ribs.archives, ribs.emitters, ribs.optimizers  # noqa: E401,E402
        for seed in args.seeds:
            run(np, ribs, args.iterations, seed)


if __name__ == "__main__":
    main()
