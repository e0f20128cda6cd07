//! CSV tables of analysis results, one function per report, each returning the
//! whole file text (header line first, `\n` line ends). Column names carry their
//! SI unit; speeds are also given in rpm.

use crate::analysis::torsion::TorsionalMode;
use std::f64::consts::PI;
use std::fmt::Write as _;

use crate::analysis::campbell::CampbellPoint;
use crate::analysis::modal::Mode;
use crate::analysis::operating_point::BearingOperatingPoint;
use crate::analysis::shapes::node_orbits;
use crate::analysis::stability::Stability;
use crate::analysis::ucs::CriticalSpeedMap;
use crate::analysis::unbalance::UnbalanceSweep;
use crate::bearing::coefficients::DimensionlessPoint;
use crate::model::RotorModel;
use crate::solver::Outputs;
use crate::units::{Amplitude, RAD_S_TO_RPM};

/// The shaft's section loads (`analysis::shaft_loads`) as CSV: one row per
/// element end, bending moments (N·m) in the x–z and y–z planes, shear (N)
/// and the outer-fibre bending stress (Pa).
pub fn shaft_loads(loads: &[crate::analysis::shaft_loads::SectionLoad]) -> String {
    let mut out = String::from(
        "element,node,z_m,moment_xz_Nm,moment_yz_Nm,moment_Nm,shear_x_N,shear_y_N,bending_stress_Pa\n",
    );
    for l in loads {
        writeln!(
            out,
            "{},{},{},{:e},{:e},{:e},{:e},{:e},{:e}",
            l.element + 1,
            l.node + 1,
            l.z,
            l.moment[0],
            l.moment[1],
            l.moment_magnitude,
            l.shear[0],
            l.shear[1],
            l.stress
        )
        .expect("writing to a String cannot fail");
    }
    out
}

/// Node displacements `q` (`4·node + k`: x, y in m; rx, ry in rad) at the nodes
/// at axial positions `node_z` (m); nodes numbered from 1.
pub fn static_deflection(node_z: &[f64], q: &[f64]) -> String {
    let mut out = String::from("node,z_m,x_m,y_m,rx_rad,ry_rad\n");
    for (i, z) in node_z.iter().enumerate() {
        let d = &q[4 * i..4 * i + 4];
        writeln!(
            out,
            "{},{z},{:e},{:e},{:e},{:e}",
            i + 1,
            d[0],
            d[1],
            d[2],
            d[3]
        )
        .ok();
    }
    out
}

/// Complex modes at spin speed `rpm`: damped frequency (rad/s, Hz), natural
/// frequency, damping ratio, logarithmic decrement and whirl.
pub fn modes(rpm: f64, modes: &[Mode]) -> String {
    let mut out = String::from(
        "mode,speed_rpm,damped_frequency_rad_s,damped_frequency_hz,natural_frequency_rad_s,damping_ratio,log_decrement,whirl\n",
    );
    for (k, m) in modes.iter().enumerate() {
        let f = m.damped_frequency / (2.0 * PI);
        writeln!(
            out,
            "{},{rpm},{},{f},{},{},{},{}",
            k + 1,
            m.damped_frequency,
            m.natural_frequency,
            m.damping_ratio,
            m.log_decrement,
            m.whirl.label()
        )
        .ok();
    }
    out
}

/// A Campbell diagram: one line per speed and mode; `mode` is the rank by
/// frequency at that speed, `branch` the tracked branch (both from 1).
pub fn campbell(diagram: &[CampbellPoint]) -> String {
    let mut out = String::from(
        "speed_rpm,speed_rad_s,mode,damped_frequency_rad_s,damped_frequency_hz,damping_ratio,log_decrement,whirl,branch\n",
    );
    for p in diagram {
        for (k, m) in p.modes.iter().enumerate() {
            writeln!(
                out,
                "{},{},{},{},{},{},{},{},{}",
                p.speed * RAD_S_TO_RPM,
                p.speed,
                k + 1,
                m.damped_frequency,
                m.damped_frequency / (2.0 * PI),
                m.damping_ratio,
                m.log_decrement,
                m.whirl.label(),
                m.branch + 1
            )
            .ok();
        }
    }
    out
}

/// Dimensionless bearing coefficients against load: load (N), eccentricity
/// ratio, attitude angle (°), `K̄ = K C/W` and `C̄ = C ω C/W`.
pub fn coefficients(curve: &[DimensionlessPoint]) -> String {
    let mut out = String::from(
        "load_N,eccentricity,attitude_deg,Kxx_bar,Kxy_bar,Kyx_bar,Kyy_bar,Cxx_bar,Cxy_bar,Cyx_bar,Cyy_bar\n",
    );
    for p in curve {
        let (k, c) = (p.stiffness, p.damping);
        writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{},{}",
            p.load,
            p.eccentricity,
            p.attitude_angle.to_degrees(),
            k[0],
            k[1],
            k[2],
            k[3],
            c[0],
            c[1],
            c[2],
            c[3]
        )
        .ok();
    }
    out
}

/// Simulation outputs of `model`: time, speed, spin angle; per bearing the
/// journal position (m), force (N), eccentricity ratio, friction torque (N·m),
/// contact normal force (N) and minimum film thickness (m); per probe the
/// position (m); the total friction torque; then, for every bearing, rub and
/// seal on a pedestal, the journal position relative to the housing (m, what
/// a proximity probe on the bearing reads) and the housing's absolute
/// position (m) and velocity (m/s, what a seismic sensor on it reads); for a
/// torque-driven shaft each torque node's speed (rpm) and angle (rad) and
/// each shaft element's torque (N·m); each thrust bearing's friction torque
/// (N·m) and power loss (W); each bearing's, rub's, seal's and pull's power
/// loss (W) and the total power loss (W).
pub fn simulation(model: &RotorModel, records: &[Outputs]) -> String {
    let mut out = String::from("time_s,speed_rpm,spin_angle_rad");
    for b in &model.bearings {
        let n = &b.name;
        write!(
            out,
            ",{n}_x_m,{n}_y_m,{n}_fx_N,{n}_fy_N,{n}_eccentricity,{n}_friction_torque_Nm,{n}_contact_force_N,{n}_min_film_thickness_m"
        )
        .ok();
    }
    for p in &model.probes {
        write!(out, ",{0}_x_m,{0}_y_m", p.name).ok();
    }
    out.push_str(",friction_torque_Nm");
    let on_pedestal: Vec<usize> = (0..model.bearings.len())
        .filter(|&k| model.bearings[k].pedestal.is_some())
        .collect();
    for &k in &on_pedestal {
        let n = &model.bearings[k].name;
        write!(
            out,
            ",{n}_x_rel_m,{n}_y_rel_m,{n}_housing_x_m,{n}_housing_y_m,{n}_housing_vx_m_s,{n}_housing_vy_m_s"
        )
        .ok();
    }
    // A torque-driven shaft: each torque node's speed and angle, each shaft
    // element's torque; and the thrust bearings' friction.
    let torque_driven = model.drive == crate::model::Drive::Torque;
    if torque_driven {
        for t in &model.torques {
            write!(out, ",{0}_speed_rpm,{0}_angle_rad", t.name).ok();
        }
        for k in 0..model.elements.len() {
            write!(out, ",shaft_torque_{}_Nm", k + 1).ok();
        }
    }
    for t in &model.thrust_bearings {
        write!(out, ",{0}_friction_torque_Nm,{0}_power_loss_W", t.name).ok();
    }
    // The power each bearing, rub, seal and pull dissipates, and the total
    // (with the thrust bearings'): the parts add up to the total.
    for b in &model.bearings {
        write!(out, ",{}_power_loss_W", b.name).ok();
    }
    out.push_str(",power_loss_W\n");
    for o in records {
        write!(
            out,
            "{},{},{}",
            o.time,
            o.speed * RAD_S_TO_RPM,
            o.spin_angle
        )
        .ok();
        for b in &o.bearings {
            write!(
                out,
                ",{:e},{:e},{:e},{:e},{},{},{},{:e}",
                b.x,
                b.y,
                b.fx,
                b.fy,
                b.report.eccentricity,
                b.report.friction_torque,
                b.report.contact_force,
                b.report.min_film_thickness
            )
            .ok();
        }
        for p in &o.probes {
            write!(out, ",{:e},{:e}", p.x, p.y).ok();
        }
        write!(out, ",{}", o.friction_torque).ok();
        for &k in &on_pedestal {
            let b = &o.bearings[k];
            let (x, y) = b.relative();
            let h = &b.housing;
            write!(
                out,
                ",{x:e},{y:e},{:e},{:e},{:e},{:e}",
                h.x, h.y, h.vx, h.vy
            )
            .ok();
        }
        if torque_driven {
            for t in &o.torques {
                write!(out, ",{},{}", t.speed * RAD_S_TO_RPM, t.angle).ok();
            }
            for torque in &o.shaft_torques {
                write!(out, ",{torque}").ok();
            }
        }
        for t in &o.thrust_bearings {
            write!(out, ",{},{}", t.friction_torque, t.power_loss).ok();
        }
        for b in &o.bearings {
            write!(out, ",{}", b.report.power_loss).ok();
        }
        writeln!(out, ",{}", o.power_loss).ok();
    }
    out
}

/// Column stem of a response point: `probe disk` → `probe_disk`.
pub fn column_stem(label: &str) -> String {
    label.replace(' ', "_")
}

/// An unbalance response sweep: speed (rpm, rad/s), then per point the x and y
/// amplitudes `|X|`, `|Y|` (m) and phases `arg X`, `arg Y` (°, with
/// `x(t) = |X| cos(Ωt + arg X)`, spin angle `Ωt` from +x toward +y), and the
/// major semi-axis of the orbit (m). With [`Amplitude::PeakToPeak`] the three
/// amplitudes are doubled and their columns say so: `…_x_amplitude_pk_pk_m`,
/// `…_y_amplitude_pk_pk_m` and `…_major_axis_pk_pk_m` (the orbit's major
/// axis, peak to peak).
pub fn unbalance(sweep: &UnbalanceSweep, amplitude: Amplitude) -> String {
    response_table(sweep, None, amplitude)
}

/// The response to one harmonic force over speed: as [`unbalance`], with
/// the force's frequency (Hz) after the speed; the phases are of
/// `x(t) = |X| cos(ωt + φ)` at the force's own frequency `ω`.
pub fn forced(frequencies: &[f64], sweep: &UnbalanceSweep) -> String {
    response_table(sweep, Some(frequencies), Amplitude::ZeroToPeak)
}

/// The table of [`unbalance`] and [`forced`]: speed, the excitation
/// frequency (Hz) when given (rad/s per speed), then per point the
/// amplitude and phase of x and y and the major semi-axis (or, peak to
/// peak, twice the amplitudes and the major axis).
fn response_table(
    sweep: &UnbalanceSweep,
    frequencies: Option<&[f64]>,
    amplitude: Amplitude,
) -> String {
    let mut out = String::from("speed_rpm,speed_rad_s");
    if frequencies.is_some() {
        out.push_str(",frequency_hz");
    }
    let (size, major) = match amplitude {
        Amplitude::ZeroToPeak => ("amplitude_m", "major_semi_axis_m"),
        Amplitude::PeakToPeak => ("amplitude_pk_pk_m", "major_axis_pk_pk_m"),
    };
    let factor = amplitude.factor();
    for p in &sweep.points {
        let n = column_stem(&p.label);
        write!(
            out,
            ",{n}_x_{size},{n}_x_phase_deg,{n}_y_{size},{n}_y_phase_deg,{n}_{major}"
        )
        .ok();
    }
    out.push('\n');
    for (k, (speed, row)) in sweep.speeds.iter().zip(&sweep.response).enumerate() {
        write!(out, "{},{speed}", speed * RAD_S_TO_RPM).ok();
        if let Some(w) = frequencies {
            write!(out, ",{}", w[k] / (2.0 * PI)).ok();
        }
        for &(x, y) in row {
            write!(
                out,
                ",{:e},{},{:e},{},{:e}",
                factor * x.norm(),
                x.arg().to_degrees(),
                factor * y.norm(),
                y.arg().to_degrees(),
                factor * crate::analysis::unbalance::major_semi_axis((x, y))
            )
            .ok();
        }
        out.push('\n');
    }
    out
}

/// Bearings at an operating point, one row each: load and force (N), journal
/// position (m), eccentricity ratio, attitude angle (°), minimum film thickness
/// (m), friction torque (N·m), power loss (W) (empty for linear bearings; the
/// eccentricity, attitude and film thickness empty for table bearings), then
/// K (N/m) and C (N·s/m) row-major, and last a tilting-pad bearing's `e/C_p`
/// over its pad clearance (its `eccentricity` is `e/C_b`; empty for other
/// kinds).
pub fn operating_point(rpm: f64, points: &[BearingOperatingPoint]) -> String {
    let mut out = String::from(
        "speed_rpm,bearing,load_N,fx_N,fy_N,x_m,y_m,eccentricity,attitude_angle_deg,min_film_thickness_m,friction_torque_Nm,power_loss_W,kxx_N_m,kxy_N_m,kyx_N_m,kyy_N_m,cxx_Ns_m,cxy_Ns_m,cyx_Ns_m,cyy_Ns_m,eccentricity_pad_clearance\n",
    );
    for p in points {
        write!(
            out,
            "{rpm},{},{},{},{},{:e},{:e}",
            p.name, p.load, p.force[0], p.force[1], p.journal[0], p.journal[1]
        )
        .ok();
        match &p.film {
            Some(f) if !f.has_geometry() => {
                write!(out, ",,,,{},{}", f.friction_torque, f.power_loss)
            }
            Some(f) => write!(
                out,
                ",{},{},{:e},{},{}",
                f.eccentricity,
                f.attitude_angle.to_degrees(),
                f.min_film_thickness,
                f.friction_torque,
                f.power_loss
            ),
            None => write!(out, ",,,,,"),
        }
        .ok();
        for v in p.stiffness.iter().chain(&p.damping).flatten() {
            write!(out, ",{v}").ok();
        }
        // e/C_p of a tilting-pad bearing (its `eccentricity` is e/C_b).
        out.push(',');
        if let Some(e) = p
            .film
            .as_ref()
            .and_then(|f| f.eccentricity_over_pad_clearance())
        {
            write!(out, "{e}").ok();
        }
        out.push('\n');
    }
    out
}

/// The pads of the tilting-pad bearings at an operating point: pivot angle
/// (°), tilt `η = ψR` (m), tilt angle `ψ` (rad) and minimum film thickness (m).
pub fn operating_pads(points: &[BearingOperatingPoint]) -> String {
    let mut out =
        String::from("bearing,pad,pivot_deg,tilt_m,tilt_angle_rad,min_film_thickness_m\n");
    for p in points {
        for (k, pad) in p.film.iter().flat_map(|f| f.pads.iter()).enumerate() {
            writeln!(
                out,
                "{},{},{},{:e},{:e},{:e}",
                p.name,
                k + 1,
                pad.pivot.to_degrees(),
                pad.tilt,
                pad.tilt_angle,
                pad.min_film_thickness
            )
            .ok();
        }
    }
    out
}

/// Complex mode shapes, one row per mode and node: the mode's damped frequency
/// (Hz), logarithmic decrement and whirl, then per node its axial position (m),
/// `X` and `Y` (real and imaginary parts; the shape is scaled so that its
/// largest translation is exactly `1 + 0i`), the forward and backward whirl
/// radii, the semi-axes and direction (°) of its orbit ellipse and the node's
/// own whirl direction (`analysis::shapes`).
pub fn mode_shapes(model: &RotorModel, modes: &[Mode]) -> String {
    let mut out = String::from(
        "mode,damped_frequency_hz,log_decrement,mode_whirl,node,z_m,x_re,x_im,y_re,y_im,forward_radius,backward_radius,major_semi_axis,minor_semi_axis,major_axis_deg,node_whirl\n",
    );
    for (k, m) in modes.iter().enumerate() {
        for o in node_orbits(model, m) {
            writeln!(
                out,
                "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                k + 1,
                m.damped_frequency / (2.0 * PI),
                m.log_decrement,
                m.whirl.label(),
                o.node + 1,
                o.z,
                o.x.re,
                o.x.im,
                o.y.re,
                o.y.im,
                o.forward,
                o.backward,
                o.major,
                o.minor,
                o.major_angle.to_degrees(),
                o.direction()
            )
            .ok();
        }
    }
    out
}

/// Torsional mode shapes: per mode its undamped natural frequency (Hz),
/// damping ratio and damped frequency (Hz), per node its position and twist
/// (rad, the largest twist 1; the undamped shape).
pub fn torsional_mode_shapes(model: &RotorModel, modes: &[TorsionalMode]) -> String {
    let mut out = String::from(
        "mode,natural_frequency_hz,damping_ratio,damped_frequency_hz,node,z_m,twist\n",
    );
    for (k, m) in modes.iter().enumerate() {
        for (node, twist) in m.shape.iter().enumerate() {
            writeln!(
                out,
                "{},{},{},{},{},{},{}",
                k + 1,
                m.natural_frequency / (2.0 * PI),
                m.damping_ratio,
                m.damped_frequency() / (2.0 * PI),
                node + 1,
                model.node_z[node],
                twist
            )
            .ok();
        }
    }
    out
}

/// The least stable forward mode against the added cross-coupled stiffness `Q` (N/m):
/// damped frequency (Hz), damping ratio and logarithmic decrement.
pub fn stability(result: &Stability) -> String {
    let mut out =
        String::from("cross_coupling_N_m,damped_frequency_hz,damping_ratio,log_decrement\n");
    for (q, m) in &result.curve {
        writeln!(
            out,
            "{q},{},{},{}",
            m.damped_frequency / (2.0 * PI),
            m.damping_ratio,
            m.log_decrement
        )
        .ok();
    }
    out
}

/// API 617 Level II: one row per judged forward mode of each case (`as_built`,
/// `with_Q_A`), its added cross-coupling (N/m), damped frequency (Hz) and
/// log decrement, and the case's verdict; a case that diverges statically
/// adds a row `static_divergence` with the growth rate (1/s) in place of the
/// frequency and no log decrement.
pub fn level_two(l: &crate::analysis::level_two::LevelTwo) -> String {
    let mut out = String::from(
        "case,speed_rpm,cross_coupling_N_m,mode,damped_frequency_hz,log_decrement,verdict\n",
    );
    let rpm = l.speed.abs() * RAD_S_TO_RPM;
    let cases = std::iter::once(("as_built", &l.as_built))
        .chain(l.anticipated.as_ref().map(|(_, _, c)| ("with_Q_A", c)));
    for (name, case) in cases {
        let verdict = if case.pass() { "pass" } else { "FAIL" };
        for (k, m) in case.modes.iter().enumerate() {
            writeln!(
                out,
                "{name},{rpm},{},{},{},{},{verdict}",
                case.cross_coupling,
                k + 1,
                m.damped_frequency / (2.0 * PI),
                m.log_decrement
            )
            .ok();
        }
        for root in &case.diverging {
            writeln!(
                out,
                "{name},{rpm},{},static_divergence,{},,{verdict}",
                case.cross_coupling,
                -root.decay_rate()
            )
            .ok();
        }
    }
    out
}

/// A critical speed map: per support stiffness (N/m) the forward synchronous
/// critical speeds in rpm (`critical_k_rpm`, increasing; empty where fewer
/// exist) and the number of statically unstable modes (none where any).
pub fn critical_speed_map(map: &CriticalSpeedMap) -> String {
    let count = map.speeds.iter().map(Vec::len).max().unwrap_or(0);
    let mut out = String::from("support_stiffness_N_m");
    for k in 1..=count {
        write!(out, ",critical_{k}_rpm").ok();
    }
    out.push_str(",statically_unstable_modes\n");
    for ((k, speeds), unstable) in map.stiffness.iter().zip(&map.speeds).zip(&map.unstable) {
        write!(out, "{k}").ok();
        for j in 0..count {
            match speeds.get(j) {
                Some(s) => write!(out, ",{}", s * RAD_S_TO_RPM),
                None => write!(out, ","),
            }
            .ok();
        }
        writeln!(out, ",{unstable}").ok();
    }
    out
}

/// The bearings' direct stiffness over speed: bearing, speed (rpm), kxx, kyy (N/m).
pub fn bearing_stiffness(map: &CriticalSpeedMap) -> String {
    let mut out = String::from("bearing,speed_rpm,kxx_N_m,kyy_N_m\n");
    for b in &map.bearings {
        for (s, kxx, kyy) in &b.points {
            writeln!(out, "{},{},{kxx},{kyy}", b.name, s * RAD_S_TO_RPM).ok();
        }
    }
    out
}

#[cfg(test)]
mod tests;
