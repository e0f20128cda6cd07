"""Independent oracle of tilting-pad journal bearings with preload, written for
this repository's tests (it generates tilting_pad_preload_reference.json; run
`.venv/bin/python tests/data/tilting_pad_preload_oracle.py` to regenerate).

It extends the method of the seed reference (tilting_pad_reference.json, no
preload) to preloaded pads, load on pad and load between pads, by numerical
quadrature of the cavitated short-bearing pressure field; it uses none of the
crate's closed forms.

Model (SI units; θ from +x toward +y, spin ω > 0 toward +θ). Pad k, pivot θp,
preload m, tilt η (pad rotation times the pad radius, counter-clockwise):
    h = C − m C cos(θ − θp) − X cos θ − Y sin θ − η sin(θ − θp)
    S = ω ∂h/∂θ + 2 ∂h/∂t
    P(θ) = ∫ max(p, 0) dz = −μ L³ / (2 h³) · min(S, 0)     (p = 3μ/h³ (z² − L²/4) S)
    F = −R ∫ P (cos θ, sin θ) dθ,    Q_η = R ∫ P ∂h/∂η dθ = −R ∫ P sin(θ − θp) dθ
over the pad arc, split where S changes sign and integrated by 64-point
Gauss–Legendre on each piece. Each pivot also carries the crate's documented
weak restoring moment −k_r η − c_r η̇ (c_r = 1e-9 μ R L³/C³, k_r = c_r max(ω, 1)).

Equilibrium under W along −y: F + (0, −W) = 0 and Q_η = 0 for every pad, by
Newton with central-difference Jacobians from a start where each pad sits at the
tilt of zero pivot moment. Coefficients: K = −∂Q/∂q, C = −∂Q/∂q̇ by central
differences over journal and pad coordinates, condensed synchronously:
Z = K + iωC, Z_red = Z_jj − Z_jp Z_pp⁻¹ Z_pj, K_red = Re Z_red, C_red = Im Z_red / ω.
"""
import json
import math
import os

import numpy as np

NODES, WEIGHTS = np.polynomial.legendre.leggauss(64)


class Bearing:
    def __init__(self, R, L, C, mu, omega, pads):
        self.R, self.L, self.C, self.mu, self.omega = R, L, C, mu, omega
        self.pads = [dict(pivot=math.radians(p), arc=math.radians(a), offset=o, preload=m)
                     for p, a, o, m in pads]
        self.c_r = 1e-9 * mu * R * L**3 / C**3
        self.k_r = self.c_r * max(abs(omega), 1.0)

    def pad_forces(self, pad, X, Y, eta, Xd, Yd, etad):
        """(F_x, F_y, Q_η) of one pad's film by quadrature."""
        C, w, tp, m = self.C, self.omega, pad["pivot"], pad["preload"]
        lead = tp - pad["offset"] * pad["arc"]
        trail = lead + pad["arc"]
        a = w * (m * C * math.cos(tp) + X - eta * math.sin(tp)) - 2 * Yd - 2 * etad * math.cos(tp)
        b = w * (-m * C * math.sin(tp) - Y - eta * math.cos(tp)) - 2 * Xd + 2 * etad * math.sin(tp)
        cuts = [lead, trail]
        if a != 0.0 or b != 0.0:
            zero = math.atan2(-b, a)
            for k in range(-4, 5):
                z = zero + k * math.pi
                if lead < z < trail:
                    cuts.append(z)
        cuts.sort()
        fx = fy = q = 0.0
        for lo, hi in zip(cuts[:-1], cuts[1:]):
            th = 0.5 * (hi + lo) + 0.5 * (hi - lo) * NODES
            wt = 0.5 * (hi - lo) * WEIGHTS
            h = C - m * C * np.cos(th - tp) - X * np.cos(th) - Y * np.sin(th) - eta * np.sin(th - tp)
            if np.any(h <= 0):
                raise ValueError("film thickness ≤ 0 on a pad")
            s = a * np.sin(th) + b * np.cos(th)
            p = -self.mu * self.L**3 / (2 * h**3) * np.minimum(s, 0.0)
            fx += -self.R * np.sum(wt * p * np.cos(th))
            fy += -self.R * np.sum(wt * p * np.sin(th))
            q += -self.R * np.sum(wt * p * np.sin(th - tp))
        return fx, fy, q

    def generalized(self, q, qd):
        """Q = [F_x, F_y, Q_η1, …] at coordinates q = [X, Y, η…] and rates qd."""
        X, Y, Xd, Yd = q[0], q[1], qd[0], qd[1]
        out = np.zeros(len(q))
        for k, pad in enumerate(self.pads):
            fx, fy, qe = self.pad_forces(pad, X, Y, q[2 + k], Xd, Yd, qd[2 + k])
            out[0] += fx
            out[1] += fy
            out[2 + k] = qe - self.k_r * q[2 + k] - self.c_r * qd[2 + k]
        return out

    def tilt_of_zero_moment(self, k, X, Y):
        """A pad's tilt where its pivot moment changes sign from + to − (scan, then bisection)."""
        pad = self.pads[k]

        def moment(eta):
            try:
                return self.pad_forces(pad, X, Y, eta, 0.0, 0.0, 0.0)[2] - self.k_r * eta
            except ValueError:
                return None
        etas = np.linspace(-0.98 * self.C, 0.98 * self.C, 129)
        prev = None
        for eta in etas:
            m = moment(eta)
            if m is None:
                prev = None
                continue
            if prev is not None and prev[1] > 0.0 >= m:
                lo, hi = prev[0], eta
                for _ in range(80):
                    mid = 0.5 * (lo + hi)
                    v = moment(mid)
                    lo, hi = (mid, hi) if v is not None and v > 0.0 else (lo, mid)
                return 0.5 * (lo + hi)
            prev = (eta, m)
        return 0.0

    def jacobians(self, q):
        n = len(q)
        K = np.zeros((n, n))
        D = np.zeros((n, n))
        zero = np.zeros(n)
        hq = 1e-7 * self.C
        hv = 1e-7 * self.C * self.omega
        for j in range(n):
            e = np.zeros(n)
            e[j] = 1.0
            K[:, j] = -(self.generalized(q + hq * e, zero) - self.generalized(q - hq * e, zero)) / (2 * hq)
            D[:, j] = -(self.generalized(q, hv * e) - self.generalized(q, -hv * e)) / (2 * hv)
        return K, D

    def equilibrium(self, W):
        """Continued in load from W/8 (each solution starts the next)."""
        n = 2 + len(self.pads)
        Cb = self.C * (1 - max(p["preload"] for p in self.pads))
        q = np.zeros(n)
        q[1] = -0.1 * Cb
        for k in range(len(self.pads)):
            q[2 + k] = self.tilt_of_zero_moment(k, q[0], q[1])
        for w in np.linspace(W / 8, W, 8):
            q = self.newton(q, w)
        return q

    def newton(self, q, W):
        n = len(q)
        load = np.zeros(n)
        load[1] = -W
        zero = np.zeros(n)
        r = self.generalized(q, zero) + load
        for it in range(200):
            if np.linalg.norm(r) <= 1e-11 * W:
                return q
            if os.environ.get("ORACLE_TRACE"):
                print(f"  W = {W:.1f} N, iteration {it}: residual {np.linalg.norm(r):.3e} N")
            K, _ = self.jacobians(q)
            step = np.linalg.solve(K, r)  # Q(q + δ) ≈ Q − K δ
            t = 1.0
            while t > 1e-12:
                trial = q + t * step
                try:
                    rt = self.generalized(trial, zero) + load
                except ValueError:
                    t *= 0.5
                    continue
                if np.linalg.norm(rt) < np.linalg.norm(r):
                    q, r = trial, rt
                    break
                t *= 0.5
            else:
                break
        raise RuntimeError(f"no equilibrium: residual {np.linalg.norm(r)} N")

    def condensed(self, q):
        K, D = self.jacobians(q)
        Z = K + 1j * self.omega * D
        red = Z[:2, :2] - Z[:2, 2:] @ np.linalg.solve(Z[2:, 2:], Z[2:, :2])
        return K, D, red.real, red.imag / self.omega


def case(name, pads, W, note):
    b = Bearing(0.05, 0.03, 1e-4, 0.02, 314.16, pads)
    q = b.equilibrium(W)
    K, D, Kr, Cr = b.condensed(q)
    return {
        "name": name,
        "note": note,
        "parameters": {"R": b.R, "L": b.L, "C": b.C, "mu": b.mu, "omega": b.omega, "W": W,
                       "pads": [{"pivot_deg": p, "arc_deg": a, "offset": o, "preload": m} for p, a, o, m in pads]},
        "equilibrium": {"X": q[0], "Y": q[1], "pad_tilts": q[2:].tolist()},
        "synchronous_reduced": {"K": Kr.tolist(), "C": Cr.tolist()},
        "residual_N": float(np.linalg.norm(b.generalized(q, np.zeros(len(q))) + np.r_[0.0, -W, np.zeros(len(q) - 2)])),
    }


def main():
    cases = [
        case("lbp4_m0", [(45, 80, 0.5, 0.0), (135, 80, 0.5, 0.0), (225, 80, 0.5, 0.0), (315, 80, 0.5, 0.0)],
             1000.0, "seed reference geometry (4 pads, load between pads, no preload): ties this oracle to it"),
        case("lop4_m03", [(0, 80, 0.5, 0.3), (90, 80, 0.5, 0.3), (180, 80, 0.5, 0.3), (270, 80, 0.5, 0.3)],
             1000.0, "4 pads, load on pad, preload 0.3"),
        case("lop5_m05_light", [(54, 60, 0.5, 0.5), (126, 60, 0.5, 0.5), (198, 60, 0.5, 0.5), (270, 60, 0.5, 0.5),
                                (342, 60, 0.5, 0.5)],
             200.0, "5 pads, load on pad at 270°, preload 0.5, light load"),
        case("lop6_m025_heavy", [(30 + 60 * k, 50, 0.6, 0.25) for k in range(6)],
             3000.0, "6 pads, load on pad at 270°, preload 0.25, pivot offset 0.6, heavy load"),
        case("lbp5_m02_heavy", [(18 + 72 * k, 60, 0.5, 0.2) for k in range(5)],
             4000.0, "5 pads, pivots at 18° + 72° k, load between pads, preload 0.2, heavy load"),
    ]
    out = {
        "description": __doc__,
        "cases": cases,
    }
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tilting_pad_preload_reference.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    for c in cases:
        print(c["name"], c["equilibrium"]["X"], c["equilibrium"]["Y"], c["residual_N"])


if __name__ == "__main__":
    main()
