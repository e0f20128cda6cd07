"""The governor, gate servo and Francis turbine shared by the plant FMUs
(system/hydro_plant.py, speed-driven; system/hydro_plant_torque.py,
torque-driven). Per unit on the rated speed ω_r and the rated torque T_r:

    governor: gate command = p_load + loss + Kp e + Ki ∫e,  e = (ω_ref − ω)/ω_r,
              integral frozen while the command saturates (anti-windup)
    gate servo: dg/dt = (command − g)/T_servo, |dg/dt| ≤ rate limit, 0 ≤ g ≤ 1
    turbine: T_t = T_r [g (2 − ω/ω_r) − loss (ω/ω_r)²]   (Francis-like; windage
             and water friction make a closed gate decelerate the unit)
"""


def gate_rates(p, ref, speed, p_load, integral, gate, stopping):
    """(dg/dt, d∫e/dt) of the gate servo and the governor's integral; `p`
    holds rated_speed, loss, kp, ki, servo_time, gate_rate."""
    error = (ref - speed) / p.rated_speed
    raw = p_load + p.loss + p.kp * error + p.ki * integral
    command = 0.0 if stopping else min(1.0, max(0.0, raw))
    # Anti-windup: the integral stops where the command saturates.
    windup = (raw <= 0.0 and error < 0.0) or (raw >= 1.0 and error > 0.0)
    dgate = max(-p.gate_rate, min(p.gate_rate, (command - gate) / p.servo_time))
    if (gate <= 0.0 and dgate < 0.0) or (gate >= 1.0 and dgate > 0.0):
        dgate = 0.0
    return dgate, 0.0 if (windup or stopping) else error


def turbine_torque(p, gate, speed):
    """Francis turbine torque at gate opening `gate` and runner speed `speed` (N·m)."""
    w0 = p.rated_speed
    return p.rated_torque * (gate * (2.0 - speed / w0) - p.loss * (speed / w0) ** 2)


def rk4(rates, t, state, step_size, clamp, max_step=0.005):
    """Integrate d(state)/dt = rates(t, state) over one communication step with
    classical Runge–Kutta in sub-steps of at most `max_step`, `clamp(state)`
    applied after each (bounds such as 0 ≤ g ≤ 1); returns the new state and
    the end time. `rates` returns a tuple as long as `state`."""
    n = max(1, int(step_size / max_step + 0.999))
    h = step_size / n
    s = tuple(state)
    for _ in range(n):
        k1 = rates(t, s)
        k2 = rates(t + h / 2, tuple(x + h / 2 * k for x, k in zip(s, k1)))
        k3 = rates(t + h / 2, tuple(x + h / 2 * k for x, k in zip(s, k2)))
        k4 = rates(t + h, tuple(x + h * k for x, k in zip(s, k3)))
        s = clamp(tuple(x + h / 6 * (a + 2 * b + 2 * c + d) for x, a, b, c, d in zip(s, k1, k2, k3, k4)))
        t += h
    return s, t
