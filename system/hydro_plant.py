"""Governor + turbine + generator of a hydro unit as an FMI 2.0 Co-Simulation FMU
(built with pythonfmu: `pythonfmu build -f system/hydro_plant.py`).

Swing equation of the rotating masses with the rotor-bearing FMU's friction
torque in the balance:

    J dω/dt = T_turbine − T_electric − T_friction
    T_turbine, governor and gate servo: system/governor.py (shared with the
                torque-driven plant, system/hydro_plant_torque.py)
    T_electric = P_load / ω_rated · (1 + D (ω − ω_rated)/ω_rated)   until load rejection
    set point ω_ref ramps from the start speed to ω_rated over `ramp_time`.
    field: the `excitation` output (0 … 1, for a rotor FMU's tunable
    magnetic_pull.<m>.excitation) rises linearly over `field_ramp` from
    `field_time` on (synchronization), or is 1 throughout (negative field_time).
    shut-down (emergency stop) at `shutdown_time`: load off, gate command 0, and a
    mechanical brake T_brake = brake_torque · T_rated below brake_speed · ω_rated.
    The bearing friction and the brake are Coulomb torques: at standstill they
    hold the unit (stiction) until the net drive T_turbine − T_electric exceeds
    them (the bearings' breakaway torque μ N R), and they never turn it backwards.

Integrated with RK4 in sub-steps of at most 5 ms inside each do_step.
"""
from governor import gate_rates, turbine_torque
from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real


class HydroPlant(Fmi2Slave):
    author = "rotor_bearing"
    description = "Hydro unit speed governor (PI + gate servo), Francis turbine torque and generator swing equation"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.inertia = 4.8e6          # kg·m², generator + runner + shaft
        self.rated_speed = 15.707963  # rad/s (150 rpm)
        self.rated_torque = 1.02e7    # N·m (160 MW at 150 rpm)
        self.start_speed = 0.0        # rad/s
        self.ramp_time = 60.0         # s, set-point ramp at start-up
        self.load = 0.0               # per unit of rated power
        self.load_damping = 1.0       # D, per unit
        self.rejection_time = -1.0    # s, negative: never
        self.kp = 3.0
        self.ki = 0.6                 # 1/s
        self.servo_time = 0.5         # s
        self.gate_rate = 0.2          # 1/s
        self.loss = 0.05              # no-load losses, per unit torque at rated speed
        self.shutdown_time = -1.0     # s, negative: never
        self.brake_speed = 0.2        # per unit of rated speed
        self.brake_torque = 0.2       # per unit of rated torque
        self.friction_torque = 0.0    # input, N·m
        self.field_time = -1.0        # s, negative: field on from the start
        self.field_ramp = 1.0         # s
        self.speed = 0.0
        self.gate = 0.0
        self.setpoint = 0.0
        self.electric_torque = 0.0
        self.turbine_torque = 0.0
        self.integral = 0.0
        params = [
            ("inertia", "Rotating inertia of generator, runner and shaft", "kg.m2"),
            ("rated_speed", "Rated speed", "rad/s"),
            ("rated_torque", "Turbine torque at rated speed and full gate", "N.m"),
            ("start_speed", "Initial speed and start of the set-point ramp", "rad/s"),
            ("ramp_time", "Duration of the set-point ramp to rated speed", "s"),
            ("load", "Electrical load before rejection (per unit of rated power)", "1"),
            ("load_damping", "Load speed sensitivity D (per unit)", "1"),
            ("rejection_time", "Time of a full load rejection (negative: none)", "s"),
            ("kp", "Governor proportional gain (per unit gate per unit speed)", "1"),
            ("ki", "Governor integral gain", "1/s"),
            ("servo_time", "Gate servo time constant", "s"),
            ("gate_rate", "Gate rate limit (per unit per second)", "1/s"),
            ("loss", "No-load windage and water-friction torque at rated speed (per unit)", "1"),
            ("shutdown_time", "Time of an emergency stop: load off, gate closed, brake on (negative: none)", "s"),
            ("brake_speed", "Speed below which the brake acts after a stop (per unit)", "1"),
            ("brake_torque", "Mechanical brake torque (per unit of rated torque)", "1"),
            ("field_time", "Time the generator field is switched on, at synchronization (negative: on from the start)", "s"),
            ("field_ramp", "Rise time of the field (excitation 0 to 1, linear)", "s"),
        ]
        for name, text, unit in params:
            self.register_variable(Real(name, causality=Fmi2Causality.parameter,
                                        variability=Fmi2Variability.fixed, description=f"{text} [{unit}]"))
        self.register_variable(Real("friction_torque", causality=Fmi2Causality.input,
                                    description="Bearing friction torque on the shaft [N.m]"))
        for name, text in [("speed", "Shaft speed [rad/s]"), ("gate", "Gate opening [1]"),
                           ("setpoint", "Speed set point [rad/s]"),
                           ("electric_torque", "Electrical torque [N.m]"),
                           ("turbine_torque", "Turbine torque [N.m]")]:
            self.register_variable(Real(name, causality=Fmi2Causality.output, description=text))
        # Appended (earlier value references unchanged): the field for a rotor
        # FMU's magnetic_pull.<m>.excitation.
        self.excitation = 1.0
        self.register_variable(Real("excitation", causality=Fmi2Causality.output,
                                    description="Generator field excitation, 0 off to 1 nominal, on at field_time [1]"))
        self.started = False

    def _rates(self, t, speed, gate, integral):
        w0 = self.rated_speed
        ramp = min(1.0, t / self.ramp_time) if self.ramp_time > 0 else 1.0
        ref = self.start_speed + (w0 - self.start_speed) * ramp
        stopping = 0.0 <= self.shutdown_time <= t
        if stopping:
            ref = 0.0
        loaded = (self.rejection_time < 0 or t < self.rejection_time) and not stopping
        p_load = self.load if loaded else 0.0
        dgate, dintegral = gate_rates(self, ref, speed, p_load, integral, gate, stopping)
        t_turbine = turbine_torque(self, gate, speed)
        t_electric = p_load * self.rated_torque * (1.0 + self.load_damping * (speed - w0) / w0)
        braking = stopping and speed <= self.brake_speed * w0
        resist = self.friction_torque + (self.brake_torque * self.rated_torque if braking else 0.0)
        drive = t_turbine - t_electric
        if speed <= 0.0 and drive <= resist:
            dspeed = 0.0  # at rest, held by the bearings' breakaway torque and the brake
        else:
            dspeed = (drive - resist) / self.inertia
        return dspeed, dgate, dintegral, ref, t_turbine, t_electric

    def _field(self, t):
        """Excitation at time t: 0 before field_time, then a linear rise over field_ramp to 1."""
        if self.field_time < 0.0:
            return 1.0
        if self.field_ramp <= 0.0:
            return 1.0 if t >= self.field_time else 0.0
        return min(1.0, max(0.0, (t - self.field_time) / self.field_ramp))

    def exit_initialization_mode(self):
        self.excitation = self._field(0.0)

    def do_step(self, current_time, step_size):
        if not self.started:
            self.speed = self.start_speed
            self.gate = self.load + self.loss if self.start_speed > 0.5 * self.rated_speed else 0.0
            self.started = True
        n = max(1, int(step_size / 0.005 + 0.999))
        h = step_size / n
        t = current_time
        s, g, i = self.speed, self.gate, self.integral
        for _ in range(n):
            k1 = self._rates(t, s, g, i)[:3]
            k2 = self._rates(t + h / 2, s + h / 2 * k1[0], g + h / 2 * k1[1], i + h / 2 * k1[2])[:3]
            k3 = self._rates(t + h / 2, s + h / 2 * k2[0], g + h / 2 * k2[1], i + h / 2 * k2[2])[:3]
            k4 = self._rates(t + h, s + h * k3[0], g + h * k3[1], i + h * k3[2])[:3]
            # Coulomb torques stop the unit; they never turn it backwards.
            s = max(0.0, s + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]))
            g = min(1.0, max(0.0, g + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])))
            i += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2])
            t += h
        self.speed, self.gate, self.integral = s, g, i
        self.excitation = self._field(t)
        _, _, _, self.setpoint, self.turbine_torque, self.electric_torque = self._rates(t, s, g, i)
        return True
