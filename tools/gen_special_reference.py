#!/usr/bin/env python3
"""Generate tests/data/special_reference.csv: high-precision values of the exponential integrals and
of the contact-kernel bracket h and its antiderivatives H1, H2 (src/special/, docs/MATH.md §2).

Run once from the repository root:  python3 tools/gen_special_reference.py
Needs mpmath (pip install mpmath). The CSV is committed; the Rust tests read it, CI needs no Python.

Columns: function, x, value. x is always an exact double (written with repr, 17 digits); value is
printed with 25 significant digits. Functions:
  e1       E1(x)                      x > 0
  exp_e1   e^x E1(x)                  x > 0
  ei       Ei(x)                      x != 0
  expm_ei  e^-x Ei(x)                 x != 0
  h        h(x) = ln|x| + gamma + g(x), g = e^x E1(x) (x > 0), -e^x Ei(-x) (x < 0)
  h1       H1(x) = int_0^x h
  h2       H2(x) = int_0^x H1
The h-family uses the closed forms h = L + g, H1 = x(L-1) + h, H2 = (x^2/2)(L-3/2) + H1
(L = gamma + ln|x|) at 120 digits, enough for the >40 digits they lose to cancellation at |x| = 1e-12;
the script cross-checks them against direct quadrature of the definitions
h(x) = int_0^inf e^-z ln|1 + x/z| dz, H1 = int_0^x h, H2 = int_0^x (x - t) h(t) dt at sample points.
"""
import math
import os
import sys

import mpmath as mp

mp.mp.dps = 120
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
OUT = os.path.join(ROOT, "tests", "data", "special_reference.csv")
OUT_TAYLOR = os.path.join(ROOT, "src", "special", "kernel_taylor.rs")
# Taylor pieces of h, H1, H2 on the negative axis, where both the series about 0 and the closed form
# are differences of O(1) pieces: (function, centre, from, to). Centre None = the function's zero
# (so the expansion has no constant term and keeps full relative accuracy there). Each window keeps
# |x - c|/|c| <= 0.42 (the radius of convergence is |c|, singularity at 0): 0.42^48 < 1e-18.
TAYLOR_TERMS = 48
TAYLOR_PIECES = [
    ("h", None, -1.467, -0.75),
    ("h", -2.2, -2.9, -1.467),
    ("h", -3.9, -4.9, -2.9),
    ("h1", -1.05, -1.35, -0.75),
    ("h1", None, -2.9, -1.35),
    ("h1", -3.9, -4.9, -2.9),
    ("h2", -1.0, -1.3, -0.75),
    ("h2", -1.7, -2.06, -1.3),
    ("h2", None, -4.1, -2.06),
    ("h2", -5.0, -6.0, -4.1),
]


def g(x):
    x = mp.mpf(x)
    return mp.exp(x) * mp.e1(x) if x > 0 else -mp.exp(x) * mp.ei(-x)


def L(x):
    return mp.euler + mp.log(abs(mp.mpf(x)))


def h0(x):
    return L(x) + g(x)


def h1(x):
    x = mp.mpf(x)
    return x * (L(x) - 1) + h0(x)


def h2(x):
    x = mp.mpf(x)
    return x * x / 2 * (L(x) - mp.mpf(3) / 2) + h1(x)


FUNCS = {
    "e1": lambda x: mp.e1(mp.mpf(x)),
    "exp_e1": lambda x: mp.exp(mp.mpf(x)) * mp.e1(mp.mpf(x)),
    "ei": lambda x: mp.ei(mp.mpf(x)),
    "expm_ei": lambda x: mp.exp(-mp.mpf(x)) * mp.ei(mp.mpf(x)),
    "h": h0,
    "h1": h1,
    "h2": h2,
}


def cross_check():
    """Closed forms against quadrature of the definitions (independent route), 30 digits."""
    with mp.workdps(30):
        for x in [-7.5, -3.0622717882277281, -2.0, -1.1673029191452993, -0.3, -1e-3, 1e-3, 0.3, 1.5, 4.0, 20.0]:
            x = mp.mpf(x)
            pts = [0, -x, mp.inf] if x < 0 else [0, mp.inf]
            hq = mp.quad(lambda z: mp.exp(-z) * mp.log(abs(1 + x / z)), pts)
            hq_of = lambda t: mp.quad(lambda z: mp.exp(-z) * mp.log(abs(1 + t / z)), [0, -t, mp.inf] if t < 0 else [0, mp.inf])
            h1q = mp.quad(hq_of, [0, x])
            h2q = mp.quad(lambda t: (x - t) * hq_of(t), [0, x])
            for name, q, c in (("h", hq, h0(x)), ("h1", h1q, h1(x)), ("h2", h2q, h2(x))):
                scale = 1 + abs(q)
                if abs(q - c) > mp.mpf("1e-20") * scale:
                    sys.exit(f"cross-check failed: {name}({x}) quad {q} closed {c}")
    # Series about 0 (independent of E1/Ei) against closed forms at small x.
    for x in ["1e-9", "-1e-9", "0.01", "-0.01", "0.7", "-0.7"]:
        x = mp.mpf(x)
        for m, f in ((0, h0), (1, h1), (2, h2)):
            s, hn, n = mp.mpf(0), mp.mpf(0), 0
            lx = L(x)
            while True:
                n += 1
                hn += mp.mpf(1) / n
                if n <= m:
                    continue
                t = x ** n / mp.factorial(n) * (hn - lx)
                s += t
                if n > 10 and abs(t) < mp.mpf(10) ** (-100) * abs(s):
                    break
            if abs(s - f(x)) > mp.mpf(10) ** (-60) * abs(s):
                sys.exit(f"series check failed m={m} x={x}")


def g_derivative(c, j):
    """g^(j)(c) for c = -y < 0, from g' = g - 1/x:  g^(j+1) = g^(j) + j!/y^(j+1)."""
    y = -c
    val = g(c)
    for i in range(j):
        val += mp.factorial(i) / y ** (i + 1)
    return val


def taylor_coefficients(name, c):
    """a_k = F^(k)(c)/k!, k = 0..TAYLOR_TERMS, of F = h (m=0), H1 (m=1), H2 (m=2) about c < 0."""
    m = {"h": 0, "h1": 1, "h2": 2}[name]
    lower = [h0, h1, h2]  # F^(k) for k <= m is the (m-k)-th antiderivative
    coeffs = []
    for k in range(0, TAYLOR_TERMS + 1):
        if k <= m:
            d = lower[m - k](c)
        else:
            d = g_derivative(c, k - m - 1)
        coeffs.append(d / mp.factorial(k))
    # Independent check of the derivative recursion by numerical differentiation of the closed form.
    with mp.workdps(60):
        for k in (1, 2, 3, 4, 7):
            num = mp.diff(lower[m], c, k) / mp.factorial(k)
            if abs(num - coeffs[k]) > mp.mpf("1e-40") * (1 + abs(num)):
                sys.exit(f"Taylor coefficient check failed: {name} k={k}")
    return coeffs


def write_taylor_pieces(zeros):
    lines = [
        "//! Taylor pieces of the kernel bracket h and its antiderivatives H1, H2 on the negative axis",
        "//! (generated by tools/gen_special_reference.py with mpmath at 120 digits; do not edit).",
        "//!",
        "//! Input: none (constants); used by kernel_bracket.rs where the series about 0 and the closed",
        "//! forms both cancel (-6 < x < -0.75), and for relative accuracy next to the negative zeros.",
        "//! Coefficients a_k = F^(k)(c)/k! from h' = g, g' = g - 1/x (module doc of kernel_bracket.rs).",
        "",
        "/// F(c + d) = sum_{k>=0} a_k d^k for from <= x < to, with c = hi + lo and d = (x - hi) - lo.",
        "pub(super) struct TaylorPiece {",
        "    /// Which function: 0 = h, 1 = H1, 2 = H2.",
        "    pub order: usize,",
        "    /// Centre, leading double.",
        "    pub hi: f64,",
        "    /// Centre, trailing double (c - hi; 0 unless the centre is a zero).",
        "    pub lo: f64,",
        "    /// Window start (inclusive).",
        "    pub from: f64,",
        "    /// Window end (exclusive).",
        "    pub to: f64,",
        "    /// a_0 ... a_K (a_0 = 0 when the centre is the function's zero).",
        f"    pub coeffs: [f64; {TAYLOR_TERMS + 1}],",
        "}",
        "",
        "/// All pieces; windows of one function do not overlap.",
        f"pub(super) const TAYLOR_PIECES: [TaylorPiece; {len(TAYLOR_PIECES)}] = [",
    ]
    for name, centre, lo_x, hi_x in TAYLOR_PIECES:
        c = zeros[name] if centre is None else mp.mpf(centre)
        assert lo_x <= c < hi_x and max(c - lo_x, hi_x - c) <= mp.mpf("0.42") * abs(c)
        # Inside a window around a zero, x - hi must be exact (Sterbenz): within a factor 2 of c.
        assert centre is not None or (lo_x >= 2 * float(c) and hi_x <= 0.5 * float(c))
        hi = float(c)
        lo = float(c - mp.mpf(hi))
        coeffs = taylor_coefficients(name, c)
        if centre is None:
            coeffs[0] = mp.mpf(0)
        what = "zero" if centre is None else "centre"
        lines.append(f"    // {name}: {what} {mp.nstr(c, 30)}, window [{lo_x}, {hi_x})")
        lines.append("    TaylorPiece {")
        lines.append(f"        order: {['h', 'h1', 'h2'].index(name)},")
        lines.append(f"        hi: {hi!r},")
        lines.append(f"        lo: {lo!r},")
        lines.append(f"        from: {lo_x!r},")
        lines.append(f"        to: {hi_x!r},")
        lines.append("        coeffs: [")
        for a in coeffs:
            lines.append(f"            {float(a)!r},")
        lines.append("        ],")
        lines.append("    },")
    lines.append("];")
    with open(OUT_TAYLOR, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {os.path.normpath(OUT_TAYLOR)}")


def main():
    cross_check()
    x0 = mp.findroot(mp.ei, 0.37)
    zeros = {"h": mp.findroot(h0, -1.17), "h1": mp.findroot(h1, -2.09), "h2": mp.findroot(h2, -3.06)}
    print("Ei zero x0 =", mp.nstr(x0, 40), "hi", repr(float(x0)), "lo", repr(float(x0 - mp.mpf(float(x0)))))
    print("ln x0 =", repr(float(mp.log(x0))))
    for k, z in zeros.items():
        print(f"zero of {k}: {mp.nstr(z, 40)}")

    write_taylor_pieces(zeros)

    logs = [10.0 ** (e / 8.0) for e in range(-96, 97)]  # 1e-12 .. 1e12, 8 per decade
    # The kernel meets b*xi from 1e-24 to 1e24 (b and |xi| each from 1e-12 to 1e12): 1 per decade out to 1e30.
    logs += [10.0 ** e for e in list(range(-30, -12)) + list(range(13, 31))]
    x0f = float(x0)
    near_x0 = [x0f]
    for k in range(1, 16):
        near_x0 += [x0f * (1 + 10.0 ** -k), x0f * (1 - 10.0 ** -k)]
    v = x0f
    for _ in range(5):
        v = math.nextafter(v, 1.0)
        near_x0.append(v)
    v = x0f
    for _ in range(5):
        v = math.nextafter(v, 0.0)
        near_x0.append(v)
    switches = [0.5, 1.0, 2.0, 3.0, 45.0, 0.5 * x0f, 2.0 * x0f, 709.0, 710.0, 740.0]
    near_sw = []
    for s in switches:
        for eps in (0.0, 1e-12, -1e-12, 1e-6, -1e-6, 1e-2, -1e-2):
            near_sw.append(s * (1 + eps))
    dense = [round(-8 + 0.05 * i, 10) for i in range(0, 321)]  # -8 .. 8 step 0.05 (derivative check)
    dense = [d for d in dense if d != 0.0]
    near_zero_h = []
    for z in zeros.values():
        zf = float(z)
        for k in range(1, 13):
            near_zero_h += [zf * (1 + 10.0 ** -k), zf * (1 - 10.0 ** -k)]
        near_zero_h += [zf, math.nextafter(zf, 0.0), math.nextafter(zf, -10.0)]
    for _, _, lo_x, hi_x in TAYLOR_PIECES:  # window edges of the Taylor pieces
        for edge in (lo_x, hi_x):
            near_zero_h += [edge, edge * (1 + 1e-12), edge * (1 - 1e-12), edge * 1.01, edge * 0.99]

    rows = []

    def add(name, xs):
        for x in sorted(set(xs)):
            x = float(x)
            val = FUNCS[name](x)
            rows.append((name, x, val))

    pos = logs + near_x0 + near_sw + [d for d in dense if d > 0]
    neg = [-x for x in logs + near_x0 + near_sw] + [d for d in dense if d < 0]
    add("e1", [x for x in pos if x <= 700.0])
    add("exp_e1", pos)
    add("ei", [x for x in pos + neg if abs(x) <= 700.0])
    add("expm_ei", pos + neg)
    for name in ("h", "h1", "h2"):
        add(name, pos + neg + near_zero_h)

    with open(OUT, "w") as f:
        f.write("# generated by tools/gen_special_reference.py (mpmath %s, 120 digits); do not edit\n" % mp.__version__)
        f.write("function,x,value\n")
        for name, x, val in rows:
            f.write("%s,%r,%s\n" % (name, x, mp.nstr(val, 25, min_fixed=1, max_fixed=0)))
    print(f"wrote {len(rows)} rows to {os.path.normpath(OUT)}")


if __name__ == "__main__":
    main()
