"""Reference numbers from ROSS (ross-rotordynamics 3.1, PyPI) for rotors both
codes build identically, written to tests/data/ross_supports.json:

- `pedestals`: the damped classic rotor (1.5 m, 50 mm steel shaft in 6
  Timoshenko elements, a 280/50 × 70 mm steel disk at mid-span) whose two
  bearings (1e6 N/m, 1000 N·s/m) each stand on a support mass in series
  (ROSS `n_link` to a `PointMass`, itself on a `BearingElement` to ground:
  anisotropic, cross-coupled, damped);
- `table_and_seal`: the same rotor on a rigid-ground linear bearing and a
  bearing given as a speed table (5 rows, PCHIP), with a seal at the disk
  (speed table, cross-coupled).

For each: the model file our side reads (same numbers), the complex
eigenvalues of `Rotor.run_modal` at three speeds between the table rows, and
the synchronous response to a 1e-3 kg·m unbalance at the disk
(`run_unbalance_response`) at the disk and bearing nodes over 12 speeds.

usage: python tests/data/ross_supports.py   (in an environment with
ross-rotordynamics 3.1; bench/run_all.sh makes one, .venv-ross)
"""
import json
import os
import warnings

import numpy as np
import ross as rs

warnings.filterwarnings("ignore")
here = os.path.dirname(os.path.abspath(__file__))
RPM = np.pi / 30.0
E, G, RHO = 211e9, 81.2e9, 7810.0
SPEEDS_MODES = [1250.0, 2600.0, 3700.0]  # rpm
SPEEDS_RESPONSE = list(np.linspace(600.0, 3900.0, 12))  # rpm, inside the table rows
NODES = [0, 3, 6]
UNBALANCE = 1e-3

# Table rows (rpm) and columns shared by both codes.
TABLE_RPM = [500.0, 1000.0, 2000.0, 3000.0, 4000.0]
TABLE = {
    "kxx": [1.0e6, 1.3e6, 2.1e6, 2.6e6, 2.8e6],
    "kxy": [1e5, 2.5e5, 6e5, 9e5, 1.1e6],
    "kyx": [-1e5, -2.0e5, -5e5, -8e5, -1.0e6],
    "kyy": [1.2e6, 1.5e6, 2.4e6, 3.0e6, 3.3e6],
    "cxx": [3000.0, 2600.0, 2100.0, 1900.0, 1850.0],
    "cyy": [3200.0, 2800.0, 2300.0, 2000.0, 1900.0],
}
SEAL = {
    "kxx": [2e5, 2.2e5, 2.6e5, 3.1e5, 3.5e5],
    "kxy": [3e4, 6e4, 1.3e5, 2.0e5, 2.8e5],
    "kyx": [-3e4, -6e4, -1.3e5, -2.0e5, -2.8e5],
    "kyy": [2e5, 2.2e5, 2.6e5, 3.1e5, 3.5e5],
    "cxx": [400.0, 420.0, 450.0, 470.0, 480.0],
    "cyy": [400.0, 420.0, 450.0, 470.0, 480.0],
}
PEDESTAL = {"mass": 25.0, "kxx": 4e6, "kxy": 2e5, "kyx": 2e5, "kyy": 6e6, "cxx": 800.0, "cyy": 900.0}

SHAFT_TOML = f"""[[materials]]
name = "steel"
youngs_modulus = {E}
shear_modulus = {G}
density = {RHO}

[[shaft]]
length = 1.5
outer_diameter = 0.05
material = "steel"
elements = 6

[[disks]]
name = "disk"
node = 4
material = "steel"
outer_diameter = 0.28
inner_diameter = 0.05
width = 0.07

[[unbalance]]
name = "disk"
node = 4
magnitude = {UNBALANCE}
phase_deg = 0.0
"""


def ross_shaft():
    steel = rs.Material(name="steel_supports", rho=RHO, E=E, G_s=G)
    shaft = [rs.ShaftElement(L=0.25, idl=0.0, odl=0.05, material=steel, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for _ in range(6)]
    disk = rs.DiskElement.from_geometry(n=3, material=steel, width=0.07, i_d=0.05, o_d=0.28)
    return shaft, [disk]


def toml_list(values):
    return "[" + ", ".join(repr(float(v)) for v in values) + "]"


def pedestals_case():
    shaft, disks = ross_shaft()
    p = PEDESTAL
    bearings, masses = [], []
    text = 'name = "ross_pedestals"\n' + SHAFT_TOML
    for name, node, link in (("drive_end", 0, 7), ("non_drive_end", 6, 8)):
        bearings.append(rs.BearingElement(n=node, kxx=1e6, kyy=1e6, cxx=1000.0, cyy=1000.0, n_link=link))
        masses.append(rs.PointMass(n=link, m=p["mass"]))
        bearings.append(rs.BearingElement(n=link, kxx=p["kxx"], kxy=p["kxy"], kyx=p["kyx"], kyy=p["kyy"],
                                          cxx=p["cxx"], cyy=p["cyy"]))
        text += (f'\n[[bearings]]\nname = "{name}"\ntype = "linear"\nnode = {node + 1}\n'
                 f'kxx = 1e6\nkyy = 1e6\ncxx = 1000.0\ncyy = 1000.0\npedestal = "{name}_pedestal"\n')
        text += (f'\n[[pedestals]]\nname = "{name}_pedestal"\nmass = {p["mass"]}\n'
                 f'kxx = {p["kxx"]}\nkxy = {p["kxy"]}\nkyx = {p["kyx"]}\nkyy = {p["kyy"]}\n'
                 f'cxx = {p["cxx"]}\ncyy = {p["cyy"]}\n')
    return text, rs.Rotor(shaft, disks, bearings, masses)


def table_and_seal_case():
    shaft, disks = ross_shaft()
    speed = np.array(TABLE_RPM) * RPM
    table = {k: TABLE.get(k, [0.0] * 5) for k in ("kxx", "kxy", "kyx", "kyy", "cxx", "cyy")}
    seal = {k: SEAL.get(k, [0.0] * 5) for k in ("kxx", "kxy", "kyx", "kyy", "cxx", "cyy")}
    bearings = [
        rs.BearingElement(n=0, kxx=1e6, kyy=1e6, cxx=1000.0, cyy=1000.0),
        rs.BearingElement(n=6, speed=speed, **table),
        rs.SealElement(n=3, speed=speed, **seal),
    ]
    text = 'name = "ross_table_and_seal"\n' + SHAFT_TOML
    text += ('\n[[bearings]]\nname = "drive_end"\ntype = "linear"\nnode = 1\n'
             'kxx = 1e6\nkyy = 1e6\ncxx = 1000.0\ncyy = 1000.0\n')
    text += f'\n[[bearings]]\nname = "non_drive_end"\ntype = "table"\nnode = 7\nspeeds_rpm = {toml_list(TABLE_RPM)}\n'
    text += "".join(f"{k} = {toml_list(v)}\n" for k, v in table.items())
    text += f'\n[[seals]]\nname = "seal"\nnode = 4\nspeeds_rpm = {toml_list(TABLE_RPM)}\n'
    text += "".join(f"{k} = {toml_list(v)}\n" for k, v in seal.items())
    return text, rs.Rotor(shaft, disks, bearings)


def results(rotor):
    modes = []
    for rpm in SPEEDS_MODES:
        ev = rotor.run_modal(rpm * RPM, num_modes=40).evalues
        modes.append({"rpm": rpm, "eigenvalues": [[float(v.real), float(v.imag)] for v in ev]})
    speeds = np.array(SPEEDS_RESPONSE) * RPM
    resp = rotor.run_unbalance_response(node=3, unbalance_magnitude=UNBALANCE, unbalance_phase=0.0,
                                        speed_range=speeds).forced_resp
    ndof = rotor.number_dof
    response = {
        str(node): {
            "x": [[float(v.real), float(v.imag)] for v in resp[ndof * node + 0]],
            "y": [[float(v.real), float(v.imag)] for v in resp[ndof * node + 1]],
        }
        for node in NODES
    }
    return {"modes": modes, "response_rpm": SPEEDS_RESPONSE, "response": response}


out = {"ross_version": rs.__version__, "cases": {}}
for name, (text, rotor) in (("pedestals", pedestals_case()), ("table_and_seal", table_and_seal_case())):
    out["cases"][name] = {"model": text, **results(rotor)}
with open(os.path.join(here, "ross_supports.json"), "w") as f:
    json.dump(out, f, indent=1)
print("wrote tests/data/ross_supports.json with ROSS", rs.__version__)
