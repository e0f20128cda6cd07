//! The FMU state (`fmi2FMUstate`): everything `fmi2GetFMUstate` saves, and its
//! byte image for `fmi2SerializeFMUstate`.
//!
//! One field list, `SCALARS` and `VECTORS`, declares what a state holds;
//! serialization, deserialization and the shape check before `fmi2SetFMUstate`
//! all walk it, so a field cannot be saved but forgotten on reading.
//!
//! Byte image (little-endian): [`MAGIC`], the format [`VERSION`] (u64), the
//! model fingerprint (u64, FNV-1a of the GUID), every scalar as f64, every
//! vector as its length (u64) and its f64 values, and an FNV-1a checksum (u64)
//! of all bytes before it. A state of another model, another format version, a
//! truncated or altered buffer is refused with a message, never a panic.

use crate::model::MAX_REDUCED_MODES;
use crate::solver::SimState;
use crate::solver::reduction_check::ValidityWatch;
use crate::units::Short;

use super::instance::Params;
use super::states::Phase;

/// Everything `fmi2GetFMUstate` saves.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// The simulator state.
    pub(super) sim: SimState,
    /// The solver parameters.
    pub(super) params: Params,
    /// The (possibly tuned) viscosity (Pa·s) or field excitation of each model
    /// bearing (0 where the bearing has none).
    pub(super) tuned: Vec<f64>,
    /// The state-machine phase.
    pub(super) phase: Phase,
    /// The model fingerprint ([`fingerprint`] of the GUID).
    pub(super) fingerprint: u64,
    /// The reduced rotor's validity watch ([`ValidityWatch::image`]): its
    /// warnings are part of the state.
    ///
    /// [`ValidityWatch::image`]: crate::solver::reduction_check::ValidityWatch::image
    pub(super) watch: Vec<f64>,
}

/// Start of every serialized state.
pub const MAGIC: &[u8; 8] = b"RBFMUst\0";
/// Format version of the byte image (1 was the unversioned `RBFMU01` image;
/// 3 added the step and speed of the factorization in hand, 4 the reduced
/// rotor's mode count, 5 the load inputs of forces and ports and the
/// torsional state of a torque-driven shaft, 6 the initial speed of a
/// torque-driven shaft and each bearing's tuned value, the field excitation
/// of a magnetic pull beside the viscosities, 7 the local error tolerance and
/// the step proposal and previous accelerations of accuracy-controlled steps,
/// 8 which contact and coefficient-table warnings have been raised and the
/// reduced rotor's validity watch, 9 whether the pads are settled on their
/// own balance, 10 each bearing's static load, 11 each harmonic force's
/// phase and frequency, tunable in the FMU, 12 the steps left without chord
/// iterations).
pub const VERSION: u64 = 12;
/// Bytes before the fields: magic, version, fingerprint.
const HEADER: usize = MAGIC.len() + 8 + 8;
/// Bytes after the fields: the checksum.
const TRAILER: usize = 8;

/// A scalar field: name, read, write (`false` for a value outside the field's
/// domain).
type Scalar = (
    &'static str,
    fn(&Snapshot) -> f64,
    fn(&mut Snapshot, f64) -> bool,
);
/// A vector field: name, read, write access.
type Vector = (
    &'static str,
    fn(&Snapshot) -> &Vec<f64>,
    fn(&mut Snapshot) -> &mut Vec<f64>,
);

/// Index of a phase in [`Phase::ALL`], the form it is saved in.
fn phase_index(phase: Phase) -> f64 {
    Phase::ALL.iter().position(|p| *p == phase).unwrap_or(0) as f64
}

/// The scalar fields, in image order.
const SCALARS: [Scalar; 20] = [
    ("time", |s| s.sim.time, |s, v| put(&mut s.sim.time, v)),
    (
        "spin_angle",
        |s| s.sim.spin_angle,
        |s, v| put(&mut s.sim.spin_angle, v),
    ),
    ("speed", |s| s.sim.speed, |s, v| put(&mut s.sim.speed, v)),
    (
        "speed_rate",
        |s| s.sim.speed_rate,
        |s, v| put(&mut s.sim.speed_rate, v),
    ),
    (
        "speed_time",
        |s| s.sim.speed_time,
        |s, v| put(&mut s.sim.speed_time, v),
    ),
    (
        "time_step",
        |s| s.params.time_step,
        |s, v| put(&mut s.params.time_step, v),
    ),
    (
        "tolerance",
        |s| s.params.tolerance,
        |s, v| put(&mut s.params.tolerance, v),
    ),
    (
        "max_iterations",
        |s| f64::from(s.params.max_iterations),
        |s, v| {
            let ok = v.fract() == 0.0 && (1.0..=f64::from(i32::MAX)).contains(&v);
            if ok {
                s.params.max_iterations = v as i32;
            }
            ok
        },
    ),
    (
        "ramp_time",
        |s| s.params.ramp_time,
        |s, v| put(&mut s.params.ramp_time, v),
    ),
    (
        "gravity",
        |s| f64::from(u8::from(s.params.gravity)),
        |s, v| {
            s.params.gravity = v == 1.0;
            v == 0.0 || v == 1.0
        },
    ),
    (
        "reduced_modes",
        |s| f64::from(s.params.reduced_modes),
        |s, v| {
            let ok = v.fract() == 0.0 && (0.0..=MAX_REDUCED_MODES as f64).contains(&v);
            if ok {
                s.params.reduced_modes = v as i32;
            }
            ok
        },
    ),
    (
        "initial_speed",
        |s| s.params.initial_speed,
        |s, v| put(&mut s.params.initial_speed, v),
    ),
    (
        "phase",
        |s| phase_index(s.phase),
        |s, v| match Phase::ALL.get(v as usize) {
            Some(&p) if v.fract() == 0.0 && v >= 0.0 => {
                s.phase = p;
                true
            }
            _ => false,
        },
    ),
    (
        "factor_step",
        |s| s.sim.factor_step,
        |s, v| {
            s.sim.factor_step = v;
            v.is_finite() && v >= 0.0
        },
    ),
    (
        "factor_speed",
        |s| s.sim.factor_speed,
        |s, v| {
            s.sim.factor_speed = v;
            v.is_finite()
        },
    ),
    (
        "stuck",
        |s| s.sim.stuck,
        |s, v| {
            s.sim.stuck = v;
            v == 0.0 || v == 1.0
        },
    ),
    (
        "local_error_tolerance",
        |s| s.params.local_error_tolerance,
        |s, v| {
            s.params.local_error_tolerance = v;
            v.is_finite() && v >= 0.0
        },
    ),
    (
        "step_proposal",
        |s| s.sim.step_proposal,
        |s, v| {
            s.sim.step_proposal = v;
            v.is_finite() && v >= 0.0
        },
    ),
    (
        "pad_balancing",
        |s| s.sim.pad_balancing,
        |s, v| {
            s.sim.pad_balancing = v;
            v == 0.0 || v == 1.0
        },
    ),
    (
        "chord_pause",
        |s| s.sim.chord_pause,
        |s, v| {
            s.sim.chord_pause = v;
            // Its range is `SimState::check`'s, which names it.
            v.is_finite()
        },
    ),
];

/// The vector fields, in image order.
const VECTORS: [Vector; 23] = [
    ("u", |s| &s.sim.u, |s| &mut s.sim.u),
    ("ud", |s| &s.sim.ud, |s| &mut s.sim.ud),
    ("udd", |s| &s.sim.udd, |s| &mut s.sim.udd),
    ("p", |s| &s.sim.p, |s| &mut s.sim.p),
    ("pd", |s| &s.sim.pd, |s| &mut s.sim.pd),
    ("pdd", |s| &s.sim.pdd, |s| &mut s.sim.pdd),
    ("unbalance", |s| &s.sim.unbalance, |s| &mut s.sim.unbalance),
    (
        "unbalance_rate",
        |s| &s.sim.unbalance_rate,
        |s| &mut s.sim.unbalance_rate,
    ),
    (
        "unbalance_phase",
        |s| &s.sim.unbalance_phase,
        |s| &mut s.sim.unbalance_phase,
    ),
    ("tuned", |s| &s.tuned, |s| &mut s.tuned),
    ("loads", |s| &s.sim.loads, |s| &mut s.sim.loads),
    (
        "load_rates",
        |s| &s.sim.load_rates,
        |s| &mut s.sim.load_rates,
    ),
    ("twist", |s| &s.sim.twist, |s| &mut s.sim.twist),
    (
        "twist_rate",
        |s| &s.sim.twist_rate,
        |s| &mut s.sim.twist_rate,
    ),
    (
        "twist_accel",
        |s| &s.sim.twist_accel,
        |s| &mut s.sim.twist_accel,
    ),
    (
        "twist_torque",
        |s| &s.sim.twist_torque,
        |s| &mut s.sim.twist_torque,
    ),
    (
        "udd_previous",
        |s| &s.sim.udd_previous,
        |s| &mut s.sim.udd_previous,
    ),
    (
        "contact_reported",
        |s| &s.sim.contact_reported,
        |s| &mut s.sim.contact_reported,
    ),
    (
        "table_warned",
        |s| &s.sim.table_warned,
        |s| &mut s.sim.table_warned,
    ),
    ("validity_watch", |s| &s.watch, |s| &mut s.watch),
    (
        "static_load",
        |s| &s.sim.static_load,
        |s| &mut s.sim.static_load,
    ),
    (
        "harmonic_phase",
        |s| &s.sim.harmonic_phase,
        |s| &mut s.sim.harmonic_phase,
    ),
    (
        "harmonic_frequency",
        |s| &s.sim.harmonic_frequency,
        |s| &mut s.sim.harmonic_frequency,
    ),
];

/// The vector of the run's history, of any length its own check accepts.
const HISTORY: &str = "validity_watch";
/// The most samples a validity watch holds in a state read back (a watch
/// keeps a window of a few revolutions).
const HISTORY_SAMPLES: u64 = 1 << 20;

/// Store a real field (any f64 is in its domain; the simulator checks values).
fn put(slot: &mut f64, v: f64) -> bool {
    *slot = v;
    true
}

/// FNV-1a 64-bit hash.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The fingerprint of a model: FNV-1a of its GUID.
pub fn fingerprint(guid: &str) -> u64 {
    fnv1a(guid.as_bytes())
}

/// Reads little-endian words from a byte image, failing on a short buffer.
struct Reader<'a> {
    bytes: &'a [u8],
}

impl Reader<'_> {
    /// The next 8 bytes.
    fn word(&mut self) -> Result<[u8; 8], String> {
        let (head, rest) = self
            .bytes
            .split_first_chunk::<8>()
            .ok_or("truncated state")?;
        self.bytes = rest;
        Ok(*head)
    }

    /// The next u64.
    fn u64(&mut self) -> Result<u64, String> {
        self.word().map(u64::from_le_bytes)
    }

    /// The next f64.
    fn f64(&mut self) -> Result<f64, String> {
        self.word().map(f64::from_le_bytes)
    }
}

/// The vector fields sized by the rotor's coordinates, which depend on the
/// mode count of the reduced rotor (`solver.reduced_modes`).
const ROTOR_VECTORS: [&str; 3] = ["u", "ud", "udd"];
/// A rotor vector that is empty until accuracy-controlled steps fill it.
const ROTOR_OR_EMPTY: &str = "udd_previous";

impl Snapshot {
    /// `Ok` if this state fits an instance whose current state is `current`:
    /// the same model fingerprint, the rotor vectors of the `coordinates` the
    /// state's own `solver.reduced_modes` builds, every other vector as long as
    /// `current`'s.
    pub fn fits(&self, current: &Snapshot, coordinates: usize) -> Result<(), String> {
        if self.fingerprint != current.fingerprint {
            return Err(format!(
                "the state belongs to another model (fingerprint {:016x}, this model {:016x})",
                self.fingerprint, current.fingerprint
            ));
        }
        for (name, get, _) in VECTORS {
            let (n, m) = if ROTOR_VECTORS.contains(&name) {
                (get(self).len(), coordinates)
            } else if name == ROTOR_OR_EMPTY {
                let n = get(self).len();
                (n, if n == 0 { 0 } else { coordinates })
            } else if name == HISTORY {
                ValidityWatch::check_image(get(self))
                    .map_err(|e| format!("the state does not fit this model ({e})"))?;
                continue;
            } else {
                (get(self).len(), get(current).len())
            };
            if n != m {
                return Err(format!(
                    "the state does not fit this model ({name} has {n} values, this model {m} with solver.reduced_modes = {})",
                    self.params.reduced_modes
                ));
            }
        }
        Ok(())
    }

    /// The byte image (`fmi2SerializeFMUstate`).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = MAGIC.to_vec();
        out.extend_from_slice(&VERSION.to_le_bytes());
        out.extend_from_slice(&self.fingerprint.to_le_bytes());
        for (_, get, _) in SCALARS {
            out.extend_from_slice(&get(self).to_le_bytes());
        }
        for (_, get, _) in VECTORS {
            let v = get(self);
            out.extend_from_slice(&(v.len() as u64).to_le_bytes());
            for x in v {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
        let sum = fnv1a(&out);
        out.extend_from_slice(&sum.to_le_bytes());
        out
    }

    /// The state in a byte image (`fmi2DeSerializeFMUstate`), checked against
    /// `current`, the state of the instance reading it (model fingerprint and
    /// vector lengths); `coordinates` gives the rotor coordinates a mode count
    /// builds on this model (`None`: that count cannot reduce it).
    pub fn from_bytes(
        bytes: &[u8],
        current: &Snapshot,
        coordinates: impl Fn(i32) -> Option<usize>,
    ) -> Result<Snapshot, String> {
        if bytes.len() < HEADER + TRAILER || bytes[..MAGIC.len()] != MAGIC[..] {
            return Err("not a serialized state of this FMU".into());
        }
        let (body, sum) = bytes.split_at(bytes.len() - TRAILER);
        let mut r = Reader {
            bytes: &body[MAGIC.len()..],
        };
        let version = r.u64()?;
        if version != VERSION {
            return Err(format!(
                "state format version {version}, this FMU reads version {VERSION}"
            ));
        }
        if sum != fnv1a(body).to_le_bytes() {
            return Err("corrupt state (checksum mismatch)".into());
        }
        let mut snap = current.clone();
        snap.fingerprint = r.u64()?;
        if snap.fingerprint != current.fingerprint {
            return Err(format!(
                "the state belongs to another model (fingerprint {:016x}, this model {:016x})",
                snap.fingerprint, current.fingerprint
            ));
        }
        for (name, _, set) in SCALARS {
            let v = r.f64()?;
            if !set(&mut snap, v) {
                return Err(format!("corrupt state ({name} = {})", Short(v)));
            }
        }
        let modes = snap.params.reduced_modes;
        let n = coordinates(modes).ok_or_else(|| {
            format!("the state was saved with solver.reduced_modes = {modes}, which cannot reduce this model")
        })?;
        for (name, _, get_mut) in VECTORS {
            if ROTOR_VECTORS.contains(&name) {
                get_mut(&mut snap).resize(n, 0.0);
            }
        }
        for (name, _, get_mut) in VECTORS {
            let read = r.u64()?;
            if name == ROTOR_OR_EMPTY && (read == 0 || read == n as u64) {
                get_mut(&mut snap).resize(read as usize, 0.0);
            }
            if name == HISTORY && read <= 4 + 3 * HISTORY_SAMPLES {
                get_mut(&mut snap).resize(read as usize, 0.0);
            }
            let n = read;
            let expected = get_mut(&mut snap).len();
            if n != expected as u64 {
                return Err(format!(
                    "the state does not fit this model ({name} has {n} values, this model {expected} with solver.reduced_modes = {modes})"
                ));
            }
            for x in get_mut(&mut snap).iter_mut() {
                *x = r.f64()?;
            }
        }
        if !r.bytes.is_empty() {
            return Err(format!(
                "corrupt state ({} bytes after the last field)",
                r.bytes.len()
            ));
        }
        ValidityWatch::check_image(&snap.watch).map_err(|e| format!("corrupt state ({e})"))?;
        Ok(snap)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Snapshot {
        let v = |n: usize, x: f64| (0..n).map(|i| x + i as f64).collect::<Vec<_>>();
        Snapshot {
            sim: SimState {
                time: 0.25,
                u: v(8, 1.0),
                ud: v(8, 2.0),
                udd: v(8, 3.0),
                p: v(3, 4.0),
                pd: v(3, 5.0),
                pdd: v(3, 6.0),
                spin_angle: 7.0,
                speed: 8.0,
                speed_rate: 9.0,
                speed_time: 0.125,
                unbalance: v(2, 10.0),
                unbalance_rate: v(2, 11.0),
                unbalance_phase: v(2, 12.0),
                loads: v(3, 14.0),
                load_rates: v(3, 15.0),
                twist: v(4, 16.0),
                twist_rate: v(4, 17.0),
                twist_accel: v(4, 18.0),
                twist_torque: v(4, 19.0),
                stuck: 1.0,
                factor_step: 1e-3,
                factor_speed: 13.0,
                udd_previous: v(8, 20.0),
                contact_reported: vec![0.0, 1.0],
                table_warned: vec![1.0, 0.0],
                static_load: v(4, 22.0),
                harmonic_phase: v(1, 23.0),
                harmonic_frequency: v(1, 24.0),
                step_proposal: 2.5e-4,
                pad_balancing: 1.0,
                chord_pause: 7.0,
            },
            params: Params {
                time_step: 1e-3,
                tolerance: 1e-8,
                max_iterations: 17,
                ramp_time: 0.5,
                gravity: false,
                reduced_modes: 6,
                initial_speed: 21.0,
                local_error_tolerance: 3e-3,
            },
            tuned: v(2, 0.03),
            phase: Phase::StepFailed,
            fingerprint: fingerprint("{guid}"),
            watch: vec![1.0, 0.5, 2.0, 3.0, 0.1, 4.0, 5.0, 0.2, 6.0, 7.0],
        }
    }

    /// Every field changed, so a field skipped by the image would show.
    fn zeroed(s: &Snapshot) -> Snapshot {
        let mut z = s.clone();
        for (_, _, set) in SCALARS {
            set(&mut z, 1.0);
        }
        for (_, _, get_mut) in VECTORS {
            get_mut(&mut z).iter_mut().for_each(|x| *x = -1.0);
        }
        z
    }

    /// The rotor coordinates of the sample's model: 8 whatever the mode count.
    fn eight(_: i32) -> Option<usize> {
        Some(8)
    }

    #[test]
    fn image_round_trips_bit_for_bit() {
        let s = sample();
        let back = Snapshot::from_bytes(&s.to_bytes(), &zeroed(&s), eight).unwrap();
        assert_eq!(back, s);
        assert_eq!(back.to_bytes(), s.to_bytes());
    }

    #[test]
    fn every_truncation_and_bit_flip_is_refused() {
        let s = sample();
        let bytes = s.to_bytes();
        for n in 0..bytes.len() {
            assert!(
                Snapshot::from_bytes(&bytes[..n], &s, eight).is_err(),
                "{n} bytes"
            );
        }
        for i in 0..bytes.len() {
            for bit in 0..8 {
                let mut b = bytes.clone();
                b[i] ^= 1 << bit;
                assert!(
                    Snapshot::from_bytes(&b, &s, eight).is_err(),
                    "byte {i} bit {bit}"
                );
            }
        }
    }

    #[test]
    fn states_of_other_models_and_versions_are_refused() {
        let s = sample();
        let mut other = s.clone();
        other.fingerprint = fingerprint("{another}");
        let e = Snapshot::from_bytes(&other.to_bytes(), &s, eight).unwrap_err();
        assert!(e.contains("another model"), "{e}");
        assert!(other.fits(&s, 8).is_err());
        let mut longer = s.clone();
        longer.sim.u.push(0.0);
        let e = Snapshot::from_bytes(&longer.to_bytes(), &s, eight).unwrap_err();
        assert!(
            e.contains("u has 9 values, this model 8 with solver.reduced_modes = 6"),
            "{e}"
        );
        assert!(longer.fits(&s, 8).is_err());
        let mut shorter_pads = s.clone();
        shorter_pads.sim.p.pop();
        assert!(shorter_pads.fits(&s, 8).is_err());

        let mut v5 = s.to_bytes();
        v5[MAGIC.len()..MAGIC.len() + 8].copy_from_slice(&5u64.to_le_bytes());
        let e = Snapshot::from_bytes(&v5, &s, eight).unwrap_err();
        assert!(e.contains("version 5"), "{e}");
    }

    /// The previous accelerations of accuracy-controlled steps are empty until
    /// the first such step: a state with them empty or full fits an instance
    /// holding either, any other length is refused.
    #[test]
    fn previous_accelerations_are_empty_or_one_per_rotor_coordinate() {
        let full = sample();
        let mut empty = full.clone();
        empty.sim.udd_previous.clear();
        for (saved, current) in [(&empty, &full), (&full, &empty), (&empty, &empty)] {
            assert!(saved.fits(current, 8).is_ok());
            let back = Snapshot::from_bytes(&saved.to_bytes(), current, eight).unwrap();
            assert_eq!(&back, saved);
        }
        let mut odd = full.clone();
        odd.sim.udd_previous.truncate(5);
        assert!(odd.fits(&full, 8).is_err());
        let e = Snapshot::from_bytes(&odd.to_bytes(), &full, eight).unwrap_err();
        assert!(e.contains("udd_previous has 5 values"), "{e}");
    }

    /// A state saved with another mode count is read with the rotor vectors
    /// of the rotor that count builds, and refused where it cannot fit.
    #[test]
    fn states_of_other_mode_counts_are_read_at_their_size() {
        let s = sample();
        let mut reduced = s.clone();
        reduced.params.reduced_modes = 12;
        for v in [
            &mut reduced.sim.u,
            &mut reduced.sim.ud,
            &mut reduced.sim.udd,
            &mut reduced.sim.udd_previous,
        ] {
            v.extend([0.5, 0.25]);
        }
        let ten = |m: i32| Some(if m == 12 { 10 } else { 8 });
        let back = Snapshot::from_bytes(&reduced.to_bytes(), &s, ten).unwrap();
        assert_eq!(back, reduced);
        assert!(reduced.fits(&s, 10).is_ok() && reduced.fits(&s, 8).is_err());
        let e = Snapshot::from_bytes(&reduced.to_bytes(), &s, eight).unwrap_err();
        assert!(
            e.contains("u has 10 values, this model 8 with solver.reduced_modes = 12"),
            "{e}"
        );
        let e = Snapshot::from_bytes(&reduced.to_bytes(), &s, |_| None).unwrap_err();
        assert!(e.contains("reduced_modes = 12, which cannot reduce"), "{e}");
        let mut too_many = s.clone();
        too_many.params.reduced_modes = MAX_REDUCED_MODES as i32 + 1;
        let e = Snapshot::from_bytes(&too_many.to_bytes(), &s, eight).unwrap_err();
        assert!(e.contains("corrupt state (reduced_modes = 1001)"), "{e}");
    }

    #[test]
    fn out_of_domain_fields_are_refused() {
        let s = sample();
        let mut bytes = s.to_bytes();
        // The phase is the thirteenth scalar, right after the header and twelve others.
        let at = HEADER + 12 * 8;
        bytes[at..at + 8].copy_from_slice(&9.0f64.to_le_bytes());
        let body = bytes.len() - TRAILER;
        let sum = fnv1a(&bytes[..body]);
        bytes[body..].copy_from_slice(&sum.to_le_bytes());
        let e = Snapshot::from_bytes(&bytes, &s, eight).unwrap_err();
        assert!(e.contains("phase = 9"), "{e}");
    }
}
