#!/usr/bin/env python3
"""Reference values of the exact one-term rolling-contact solution (src/contact/exact.rs) in high
precision with mpmath, written to tests/data/exact_one_term_reference.csv.

Evaluates the closed forms D4-D5 of src/contact/exact.rs with mpmath's own Bessel functions
(besseli) and tanh-sinh quadrature at 30 digits, so the table checks the double-precision
implementation (Miller recurrence, cancellation-free forms, adaptive Gauss-Legendre) independently.
The derivation itself is checked separately by the eq. 3.25 residual test (direct quadrature of the
integral equation, src/contact/exact_tests.rs).

The solution depends only on r = f/b and b*lambda (lengths scale with lambda), so the grid is over
those with lambda = 1. Run once (tens of minutes):
    python3 tools/gen_exact_reference.py > tests/data/exact_one_term_reference.csv
"""
import sys
import mpmath
from mpmath import mp, mpf, besseli, exp, expm1, sinh, asinh, quad, sqrt

mp.dps = 30


def solve(f, b, lam):
    f, b, lam = mpf(f), mpf(b), mpf(lam)
    k = b + f
    c = k * lam / 2
    p = b * lam / 2
    ib = [besseli(0, c) * exp(-c)]
    n = 0
    while True:
        n += 1
        v = besseli(n, c) * exp(-c)
        ib.append(v)
        if v < mpf("1e-32") * ib[0]:
            break
    U = 2 * asinh(sqrt(80 / p))
    br = sorted(set([mpf(0), U] + [x for x in [1 / sqrt(c) / 4, 1 / sqrt(c), 4 / sqrt(c),
                                                 1 / sqrt(p) / 4, 1 / sqrt(p), mpf(1), mpf(4)] if x < U]))
    W = lambda u: exp(-2 * p * sinh(u / 2) ** 2) * sinh(u)

    def S(u):
        w = exp(-u)
        acc = mpf(0)
        for v in reversed(ib[1:]):
            acc = acc * w + v
        return acc * w

    pM1 = p * quad(lambda u: W(u) * exp(-u), br)
    pP = p * quad(lambda u: W(u) * (-expm1(-u)), br)
    Sig = quad(lambda u: W(u) * S(u), br)
    E = 1 - (1 + c) * ib[0]
    D = 1 + (f / b) * ib[0] + f * lam * Sig
    A = (f / k) * (1 / b + (lam / 2) * pP) / D
    hmb = (f / (k * b * D)) * (E + c * ib[0] * pM1 + f * lam * Sig)
    beta = lam / 2 - hmb
    h1 = b * lam / (2 * k) + 2 * A * ib[1]
    h2 = 2 * A * ib[2] if len(ib) > 2 else mpf(0)
    load = lam * h1 / 2
    fr = hmb + (lam / 4) * h2 / h1
    return beta, load, fr


def main():
    ratios = ["1e-3", "1e-1", "1", "10", "1e3"]
    blams = ["1e-4", "1e-2", "1", "1e2", "1e4"]
    grid = [(r, bl) for r in ratios for bl in blams if (1 + mpf(r)) * mpf(bl) <= 2e4]
    # The corners of kappa*lambda = 1e4 at the large ratios.
    grid += [("1e3", "10"), ("10", "1e3")]
    if "--extra-only" in sys.argv:
        grid = grid[-2:]
    else:
        print("# f,b,lambda,beta,load,friction_rho  (mpmath %s, %d digits; tools/gen_exact_reference.py)"
              % (mpmath.__version__, mp.dps))
    for r, bl in grid:
        b = mpf(bl)
        f = mpf(r) * b
        beta, load, fr = solve(f, b, 1)
        print("%s,%s,1,%s,%s,%s" % (mp.nstr(f, 17), mp.nstr(b, 17), mp.nstr(beta, 22),
                                     mp.nstr(load, 22), mp.nstr(fr, 22)), flush=True)


if __name__ == "__main__":
    main()
