//! The FMU-state calls of an [`Instance`]: fmi2GetFMUstate, fmi2SetFMUstate
//! (with every restored field checked) and the serialization of a state.

use super::super::snapshot::Snapshot;
use super::super::states::Call;
use super::super::variables::{EXCITATION_RANGE, VISCOSITY_RANGE};
use super::{Instance, Status, category, model_tuned};
use crate::solver::Simulator;
use crate::solver::reduction_check::ValidityWatch;
use crate::units::Short;

impl Instance {
    /// The state `fmi2GetFMUstate` would save now.
    fn current_snapshot(&self) -> Snapshot {
        Snapshot {
            sim: self.sim.state().clone(),
            params: self.params,
            tuned: self.tuned.clone(),
            phase: self.phase,
            fingerprint: self.fingerprint,
            watch: self.watch.image(),
        }
    }

    /// fmi2GetFMUstate.
    pub fn snapshot(&mut self) -> Result<Snapshot, Status> {
        self.check(Call::GetFmuState)?;
        Ok(self.current_snapshot())
    }

    /// Rotor coordinates `modes` fixed-interface modes build on this model
    /// (`None`: a negative count, or a model with no node to keep).
    fn coordinates_for(&self, modes: i32) -> Option<usize> {
        let modes = usize::try_from(modes).ok()?;
        self.sim.rotor().transient_coordinates(modes)
    }

    /// Whether mode counts `a` and `b` build the same rotor (both full, or
    /// both reduced to the same coordinates: 999 and 1000 modes on a rotor
    /// with fewer interior DOFs are one rotor).
    fn same_rotor(&self, a: i32, b: i32) -> bool {
        (a == 0) == (b == 0) && self.coordinates_for(a) == self.coordinates_for(b)
    }

    /// fmi2SetFMUstate. The FMU state includes the parameters (FMI 2.0
    /// §2.1.8), `solver.reduced_modes` among them: a state saved with another
    /// mode count brings its own rotor, rebuilt here when it is not the one
    /// running, as `solver.time_step` and `solver.tolerance` come back with it.
    /// A state that does not fit is refused before anything changes.
    pub fn restore(&mut self, snap: &Snapshot) -> Status {
        let call = Call::SetFmuState;
        if let Err(s) = self.check(call) {
            return s;
        }
        let modes = snap.params.reduced_modes;
        let fits = match self.coordinates_for(modes) {
            Some(n) => snap.fits(&self.current_snapshot(), n),
            None => Err(format!(
                "the state was saved with solver.reduced_modes = {modes}, which cannot reduce this model"
            )),
        };
        if let Err(why) = fits {
            return self.report(
                Status::Error,
                format!("{}: {why}", call.name_in(self.version)),
            );
        }
        let tunable = |k: usize| self.model.bearings[k].kind.tuned().is_some();
        let range = |k: usize| {
            let kind = &self.model.bearings[k].kind;
            match (kind.viscosity(), kind.excitation()) {
                (Some(_), _) => Some(("viscosity", VISCOSITY_RANGE, " Pa·s")),
                (_, Some(_)) => Some(("field excitation", EXCITATION_RANGE, "")),
                _ => None,
            }
        };
        if let Some((k, &value)) = snap.tuned.iter().enumerate().find(|&(k, &value)| {
            range(k).map_or(value != 0.0, |(_, (lo, hi), _)| !(lo..=hi).contains(&value))
        }) {
            let (what, (lo, hi), unit) = range(k).unwrap_or(("tuned value", (0.0, 0.0), ""));
            return self.report(
                Status::Error,
                format!(
                    "{}: {what} {}{unit} of bearing {} in the state is outside [{lo}, {hi}]{unit}",
                    call.name_in(self.version),
                    Short(value),
                    self.model.bearings[k].name
                ),
            );
        }
        let rebuild = !self.same_rotor(modes, self.params.reduced_modes);
        let result = if rebuild {
            // The state's rotor, built aside: the running one stays until it is ready.
            match Self::fresh_simulator(&self.model, modes) {
                Ok(mut sim) => {
                    let given = model_tuned(&self.model);
                    Self::load_state(&mut sim, snap, &given, tunable).map(|()| Some(sim))
                }
                Err(e) => Err(e),
            }
        } else {
            let now = self.tuned.clone();
            Self::load_state(&mut self.sim, snap, &now, tunable).map(|()| None)
        };
        match result {
            Ok(Some(sim)) => {
                self.watch = ValidityWatch::new(sim.rotor());
                self.sim = sim;
                self.sim.set_stop_at_contact(self.early_return);
                let line = self.sim.rotor().coordinates();
                self.messages.push((Status::Ok, category(Status::Ok), line));
            }
            Ok(None) => {}
            Err(e) => {
                return self.report(
                    Status::Error,
                    format!("{}: {e}", call.name_in(self.version)),
                );
            }
        }
        // Checked by `fits` and on reading: the watch of the state's run.
        if let Err(e) = self.watch.set_image(&snap.watch) {
            self.watch.reset();
            return self.report(
                Status::Error,
                format!("{}: {e}", call.name_in(self.version)),
            );
        }
        self.params = snap.params;
        self.tuned = snap.tuned.clone();
        self.phase = snap.phase;
        self.outputs.invalidate();
        Status::Ok
    }

    /// Put `snap`'s tuned viscosities and excitations (where they differ from
    /// `held`, those `sim` runs with), options and simulator state into `sim`.
    fn load_state(
        sim: &mut Simulator,
        snap: &Snapshot,
        held: &[f64],
        tunable: impl Fn(usize) -> bool,
    ) -> Result<(), String> {
        for (k, (&value, &now)) in snap.tuned.iter().zip(held).enumerate() {
            if value != now && tunable(k) {
                sim.set_bearing_tuned(k, value).map_err(|e| e.to_string())?;
            }
        }
        sim.set_options(snap.params.options())
            .and_then(|()| sim.set_state(snap.sim.clone()))
            .map_err(|e| e.to_string())
    }

    /// fmi2SerializedFMUstateSize: the length of the byte image of `snap`.
    pub fn serialized_size(&mut self, snap: &Snapshot) -> Result<usize, Status> {
        self.check(Call::SerializedFmuStateSize)?;
        Ok(snap.to_bytes().len())
    }

    /// fmi2SerializeFMUstate: the byte image of `snap`.
    pub fn serialize(&mut self, snap: &Snapshot) -> Result<Vec<u8>, Status> {
        self.check(Call::SerializeFmuState)?;
        Ok(snap.to_bytes())
    }

    /// fmi2DeSerializeFMUstate: the state in `bytes`, checked against this
    /// instance's model (fingerprint, sizes), format version and checksum.
    pub fn deserialize(&mut self, bytes: &[u8]) -> Result<Snapshot, Status> {
        let call = Call::DeSerializeFmuState;
        self.check(call)?;
        Snapshot::from_bytes(bytes, &self.current_snapshot(), |m| self.coordinates_for(m)).map_err(
            |why| {
                self.report(
                    Status::Error,
                    format!("{}: {why}", call.name_in(self.version)),
                )
            },
        )
    }
}
