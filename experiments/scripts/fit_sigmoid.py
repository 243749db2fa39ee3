#!/usr/bin/env python3
"""Fits the rational 2^y of the network kernel's sigmoid (core/growth/network/network_kernel.cpp).

usage: experiments/scripts/fit_sigmoid.py        (needs mpmath: Debian's python3-mpmath)

2^y = (q + p) / (q - p) on |y| <= 1/2, with p = y (d0 + d1 x + d2 x^2) and
q = c0 + c1 x + x^2, x = y^2: equivalently p / q = tanh(y ln2 / 2), which is
what is fitted, for the least maximum absolute error (a relative error of
about twice that in 2^y). Lawson's iteration on Loeb's linearisation, in
60-digit arithmetic on 1200 Chebyshev points; prints the coefficients and
the error reached (8.3e-19 relative in 2^y: below a double's rounding).
"""
import mpmath as mp

mp.mp.dps = 60
HALF = mp.mpf(1) / 2
POINTS = 1200
ys = [HALF * (1 + mp.cos(mp.pi * (2 * i + 1) / (2 * POINTS))) / 2 for i in range(POINTS)]
xs = [y * y for y in ys]
target = [mp.tanh(y * mp.log(2) / 2) / y for y in ys]  # p / q / y, an even function
P_TERMS, Q_TERMS = 3, 2  # d0..d2; c0, c1 (q is monic)

weights = [mp.mpf(1) / POINTS] * POINTS
q_previous = [mp.mpf(1)] * POINTS
best = None
for _ in range(80):
    n = P_TERMS + Q_TERMS
    a, b = mp.matrix(POINTS, n), mp.matrix(POINTS, 1)
    for i, (y, x, f) in enumerate(zip(ys, xs, target)):
        k = mp.sqrt(weights[i]) * y / q_previous[i]
        for j in range(P_TERMS):
            a[i, j] = k * x**j
        for j in range(Q_TERMS):
            a[i, P_TERMS + j] = -k * f * x**j
        b[i] = k * f * x**Q_TERMS
    solution = mp.lu_solve(a.T * a, a.T * b)
    d = [solution[j] for j in range(P_TERMS)]
    c = [solution[P_TERMS + j] for j in range(Q_TERMS)] + [mp.mpf(1)]
    q = [mp.polyval(c[::-1], x) for x in xs]
    error = [y * (mp.polyval(d[::-1], x) / qi - f) for y, x, f, qi in zip(ys, xs, target, q)]
    worst = max(abs(e) for e in error)
    if best is None or worst < best[0]:
        best = (worst, d, c)
    q_previous = q
    weights = [w * abs(e) for w, e in zip(weights, error)]
    total = mp.fsum(weights)
    weights = [w / total for w in weights]

worst, d, c = best
for name, value in [("d0", d[0]), ("d1", d[1]), ("d2", d[2]), ("c0", c[0]), ("c1", c[1])]:
    print(f"{name} = {mp.nstr(value, 22)}")
print(f"max |p/q - tanh(y ln2 / 2)| = {mp.nstr(worst, 3)}, relative error of 2^y about {mp.nstr(2 * worst, 3)}")
