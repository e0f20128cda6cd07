"""Reference numbers from ROSS (ross-rotordynamics 3.1, PyPI) for trains of
two rotors both codes build identically (issue 49), written to
tests/data/ross_train.json:

- `flexible`: a 1.0 m, 60 mm steel shaft in 4 elements (a 250/60 × 60 mm
  disk at node 3, bearings at nodes 1 and 4, overhung coupling hub) and a
  1.2 m, 50 mm shaft in 4 elements (a 220/50 × 50 mm disk at its node 3,
  bearings at its nodes 2 and 5) joined by a flexible coupling: ROSS's
  `CouplingElement` (kt_x = kt_y = 2e7 N/m, kr_x = kr_y = 5e4 N·m/rad,
  ct = 100 N·s/m, cr = 5 N·m·s/rad, kr_z = 3e4 N·m/rad; hub masses 4 and
  3 kg, Ip 0.02 and 0.015 kg·m², Id 0.012 and 0.009 kg·m²). Our model file:
  the coupling in place of a 0.1 m shaft element between the two shafts,
  its hubs as disks of the same mass and inertias at its two nodes.
- `flange`: the same two shafts bolted by a rigid flange at a shared node
  (ROSS: the second shaft's first element starts at the first shaft's last
  node), both hubs one disk of 7 kg there; our model file sets the flange
  off by 0.1 mm and 0.5 mrad, which loads the shafts in statics and leaves
  the linear dynamics as they are.

Anisotropic bearings with damping (and cross-coupled stiffness on the
second shaft). For each case: the model file our side reads, the complex
eigenvalues of `Rotor.run_modal` at 1500, 3000 and 4500 rpm, and the
synchronous response to a 1e-3 kg·m unbalance at the first shaft's disk
(`run_unbalance_response`) at that disk and both coupling nodes over 12
speeds from 500 to 6000 rpm.

usage: python tests/data/ross_train.py   (in an environment with
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
SPEEDS_MODES = [1500.0, 3000.0, 4500.0]  # rpm
SPEEDS_RESPONSE = list(np.linspace(500.0, 6000.0, 12))  # rpm
UNBALANCE = 1e-3
HUB = {"m_l": 4.0, "m_r": 3.0, "Ip_l": 0.02, "Ip_r": 0.015, "Id_l": 0.012, "Id_r": 0.009}
COUPLING = {"kt": 2e7, "kr": 5e4, "ct": 100.0, "cr": 5.0, "kz": 3e4}
BEARING_A = {"kxx": 2e7, "kyy": 3e7, "cxx": 2000.0, "cyy": 2500.0}
BEARING_B = {"kxx": 1.5e7, "kxy": 2e6, "kyx": -2e6, "kyy": 2e7, "cxx": 1500.0, "cyy": 1800.0}

MATERIAL = f"""[[materials]]
name = "steel"
youngs_modulus = {E}
shear_modulus = {G}
density = {RHO}
"""


def shaft_toml(length, diameter, elements):
    return (f'\n[[shaft]]\nlength = {length}\nouter_diameter = {diameter}\n'
            f'material = "steel"\nelements = {elements}\n')


def disk_geometry_toml(name, node, od, bore, width):
    return (f'\n[[disks]]\nname = "{name}"\nnode = {node + 1}\nmaterial = "steel"\n'
            f'outer_diameter = {od}\ninner_diameter = {bore}\nwidth = {width}\n')


def disk_inertia_toml(name, node, m, ip, id_):
    return (f'\n[[disks]]\nname = "{name}"\nnode = {node + 1}\nmass = {m}\n'
            f'polar_inertia = {ip}\ndiametral_inertia = {id_}\n')


def bearing_toml(name, node, coeff):
    return (f'\n[[bearings]]\nname = "{name}"\ntype = "linear"\nnode = {node + 1}\n'
            + "".join(f"{k} = {v}\n" for k, v in coeff.items()))


def unbalance_toml(node):
    return f'\n[[unbalance]]\nname = "disk_a"\nnode = {node + 1}\nmagnitude = {UNBALANCE}\nphase_deg = 0.0\n'


def ross_shafts(steel, gap):
    a = [rs.ShaftElement(L=0.25, idl=0.0, odl=0.06, material=steel, shear_effects=True,
                         rotary_inertia=True, gyroscopic=True) for _ in range(4)]
    b = [rs.ShaftElement(L=0.3, idl=0.0, odl=0.05, material=steel, shear_effects=True,
                         rotary_inertia=True, gyroscopic=True) for _ in range(4)]
    return a + gap + b


def flexible_case():
    steel = rs.Material(name="steel_train", rho=RHO, E=E, G_s=G)
    c = COUPLING
    coupling = rs.CouplingElement(kt_x=c["kt"], kt_y=c["kt"], kr_x=c["kr"], kr_y=c["kr"],
                                  ct_x=c["ct"], ct_y=c["ct"], cr_x=c["cr"], cr_y=c["cr"],
                                  kr_z=c["kz"], L=0.1, o_d=0.06, **HUB)
    shaft = ross_shafts(steel, [coupling])
    # Nodes: shaft A 0–4, the coupling 4–5, shaft B 5–9.
    disks = [
        rs.DiskElement.from_geometry(n=2, material=steel, width=0.06, i_d=0.06, o_d=0.25),
        rs.DiskElement.from_geometry(n=7, material=steel, width=0.05, i_d=0.05, o_d=0.22),
    ]
    bearings = [
        rs.BearingElement(n=0, **BEARING_A), rs.BearingElement(n=3, **BEARING_A),
        rs.BearingElement(n=6, **BEARING_B), rs.BearingElement(n=9, **BEARING_B),
    ]
    text = 'name = "ross_train_flexible"\n' + MATERIAL
    text += shaft_toml(1.0, 0.06, 4) + shaft_toml(0.1, 0.06, 1) + shaft_toml(1.2, 0.05, 4)
    text += disk_geometry_toml("disk_a", 2, 0.25, 0.06, 0.06)
    text += disk_geometry_toml("disk_b", 7, 0.22, 0.05, 0.05)
    text += disk_inertia_toml("hub_a", 4, HUB["m_l"], HUB["Ip_l"], HUB["Id_l"])
    text += disk_inertia_toml("hub_b", 5, HUB["m_r"], HUB["Ip_r"], HUB["Id_r"])
    for name, node, coeff in (("a1", 0, BEARING_A), ("a2", 3, BEARING_A),
                              ("b1", 6, BEARING_B), ("b2", 9, BEARING_B)):
        text += bearing_toml(name, node, coeff)
    text += (f'\n[[couplings]]\nname = "flexible"\nnode = 5\n'
             f'lateral_stiffness = {c["kt"]}\nangular_stiffness = {c["kr"]}\n'
             f'lateral_damping = {c["ct"]}\nangular_damping = {c["cr"]}\n'
             f'torsional_stiffness = {c["kz"]}\n')
    text += unbalance_toml(2)
    return text, rs.Rotor(shaft, disks, bearings), [2, 4, 5]


def flange_case():
    steel = rs.Material(name="steel_train", rho=RHO, E=E, G_s=G)
    shaft = ross_shafts(steel, [])
    # Nodes: shaft A 0–4, shaft B 4–8 (node 4 the flange).
    hub = {k: HUB[k + "_l"] + HUB[k + "_r"] for k in ("m", "Ip", "Id")}
    disks = [
        rs.DiskElement.from_geometry(n=2, material=steel, width=0.06, i_d=0.06, o_d=0.25),
        rs.DiskElement.from_geometry(n=6, material=steel, width=0.05, i_d=0.05, o_d=0.22),
        rs.DiskElement(n=4, m=hub["m"], Ip=hub["Ip"], Id=hub["Id"]),
    ]
    bearings = [
        rs.BearingElement(n=0, **BEARING_A), rs.BearingElement(n=3, **BEARING_A),
        rs.BearingElement(n=5, **BEARING_B), rs.BearingElement(n=8, **BEARING_B),
    ]
    text = 'name = "ross_train_flange"\n' + MATERIAL
    text += shaft_toml(1.0, 0.06, 4) + shaft_toml(1.2, 0.05, 4)
    text += disk_geometry_toml("disk_a", 2, 0.25, 0.06, 0.06)
    text += disk_geometry_toml("disk_b", 6, 0.22, 0.05, 0.05)
    text += disk_inertia_toml("hubs", 4, hub["m"], hub["Ip"], hub["Id"])
    for name, node, coeff in (("a1", 0, BEARING_A), ("a2", 3, BEARING_A),
                              ("b1", 5, BEARING_B), ("b2", 8, BEARING_B)):
        text += bearing_toml(name, node, coeff)
    text += ('\n[[couplings]]\nname = "flange"\nnode = 5\n'
             'parallel_offset = [1e-4, 0.0]\nangular_offset = [0.0, 5e-4]\n')
    text += unbalance_toml(2)
    return text, rs.Rotor(shaft, disks, bearings), [2, 4, 5]


def results(rotor, nodes):
    modes = []
    for rpm in SPEEDS_MODES:
        ev = rotor.run_modal(rpm * RPM, num_modes=40).evalues
        modes.append({"rpm": rpm, "eigenvalues": [[float(v.real), float(v.imag)] for v in ev]})
    speeds = np.array(SPEEDS_RESPONSE) * RPM
    resp = rotor.run_unbalance_response(node=2, unbalance_magnitude=UNBALANCE, unbalance_phase=0.0,
                                        speed_range=speeds).forced_resp
    ndof = rotor.number_dof
    response = {
        str(node): {
            "x": [[float(v.real), float(v.imag)] for v in resp[ndof * node + 0]],
            "y": [[float(v.real), float(v.imag)] for v in resp[ndof * node + 1]],
        }
        for node in nodes
    }
    return {"modes": modes, "response_rpm": SPEEDS_RESPONSE, "response_nodes": nodes,
            "response": response}


out = {"ross_version": rs.__version__, "cases": {}}
for name, (text, rotor, nodes) in (("flexible", flexible_case()), ("flange", flange_case())):
    out["cases"][name] = {"model": text, **results(rotor, nodes)}
with open(os.path.join(here, "ross_train.json"), "w") as f:
    json.dump(out, f, indent=1)
print("wrote tests/data/ross_train.json with ROSS", rs.__version__)
