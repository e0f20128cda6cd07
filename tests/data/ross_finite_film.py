"""Reference coefficients of finite-length, isoviscous oil films from ROSS
(ross-rotordynamics 3.1.0, PyPI), written to tests/data/ross_finite_film.csv
for tests/ross_finite_film.rs (issue 47).

ROSS 3.1 solves the Reynolds equation over each pad or land by finite
volumes (its fluid-film engine, `ross.bearings.fluid_film`), with the
Reynolds cavitation condition (a zero-pressure floor in the banded
back-substitution) and ambient (supply = 0) pressure at the pad edges and
the axial ends; `thermal_type=None` makes it isoviscous, and a lubricant
whose two viscosity points are equal makes that viscosity 0.02 Pa·s at any
temperature. Coefficients are its perturbation solves, pads condensed
synchronously.

Cases, all D = 0.1 m, L = 0.05 m (L/D = 0.5), bearing clearance
C_b = 0.1 mm (ROSS's `radial_clearance`; a pad's own clearance is
C_b / (1 − preload)), W = 2000 N along −y, at 1500, 3000 and 6000 rpm:

- `plain2`: ROSS's `PlainJournal` — a bore of two 176° lands between axial
  grooves centred at 90° and 270° (θ from +x toward +y, spin toward +θ).
  ROSS's plain journal is always a grooved bore: the comparison uses the
  same two lands on our side (`FiniteFilm` over two arcs), not our
  periodic 360° film.
- `tp4_lop_m0`, `tp4_lbp_m3`: `TiltingPad`, 4 pads of 80°, pivots at 0.5,
  load on a pad (pivots 0°, 90°, 180°, 270°), preload 0, and between pads
  (45°, 135°, 225°, 315°), preload 0.3.
- `tp5_lbp_m3`, `tp5_lop_m0`: 5 pads of 60°, load between pads (pivots
  234° + 72° k), preload 0.3, and on a pad (270° + 72° k), preload 0.

usage: .venv-ross/bin/python tests/data/ross_finite_film.py NX NZ [NX NZ …]
(film elements around a pad/land and along the length; each mesh is one
block of rows). bench/run_all.sh makes .venv-ross (pip install
ross-rotordynamics==3.1.0 into Python 3.13).
"""
import csv
import os
import sys
import time
import warnings

import numpy as np

warnings.filterwarnings("ignore")
import ross  # noqa: E402
from ross.bearings.lubricants import lubricants_dict  # noqa: E402
from ross.bearings.plain_journal import PlainJournal  # noqa: E402
from ross.bearings.tilting_pad import TiltingPad  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
D, L, CB, MU, W = 0.1, 0.05, 1e-4, 0.02, 2000.0
RPMS = [1500.0, 3000.0, 6000.0]
LUB = dict(lubricants_dict["ISOVG32"])
LUB["liquid_viscosity1"] = MU
LUB["liquid_viscosity2"] = MU
COMMON = dict(
    journal_diameter=D,
    radial_clearance=CB,
    oil_supply_temperature=313.15,
    lubricant=LUB,
    oil_flow_v=1e-2,
    thermal_type=None,
    fxs_load=0.0,
    fys_load=-W,
)
TP = {
    "tp4_lop_m0": (4, 80.0, 0.0, 0.0),
    "tp4_lbp_m3": (4, 80.0, 45.0, 0.3),
    "tp5_lbp_m3": (5, 60.0, 234.0, 0.3),
    "tp5_lop_m0": (5, 60.0, 270.0, 0.0),
}


def plain(speed, nx, nz):
    return PlainJournal(
        n=0, pad_axial_length=L, n_pads=2, pad_arc=np.radians(176.0), preload=0.0,
        speed=[speed], total_ex_film=nx, total_ez_film=nz, total_ey_film=10,
        total_ey_pad=10, **COMMON,
    )


def tilting(name, speed, nx, nz):
    n, arc, first, m = TP[name]
    pivots = [np.radians(first + k * 360.0 / n) for k in range(n)]
    return TiltingPad(
        n=0, pad_axial_length=[L] * n, pad_arc=[np.radians(arc)] * n,
        pivot_angle=pivots, preload=[m] * n, offset=[0.5] * n,
        pad_thickness=0.02, speed=[speed], total_ex_film=nx, total_ez_film=nz,
        total_ey_pad=10, equilibrium_type="match_load", eccentricity=0.3,
        **COMMON,
    )


def main():
    args = [int(a) for a in sys.argv[1:]] or [30, 20]
    meshes = list(zip(args[::2], args[1::2]))
    out = os.path.join(here, "ross_finite_film.csv")
    keys = ["kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy"]
    with open(out, "w", newline="") as f:
        f.write(f"# ROSS {ross.__version__} (ross-rotordynamics), written by tests/data/ross_finite_film.py;\n")
        f.write("# K (N/m), C (N s/m) as ROSS reports them (bearing coefficients, its sign convention).\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["case", "nx", "nz", "rpm"] + keys)
        for nx, nz in meshes:
            for case in ["plain2"] + list(TP):
                for rpm in RPMS:
                    t = time.time()
                    speed = rpm * np.pi / 30.0
                    b = plain(speed, nx, nz) if case == "plain2" else tilting(case, speed, nx, nz)
                    row = [float(np.ravel(getattr(b, k))[0]) for k in keys]
                    w.writerow([case, nx, nz, rpm] + [f"{v:.6e}" for v in row])
                    f.flush()
                    print(f"{case} {nx}x{nz} {rpm:.0f} rpm: {time.time() - t:.1f} s", flush=True)


if __name__ == "__main__":
    main()
