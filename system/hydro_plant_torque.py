"""Governor + turbine + grid-connected generator of a hydro unit for a
torque-driven rotor FMU, as an FMI 2.0 Co-Simulation FMU (pythonfmu; built by
system/build_plant.py). It carries no inertia: the rotor-bearing FMU
(`[torsion] drive = "torque"`, models/hydro_unit_torque.toml) integrates the
shaft with its own polar inertia, torsional stiffness and bearing friction, and
returns the speeds and the generator's angle.

    inputs  turbine_speed, generator_speed (rad/s), generator_angle (rad)
    outputs turbine_torque (N·m, into the rotor's torques.turbine)
            generator_torque = −(T_e + T_brake) (N·m, into torques.generator)

Turbine, governor and gate servo: system/governor.py (the speed-driven plant's),
with the turbine torque at the runner's speed and the governor on the
generator's speed.

Generator (classical single-machine–infinite-bus model, per unit on the rated
torque T_r; Kundur, Power System Stability and Control, 1994, §3.9 and ch. 5):
    load angle (electrical)  δ = p φ_g − ω_e t − θ_grid,  ω_e = p ω_r
    T_e = T_r [P_max sin δ + D (ω_g − ω_r)/ω_r]   while the breaker is closed
    (synchronizing torque ∂T_e/∂δ = T_r P_max cos δ, damping D), 0 while open.
Synchronization: the set point runs to ω_r (1 + sync_slip); from `sync_time`
on, the breaker closes at the first step with |δ| (wrapped) ≤ sync_angle and
|ω_g/ω_r − 1| ≤ sync_slip_limit; the load set point then ramps from 0 to `load`
over `load_ramp_time`, with the set point back at ω_r.
Connected start (`connected` = 1): breaker closed at t = 0 in the steady state
of `load` (δ₀ = asin(load/P_max), gate = load + loss); both torques come in
with a half-cosine ramp over `settle_time`, so that the rotor FMU's shaft,
which starts untwisted, takes its steady twist without ringing.
Three-phase terminal short circuit at `fault_time` (standard design case):
    T_e = T_r (E²/x''_d) e^{−τ/T_a} sin(ω_e τ),  τ = t − fault_time
(the fundamental-frequency air-gap torque of a sudden short circuit with the
resistances neglected: Kundur §3.9; Concordia, Synchronous Machines, 1951;
the unidirectional loss torque and the second harmonic of subtransient saliency
are left out); the generator breaker clears it after `fault_duration` and the
unit is left disconnected (the governor then sees a load rejection).
Load rejection at `rejection_time`: breaker open, load set point 0.
Shut-down at `shutdown_time`: breaker open, gate command 0, and below
brake_speed the brake, a Coulomb torque brake_torque · T_r regularized over
|ω_g| ≤ brake_smoothing (the rotor FMU's thrust bearing holds it at rest).

Gate and governor integral by RK4 in sub-steps of at most 5 ms, with the
speeds held over the communication step; the output torques are those at the
step's end (the generator angle extrapolated with its speed).
"""
import math

from governor import gate_rates, rk4, turbine_torque
from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real


class HydroPlantTorque(Fmi2Slave):
    author = "rotor_bearing"
    description = "Hydro unit governor (PI + gate servo), Francis turbine and grid-connected generator torques for a torque-driven rotor FMU (no inertia of its own)"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.rated_speed = 15.707963  # rad/s (150 rpm, 50 Hz with 20 pole pairs)
        self.rated_torque = 1.02e7    # N·m (160 MW at 150 rpm)
        self.start_speed = 0.0        # rad/s
        self.ramp_time = 60.0         # s
        self.load = 0.0               # per unit
        self.load_ramp_time = 10.0    # s
        self.connected = 0.0
        self.rejection_time = -1.0
        self.kp = 3.0
        self.ki = 0.6
        self.servo_time = 0.5
        self.gate_rate = 0.2
        self.loss = 0.05
        self.shutdown_time = -1.0
        self.brake_speed = 0.2
        self.brake_torque = 0.2
        self.brake_smoothing = 0.05   # rad/s
        self.pole_pairs = 20.0
        self.pullout = 2.0            # P_max, per unit
        self.damping = 10.0           # D, per unit torque per unit slip
        self.sync_time = -1.0
        self.sync_slip = 0.003
        self.sync_slip_limit = 0.01
        self.sync_angle = 0.17        # rad electrical (about 10°)
        self.grid_phase = 2.0         # rad electrical: the grid's phase at t = 0 (θ_grid of a start from rest)
        self.fault_time = -1.0
        self.fault_duration = 0.5
        self.subtransient_reactance = 0.2   # x''_d, per unit
        self.armature_time = 0.25           # T_a, s
        self.emf = 1.0                      # E, per unit
        self.settle_time = 1.0              # s
        self.turbine_speed = 0.0
        self.generator_speed = 0.0
        self.generator_angle = 0.0
        self.turbine_torque = 0.0
        self.generator_torque = 0.0
        self.electric_torque = 0.0
        self.gate = 0.0
        self.setpoint = 0.0
        self.load_angle = 0.0
        self.breaker = 0.0
        self.integral = 0.0
        params = [
            ("rated_speed", "Rated (synchronous) speed", "rad/s"),
            ("rated_torque", "Turbine torque at rated speed and full gate, the per-unit base", "N.m"),
            ("start_speed", "Initial speed (the rotor FMU's shaft.initial_speed) and start of the set-point ramp", "rad/s"),
            ("ramp_time", "Duration of the set-point ramp to rated speed", "s"),
            ("load", "Electrical load set point after synchronization (per unit of rated power)", "1"),
            ("load_ramp_time", "Ramp of the load set point after synchronization", "s"),
            ("connected", "1: start connected to the grid in the steady state of `load`", "1"),
            ("rejection_time", "Time of a full load rejection, breaker open (negative: none)", "s"),
            ("kp", "Governor proportional gain (per unit gate per unit speed)", "1"),
            ("ki", "Governor integral gain", "1/s"),
            ("servo_time", "Gate servo time constant", "s"),
            ("gate_rate", "Gate rate limit (per unit per second)", "1/s"),
            ("loss", "No-load windage and water-friction torque at rated speed (per unit)", "1"),
            ("shutdown_time", "Time of a shut-down: breaker open, gate closed, brake on (negative: none)", "s"),
            ("brake_speed", "Speed below which the brake acts after a shut-down (per unit)", "1"),
            ("brake_torque", "Mechanical brake torque (per unit of rated torque)", "1"),
            ("brake_smoothing", "Speed over which the brake's Coulomb torque is regularized", "rad/s"),
            ("pole_pairs", "Generator pole pairs p (electrical angle = p x mechanical)", "1"),
            ("pullout", "Pull-out power P_max = E V / X (per unit)", "1"),
            ("damping", "Damping torque coefficient D (per unit torque per unit slip)", "1"),
            ("sync_time", "Earliest time the synchronizer may close the breaker (negative: never)", "s"),
            ("sync_slip", "Speed set point above synchronous while synchronizing (per unit)", "1"),
            ("sync_slip_limit", "Largest slip at which the breaker may close (per unit)", "1"),
            ("sync_angle", "Largest electrical phase difference at which the breaker may close", "rad"),
            ("grid_phase", "Electrical phase of the grid at t = 0 relative to the rotor's angle 0", "rad"),
            ("fault_time", "Time of a three-phase terminal short circuit (negative: none)", "s"),
            ("fault_duration", "Time until the generator breaker clears the short circuit", "s"),
            ("subtransient_reactance", "Subtransient reactance x''_d (per unit)", "1"),
            ("armature_time", "Armature (DC) time constant T_a", "s"),
            ("emf", "Internal voltage E before the short circuit (per unit)", "1"),
            ("settle_time", "Connected start: the steady torques come in over this time, twisting the shaft quasi-statically", "s"),
        ]
        for name, text, unit in params:
            self.register_variable(Real(name, causality=Fmi2Causality.parameter,
                                        variability=Fmi2Variability.fixed, description=f"{text} [{unit}]"))
        for name, text in [("turbine_speed", "Runner speed from the rotor FMU (torques.turbine.speed) [rad/s]"),
                           ("generator_speed", "Generator speed from the rotor FMU (torques.generator.speed) [rad/s]"),
                           ("generator_angle", "Generator rotor angle from the rotor FMU (torques.generator.angle) [rad]")]:
            self.register_variable(Real(name, causality=Fmi2Causality.input, description=text))
        for name, text in [("turbine_torque", "Turbine torque on the runner, about +z [N.m]"),
                           ("generator_torque", "Torque on the generator rotor, about +z: minus the air-gap and brake torques [N.m]"),
                           ("electric_torque", "Air-gap (electromagnetic) torque T_e, positive braking [N.m]"),
                           ("gate", "Gate opening [1]"), ("setpoint", "Speed set point [rad/s]"),
                           ("load_angle", "Electrical load angle delta [rad]"),
                           ("breaker", "Generator breaker: 1 closed, 0 open [1]")]:
            self.register_variable(Real(name, causality=Fmi2Causality.output, description=text))
        self.started = False
        self.theta = 0.0
        self.closed_at = -1.0
        self.load_from = -1.0
        self._input_time = 0.0

    # -- the generator and the sequence of events -------------------------
    def _delta(self, t, angle):
        return self.pole_pairs * (angle - self.rated_speed * t) - self.theta

    def _faulted(self, t):
        return 0.0 <= self.fault_time <= t < self.fault_time + self.fault_duration

    def _connected(self, t):
        """Breaker closed at time t (synchronized and not yet tripped)."""
        if self.closed_at < 0.0 or t < self.closed_at:
            return False
        for trip in (self.rejection_time, self.shutdown_time):
            if 0.0 <= trip <= t:
                return False
        return not (self.fault_time >= 0.0 and t >= self.fault_time + self.fault_duration)

    def _air_gap(self, t, speed, angle):
        w0 = self.rated_speed
        if self._faulted(t):
            tau = t - self.fault_time
            peak = self.emf ** 2 / self.subtransient_reactance
            return self.rated_torque * peak * math.exp(-tau / self.armature_time) * math.sin(self.pole_pairs * w0 * tau)
        if not self._connected(t):
            return 0.0
        delta = self._delta(t, angle)
        return self.rated_torque * (self.pullout * math.sin(delta) + self.damping * (speed - w0) / w0)

    def _brake(self, t, speed):
        stopping = 0.0 <= self.shutdown_time <= t
        if not (stopping and speed <= self.brake_speed * self.rated_speed):
            return 0.0
        return self.brake_torque * self.rated_torque * max(-1.0, min(1.0, speed / self.brake_smoothing))

    def _plan(self, t):
        """(speed set point, load set point, stopping) at time t."""
        w0 = self.rated_speed
        stopping = 0.0 <= self.shutdown_time <= t
        if stopping:
            return 0.0, 0.0, True
        if self._connected(t):
            ramp = 1.0 if self.load_ramp_time <= 0 else min(1.0, (t - self.load_from) / self.load_ramp_time)
            return w0, self.load * ramp, False
        top = w0 * (1.0 + self.sync_slip) if self.sync_time >= 0.0 and self.closed_at < 0.0 else w0
        ramp = min(1.0, t / self.ramp_time) if self.ramp_time > 0 else 1.0
        return self.start_speed + (top - self.start_speed) * ramp, 0.0, False

    def _rates(self, t, state):
        gate, integral = state
        ref, p_load, stopping = self._plan(t)
        return gate_rates(self, ref, self.generator_speed, p_load, integral, gate, stopping)

    def _settling(self, t):
        """Scale of a connected start's torques: (1 − cos(π t/settle_time))/2 up to settle_time, then 1."""
        if self.connected < 0.5 or self.settle_time <= 0.0 or t >= self.settle_time:
            return 1.0
        return 0.5 * (1.0 - math.cos(math.pi * t / self.settle_time))

    def _outputs(self, t):
        angle = self.generator_angle + self.generator_speed * (t - self._input_time)
        scale = self._settling(t)
        self.turbine_torque = scale * turbine_torque(self, self.gate, self.turbine_speed)
        self.electric_torque = scale * self._air_gap(t, self.generator_speed, angle)
        self.generator_torque = -(self.electric_torque + self._brake(t, self.generator_speed))
        self.setpoint = self._plan(t)[0]
        self.load_angle = self._delta(t, angle)
        self.breaker = 1.0 if self._connected(t) else 0.0

    def exit_initialization_mode(self):
        self._input_time = 0.0
        if self.connected >= 0.5:
            # In the steady state of `load`: the air gap balances the load.
            self.closed_at = 0.0
            self.load_from = -math.inf  # at full load from the start
            self.theta = -math.asin(min(1.0, self.load / self.pullout))
            self.gate = self.load + self.loss
            self.turbine_speed = self.generator_speed = self.start_speed
        else:
            self.theta = self.grid_phase
            # Running at no load (speed-no-load gate), or at rest with the gate shut.
            self.gate = self.loss if self.start_speed > 0.5 * self.rated_speed else 0.0
        self._outputs(0.0)
        self.started = True

    def do_step(self, current_time, step_size):
        self._input_time = current_time
        t_end = current_time + step_size
        (self.gate, self.integral), _ = rk4(self._rates, current_time, (self.gate, self.integral), step_size,
                                            lambda s: (min(1.0, max(0.0, s[0])), s[1]))
        if self.closed_at < 0.0 and 0.0 <= self.sync_time <= t_end and not (0.0 <= self.shutdown_time <= t_end):
            angle = self.generator_angle + self.generator_speed * step_size
            delta = self._delta(t_end, angle)
            wrapped = math.atan2(math.sin(delta), math.cos(delta))
            slip = self.generator_speed / self.rated_speed - 1.0
            if abs(wrapped) <= self.sync_angle and abs(slip) <= self.sync_slip_limit:
                self.closed_at = self.load_from = t_end
                self.theta += delta - wrapped  # δ continues from its wrapped value
        self._outputs(t_end)
        return True
