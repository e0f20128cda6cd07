"""A PD active magnetic bearing as an FMI 2.0 Co-Simulation FMU (built with
pythonfmu: `python system/build_amb.py`).

The bearing's force on the rotor at its port, from the journal's
displacement and velocity there (the rotor FMU's `ports.<p>.x`, `y`, `vx`,
`vy`):

    fx = −(k x + c vx),   fy = −(k y + c vy)

with the closed-loop stiffness k (N/m) and damping c (N·s/m) of the
bearing's position controller, a linearized AMB: bias-current linearization,
the actuator's negative stiffness and the amplifier's bandwidth folded into
k and c. The law is algebraic (direct feedthrough): an output read after
inputs were set follows those inputs, so a master that sets the inputs
before reading the outputs (Gauss–Seidel) closes the loop with only the
hold of the rotor's inputs over a step; a Jacobi master (libcosim's fixed
step) adds one communication step of delay (docs/system.md).
"""
from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real


class AmbController(Fmi2Slave):
    author = "rotor_bearing"
    description = "PD active magnetic bearing: fx = -(k x + c vx), fy = -(k y + c vy)"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.k = 1e6  # N/m
        self.c = 1e3  # N·s/m
        self.x = 0.0
        self.y = 0.0
        self.vx = 0.0
        self.vy = 0.0
        for name, text in [("k", "Closed-loop stiffness of the bearing [N/m]"),
                           ("c", "Closed-loop damping of the bearing [N.s/m]")]:
            self.register_variable(Real(name, causality=Fmi2Causality.parameter,
                                        variability=Fmi2Variability.fixed, description=text))
        for name, text in [("x", "Journal displacement x at the bearing [m]"),
                           ("y", "Journal displacement y at the bearing [m]"),
                           ("vx", "Journal velocity x at the bearing [m/s]"),
                           ("vy", "Journal velocity y at the bearing [m/s]")]:
            self.register_variable(Real(name, causality=Fmi2Causality.input, description=text))
        self.register_variable(Real("fx", causality=Fmi2Causality.output,
                                    description="Bearing force x on the rotor [N]",
                                    getter=lambda: -(self.k * self.x + self.c * self.vx)))
        self.register_variable(Real("fy", causality=Fmi2Causality.output,
                                    description="Bearing force y on the rotor [N]",
                                    getter=lambda: -(self.k * self.y + self.c * self.vy)))

    def do_step(self, current_time, step_size):
        return True
