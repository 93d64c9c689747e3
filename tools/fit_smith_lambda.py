#!/usr/bin/env python3
"""Chebyshev coefficients of the float Smith Lambda(t) in shaders/lib/gaussian_masking.glsl.

Lambda(t) = m_1(-t)/t = phi(t) k(t)/t with k(t) = 1 - t Q(t)/phi(t) (Q: the upper normal tail), so k(0) = 1
and k(t) ~ 1/t^2 - 3/t^4 + ... for large t. f(t) = k(t) (9 + t^2) runs from 9 to 1 and is fitted by a
Chebyshev series in u = (t - 3)/(t + 3) = 1 - 6/(t + 3), which maps t in [0, inf) onto [-1, 1)
(docs/masking.md, "Lambda in float"). The reference k is computed in double: from erfc up to t = 30 (its
cancellation, about t^2 eps, stays below 1e-13 there), from the asymptotic series beyond. Prints the
coefficients c_0 ... c_13 and the fit's worst relative error of f over t in [1e-6, 1e4].

Usage: python3 tools/fit_smith_lambda.py   (needs numpy)
"""
import math

import numpy as np
from numpy.polynomial import chebyshev

DEGREE = 13
SCALE = 3.0


def k(t):
    if t > 30:
        total, term = 0.0, 1 / t**2
        for n in range(10):
            total += term
            term *= -(2 * n + 3) / t**2
        return total
    tail = math.erfc(t / math.sqrt(2)) / 2
    pdf = math.exp(-t * t / 2) / math.sqrt(2 * math.pi)
    return (pdf - t * tail) / pdf


def f(t):
    return k(t) * (SCALE * SCALE + t * t)


def main():
    nodes = 600
    u = np.cos(np.pi * (np.arange(nodes) + 0.5) / nodes)
    t = SCALE * (1 + u) / (1 - u)
    coefficients = chebyshev.chebfit(u, np.array([f(x) for x in t]), DEGREE)
    check = np.concatenate([np.geomspace(1e-6, SCALE, 3000), np.geomspace(SCALE, 1e4, 6000)])
    fitted = chebyshev.chebval(1 - 2 * SCALE / (check + SCALE), coefficients)
    worst = max(abs(fitted[i] / f(x) - 1) for i, x in enumerate(check))
    for i, c in enumerate(coefficients):
        print(f"c_{i} = {c!r}")
    print(f"worst relative error of f: {worst:.2e}")


if __name__ == "__main__":
    main()
