"""Independent oracle of tilting-pad journal bearings with preload, written for
this repository's tests (it generates tilting_pad_preload_reference.json; run
`.venv/bin/python tests/data/tilting_pad_preload_oracle.py` to regenerate; with
`--speed-grid` it writes tilting_pad_speed_grid.json instead, see `speed_grid`).

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

    def equilibrium(self, W, tol=1e-11):
        """Continued in load from W/8 (each solution starts the next)."""
        n = 2 + len(self.pads)
        Cb = self.C * (1 - max(p["preload"] for p in self.pads))
        q = np.zeros(n)
        q[1] = -0.1 * Cb
        for k in range(len(self.pads)):
            q[2 + k] = self.tilt_of_zero_moment(k, q[0], q[1])
        for w in np.linspace(W / 8, W, 8):
            q = self.newton(q, w, tol)
        return q

    def newton(self, q, W, tol=1e-11):
        n = len(q)
        load = np.zeros(n)
        load[1] = -W
        zero = np.zeros(n)
        r = self.generalized(q, zero) + load
        for it in range(200):
            if np.linalg.norm(r) <= tol * W:
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

    def pads_at(self, X, Y):
        """Every pad at its stable zero-moment tilt with the journal held at (X, Y)."""
        return [self.tilt_of_zero_moment(k, X, Y) for k in range(len(self.pads))]

    def journal_force(self, X, Y):
        """Film force on the journal with every pad at `pads_at` (N)."""
        fx = fy = 0.0
        for k, eta in enumerate(self.pads_at(X, Y)):
            f = self.pad_forces(self.pads[k], X, Y, eta, 0.0, 0.0, 0.0)
            fx, fy = fx + f[0], fy + f[1]
        return np.array([fx, fy])

    def equilibrium_on_journal(self, W):
        """The journal equilibrium with the pads eliminated: each pad's moment
        balance is solved on its own at every journal position (`pads_at`:
        scan and bisection, which cannot leave a pad on a wrong root), leaving
        F(X, Y) + (0, −W) = 0 for Newton with central-difference Jacobians and
        backtracking, continued in load from W/8 as `equilibrium`. Converged
        at |F + (0, −W)| ≤ max(1e-10 W, n k_r C) (n pads): a pad without load is held by
        the pivot's rest moment alone, so forces below the rest stiffness
        times a clearance are below what the model resolves."""
        Cb = self.C * (1 - max(p["preload"] for p in self.pads))
        x = np.array([0.0, -0.1 * Cb])
        h = 1e-7 * self.C
        for w in np.linspace(W / 8, W, 8):
            load = np.array([0.0, -w])
            tol = max(1e-10 * w, len(self.pads) * self.k_r * self.C)
            r = self.journal_force(*x) + load
            for _ in range(100):
                if np.linalg.norm(r) <= tol:
                    break
                J = np.zeros((2, 2))
                for j in range(2):
                    e = np.zeros(2)
                    e[j] = h
                    J[:, j] = (self.journal_force(*(x + e)) - self.journal_force(*(x - e))) / (2 * h)
                step = -np.linalg.solve(J, r)
                t = 1.0
                while t > 1e-12:
                    trial = x + t * step
                    try:
                        rt = self.journal_force(*trial) + load
                    except ValueError:
                        t *= 0.5
                        continue
                    if np.linalg.norm(rt) < np.linalg.norm(r):
                        x, r = trial, rt
                        break
                    t *= 0.5
                else:
                    break
            if np.linalg.norm(r) > tol:
                raise RuntimeError(f"no journal equilibrium at {w} N: residual {np.linalg.norm(r)} N")
        return np.r_[x, self.pads_at(*x)]

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


def speed_grid():
    """Equilibria of five bearings (R = 0.05 m, L = 0.03 m, C = 0.1 mm,
    μ = 0.02 Pa·s) under their load W along −y at 21 speeds, 2000–4000 rpm:
    4 pads with the load on a pad and on two pads, both without preload (the
    case whose rotor-level static solve used to stall or end sideways), 5, 6
    and 8 pads with preload 0.25–0.5. Per speed: journal position, pad tilts
    and each pad's film force on the journal. Unloaded pads without preload
    make the full system nearly singular (only the pivots' weak restoring
    moment acts on them), and heavy loads at low speed take the pads to large
    tilts, and a pad's branch can fold within the range: where Newton on the
    full system (`equilibrium`) stalls, it starts from the equilibrium at the
    neighbouring speed of the grid (continuation in speed, 4000 rpm down, then
    up again), then with the pads eliminated (`equilibrium_on_journal`). (Under
    3000 N the six-pad bearing's top pad folds from one branch to another near
    2500 rpm; at the grid's 2000 N it stays on one.)"""
    geometries = [
        ("lop4_m0", [(270 + 90 * k, 80, 0.5, 0.0) for k in range(4)], 2000.0),
        ("lbp4_m0", [(225 + 90 * k, 80, 0.5, 0.0) for k in range(4)], 1000.0),
        ("lop5_m05", [(270 + 72 * k, 60, 0.5, 0.5) for k in range(5)], 200.0),
        ("lop6_m025", [(270 + 60 * k, 50, 0.6, 0.25) for k in range(6)], 2000.0),
        ("lbp8_m05", [(247.5 + 45 * k, 40, 0.5, 0.5) for k in range(8)], 2000.0),
    ]
    out = []
    for name, pads, W in geometries:
        rpms = list(range(2000, 4001, 100))
        solved = {}

        def solve(rpm, neighbour):
            b = Bearing(0.05, 0.03, 1e-4, 0.02, rpm * math.pi / 30, pads)
            attempts = [lambda: b.equilibrium(W), lambda: b.equilibrium_on_journal(W)]
            if neighbour in solved:
                attempts.insert(1, lambda: b.newton(solved[neighbour][0].copy(), W))
            for attempt in attempts:
                try:
                    return attempt(), b
                except (RuntimeError, ValueError):
                    continue
            return None

        # Down from 4000 rpm, then up again for the speeds a fold of a pad's
        # branch left unsolved.
        for order, step in ((rpms[::-1], 100), (rpms, -100)):
            for rpm in order:
                if rpm not in solved:
                    found = solve(rpm, rpm + step)
                    if found is not None:
                        solved[rpm] = found
        points = []
        for rpm in rpms:
            if rpm not in solved:
                raise RuntimeError(f"{name} at {rpm} rpm: no equilibrium")
            q, b = solved[rpm]
            forces = [b.pad_forces(b.pads[k], q[0], q[1], q[2 + k], 0.0, 0.0, 0.0)[:2]
                      for k in range(len(pads))]
            points.append({"rpm": rpm, "omega": b.omega, "X": q[0], "Y": q[1],
                           "pad_tilts": q[2:].tolist(),
                           "pad_forces": [[fx, fy] for fx, fy in forces]})
        out.append({"name": name, "R": 0.05, "L": 0.03, "C": 1e-4, "mu": 0.02, "W": W,
                    "pads": [{"pivot_deg": p, "arc_deg": a, "offset": o, "preload": m}
                             for p, a, o, m in pads],
                    "points": points})
        print(name, [round(p["Y"] / 1e-4, 5) for p in points[::10]])
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "tilting_pad_speed_grid.json")
    with open(path, "w") as f:
        json.dump({"description": speed_grid.__doc__, "command":
                   ".venv/bin/python tests/data/tilting_pad_preload_oracle.py --speed-grid",
                   "cases": out}, f, indent=1)


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
    import sys
    if "--speed-grid" in sys.argv[1:]:
        speed_grid()
    else:
        main()
