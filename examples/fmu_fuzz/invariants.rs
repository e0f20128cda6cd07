//! Invariants the fuzzer checks beyond the state machine (issue 46):
//! - the power losses add up: the outputs `*.power_loss` sum to the total
//!   `power_loss` after every read that succeeds;
//! - a state just saved is restorable, in the same instance and, serialized,
//!   in a fresh one;
//! - a step replayed from a state saved before it returns the same status,
//!   the same warnings and bit-identical outputs (warnings are part of the
//!   FMU state);
//! - an input derivative of order 2 or higher, where the state machine
//!   allows the call and the value is finite, is accepted (not used).

use super::*;

impl Fuzz<'_> {
    /// The outputs `*.power_loss` add up to `power_loss` (to the round-off
    /// of the sum).
    pub(super) fn check_power_losses(&mut self) -> Result<(), String> {
        let parts: Vec<u32> = self
            .vars
            .iter()
            .filter(|v| v.causality == "output" && v.name.ends_with(".power_loss"))
            .map(|v| v.vr)
            .collect();
        let Some(total) = self.vars.iter().find(|v| v.name == "power_loss") else {
            return Ok(());
        };
        let mut refs = parts.clone();
        refs.push(total.vr);
        let mut values = vec![0.0; refs.len()];
        // SAFETY: `c` is live; `refs` and `values` hold `refs.len()` elements.
        let s = unsafe {
            self.lib
                .fmi2GetReal(self.c, refs.as_ptr(), refs.len(), values.as_mut_ptr())
        };
        if s > fmi2Status_fmi2Warning {
            return Ok(());
        }
        let total = values[parts.len()];
        let sum: f64 = values[..parts.len()].iter().sum();
        let size: f64 = values.iter().map(|v| v.abs()).sum();
        if (sum - total).abs() > 1e-12 * size.max(1.0) {
            return Err(self.fail(format!(
                "power losses do not add up: the {} parts sum to {sum} W, power_loss = {total} W",
                parts.len()
            )));
        }
        Ok(())
    }

    /// Every Real, in model order (the raw values, for bit comparison).
    fn all_reals(&self) -> (fmi2Status, Vec<f64>) {
        let refs: Vec<u32> = self
            .vars
            .iter()
            .filter(|v| v.kind == "Real")
            .map(|v| v.vr)
            .collect();
        let mut values = vec![0.0; refs.len()];
        // SAFETY: `c` is live; `refs` and `values` hold `refs.len()` elements.
        let s = unsafe {
            self.lib
                .fmi2GetReal(self.c, refs.as_ptr(), refs.len(), values.as_mut_ptr())
        };
        (s, values)
    }

    /// The warnings logged since entry `from` of the log.
    fn warnings_since(from: usize) -> Vec<String> {
        LOG.lock().map_or_else(
            |_| Vec::new(),
            |log| {
                log.get(from..)
                    .unwrap_or_default()
                    .iter()
                    .filter(|(s, _)| *s == fmi2Status_fmi2Warning)
                    .map(|(_, m)| m.clone())
                    .collect()
            },
        )
    }

    fn log_len() -> usize {
        LOG.lock().map_or(0, |log| log.len())
    }

    /// `fmi2DoStep(t, h)` from a state saved just before it, then again from
    /// that state: the same status, warnings and outputs, bit for bit.
    pub(super) fn replayed_step(&mut self, t: f64, h: f64) -> Result<fmi2Status, String> {
        let mut saved: fmi2FMUstate = std::ptr::null_mut();
        // SAFETY: `c` is live; `saved` receives the state.
        let s = unsafe { self.lib.fmi2GetFMUstate(self.c, &mut saved) };
        self.check_status("fmi2GetFMUstate", s)?;
        if s != fmi2Status_fmi2OK || saved.is_null() {
            return Err(self.fail(format!(
                "fmi2GetFMUstate in StepComplete returned {}",
                status_name(s)
            )));
        }
        let mut runs = Vec::new();
        for pass in 0..2 {
            if pass == 1 {
                // SAFETY: `saved` is a state of this instance.
                let s = unsafe { self.lib.fmi2SetFMUstate(self.c, saved) };
                if s != fmi2Status_fmi2OK {
                    // SAFETY: as above; freed once.
                    unsafe { self.lib.fmi2FreeFMUstate(self.c, &mut saved) };
                    return Err(self.fail(format!(
                        "fmi2SetFMUstate of the state saved before the step returned {}",
                        status_name(s)
                    )));
                }
            }
            let from = Self::log_len();
            self.calling(&format!("fmi2DoStep(t = {t}, h = {h:e}) pass {pass}"));
            // SAFETY: `c` is live.
            let s = unsafe { self.lib.fmi2DoStep(self.c, t, h, fmi2True as fmi2Boolean) };
            self.note(format!(
                "fmi2DoStep(t = {t}, h = {h:e}) pass {pass} → {}",
                status_name(s)
            ));
            self.check_status("fmi2DoStep", s)?;
            let warnings = Self::warnings_since(from);
            let reals = if s <= fmi2Status_fmi2Warning {
                self.all_reals().1
            } else {
                Vec::new()
            };
            runs.push((s, warnings, reals));
        }
        // SAFETY: `saved` is a state of this instance, freed once.
        unsafe { self.lib.fmi2FreeFMUstate(self.c, &mut saved) };
        let (first, second) = (&runs[0], &runs[1]);
        if first.0 != second.0 {
            return Err(self.fail(format!(
                "a step replayed from the state saved before it returned {} where it returned {}",
                status_name(second.0),
                status_name(first.0)
            )));
        }
        if first.1 != second.1 {
            return Err(self.fail(format!(
                "a step replayed from the state saved before it warned {:?} where it warned {:?}",
                second.1, first.1
            )));
        }
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        if bits(&first.2) != bits(&second.2) {
            return Err(self
                .fail("a step replayed from the state saved before it gave other outputs".into()));
        }
        Ok(first.0)
    }

    /// A state just saved restores in this instance and, serialized, in a
    /// fresh instance of the same FMU.
    pub(super) fn check_restorable(&mut self, state: fmi2FMUstate) -> Result<(), String> {
        // SAFETY: `state` is a live state of this instance.
        let s = unsafe { self.lib.fmi2SetFMUstate(self.c, state) };
        self.note(format!("fmi2SetFMUstate(just saved) → {}", status_name(s)));
        if s != fmi2Status_fmi2OK {
            return Err(self.fail(format!(
                "the state just saved is refused by its own instance: {}",
                status_name(s)
            )));
        }
        if !self.rng.chance(0.3) {
            return Ok(());
        }
        let mut size = 0usize;
        // SAFETY: as above; `size` receives the length.
        let s = unsafe {
            self.lib
                .fmi2SerializedFMUstateSize(self.c, state, &mut size)
        };
        if s != fmi2Status_fmi2OK {
            return Err(self.fail(format!(
                "fmi2SerializedFMUstateSize of the state just saved: {}",
                status_name(s)
            )));
        }
        let mut bytes = vec![0 as c_char; size];
        // SAFETY: `bytes` holds `size` bytes.
        let s = unsafe {
            self.lib
                .fmi2SerializeFMUstate(self.c, state, bytes.as_mut_ptr(), size)
        };
        if s != fmi2Status_fmi2OK {
            return Err(self.fail(format!(
                "fmi2SerializeFMUstate of the state just saved: {}",
                status_name(s)
            )));
        }
        let name = CString::new("fuzz-fresh").unwrap_or_default();
        let callbacks = callbacks();
        // SAFETY: the strings and callbacks outlive the instance, freed below.
        let fresh = unsafe {
            self.lib.fmi2Instantiate(
                name.as_ptr(),
                fmi2Type_fmi2CoSimulation,
                self.guid.as_ptr(),
                self.uri.as_ptr(),
                &callbacks,
                0,
                0,
            )
        };
        if fresh.is_null() {
            return Err(self.fail("a fresh instance could not be instantiated".into()));
        }
        let mut restored: fmi2FMUstate = std::ptr::null_mut();
        // SAFETY: `fresh` is live, `bytes` holds the image.
        let read = unsafe {
            self.lib
                .fmi2DeSerializeFMUstate(fresh, bytes.as_ptr(), bytes.len(), &mut restored)
        };
        let set = if read == fmi2Status_fmi2OK && !restored.is_null() {
            // SAFETY: `restored` is a state of `fresh`.
            unsafe { self.lib.fmi2SetFMUstate(fresh, restored) }
        } else {
            read
        };
        // SAFETY: `restored` and `fresh` are freed once each.
        unsafe {
            if !restored.is_null() {
                self.lib.fmi2FreeFMUstate(fresh, &mut restored);
            }
            self.lib.fmi2FreeInstance(fresh);
        }
        self.note(format!(
            "state just saved, serialized into a fresh instance → {}",
            status_name(set)
        ));
        if set != fmi2Status_fmi2OK {
            return Err(self.fail(format!(
                "the state just saved is refused by a fresh instance: {}",
                status_name(set)
            )));
        }
        Ok(())
    }

    /// `fmi2SetRealInputDerivatives` on a random input with order 0 to 3
    /// (order ≥ 2 accepted and unused where the call is allowed, order 0
    /// refused).
    pub(super) fn input_derivative(&mut self) -> Result<(), String> {
        let inputs: Vec<Var> = self
            .vars
            .iter()
            .filter(|v| v.causality == "input" && v.kind == "Real")
            .cloned()
            .collect();
        if inputs.is_empty() {
            return Ok(());
        }
        let v = inputs[self.rng.below(inputs.len())].clone();
        let order: fmi2Integer = [1, 1, 1, 2, 2, 3, 0][self.rng.below(7)];
        let value = match self.rng.below(8) {
            0 => f64::NAN,
            1 => 0.0,
            _ => {
                let scale = v.max.map_or(100.0, f64::abs).max(1.0);
                let sign = if self.rng.chance(0.5) { 1.0 } else { -1.0 };
                sign * scale * self.rng.log_uniform(1e-6, 1.0)
            }
        };
        // SAFETY: `c` is live; one reference, order and value.
        let s = unsafe {
            self.lib
                .fmi2SetRealInputDerivatives(self.c, &v.vr, 1, &order, &value)
        };
        self.note(format!(
            "fmi2SetRealInputDerivatives({}, order {order}, {value:e}) → {}",
            v.name,
            status_name(s)
        ));
        self.check_status("fmi2SetRealInputDerivatives", s)?;
        let allowed = matches!(
            self.phase,
            Phase::Instantiated | Phase::Initialization | Phase::StepComplete
        );
        if allowed && order >= 2 && value.is_finite() && s != fmi2Status_fmi2OK {
            return Err(self.fail(format!(
                "an order-{order} derivative of {} was refused ({}): the FMU may ignore orders it does not use",
                v.name,
                status_name(s)
            )));
        }
        if self.phase != Phase::Error && order == 0 {
            self.expect_error("fmi2SetRealInputDerivatives", s, "order 0 is no derivative")?;
        }
        self.after(s);
        Ok(())
    }
}
