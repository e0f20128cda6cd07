//! The FMU-state calls of an [`Instance`]: fmi2GetFMUstate, fmi2SetFMUstate
//! (with every restored field checked) and the serialization of a state.

use super::super::snapshot::Snapshot;
use super::super::states::Call;
use super::super::variables::VISCOSITY_RANGE;
use super::{Instance, Status};
use crate::units::Short;

impl Instance {
    /// The state `fmi2GetFMUstate` would save now.
    fn current_snapshot(&self) -> Snapshot {
        Snapshot {
            sim: self.sim.state().clone(),
            params: self.params,
            viscosity: self.viscosity.clone(),
            phase: self.phase,
            fingerprint: self.fingerprint,
        }
    }

    /// fmi2GetFMUstate.
    pub fn snapshot(&mut self) -> Result<Snapshot, Status> {
        self.check(Call::GetFmuState)?;
        Ok(self.current_snapshot())
    }

    /// fmi2SetFMUstate.
    pub fn restore(&mut self, snap: &Snapshot) -> Status {
        let call = Call::SetFmuState;
        if let Err(s) = self.check(call) {
            return s;
        }
        if let Err(why) = snap.fits(&self.current_snapshot()) {
            return self.report(Status::Error, format!("{}: {why}", call.name()));
        }
        let film = |k: usize| self.model.bearings[k].kind.viscosity().is_some();
        let (lo, hi) = VISCOSITY_RANGE;
        if let Some((k, mu)) = snap.viscosity.iter().enumerate().find(|&(k, &mu)| {
            if film(k) {
                !(lo..=hi).contains(&mu)
            } else {
                mu != 0.0
            }
        }) {
            return self.report(
                Status::Error,
                format!(
                    "{}: viscosity {} Pa·s of bearing {} in the state is outside [{lo}, {hi}] Pa·s",
                    call.name(),
                    Short(*mu),
                    self.model.bearings[k].name
                ),
            );
        }
        for (k, (&mu, &now)) in snap
            .viscosity
            .iter()
            .zip(self.viscosity.clone().iter())
            .enumerate()
        {
            if mu != now && film(k) {
                if let Err(e) = self.sim.set_bearing_viscosity(k, mu) {
                    return self.report(Status::Error, format!("{}: {e}", call.name()));
                }
            }
        }
        let options = snap.params.options();
        if let Err(e) = self
            .sim
            .set_options(options)
            .and_then(|()| self.sim.set_state(snap.sim.clone()))
        {
            return self.report(Status::Error, format!("{}: {e}", call.name()));
        }
        self.params = snap.params;
        self.viscosity = snap.viscosity.clone();
        self.phase = snap.phase;
        self.outputs = None;
        Status::Ok
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
        Snapshot::from_bytes(bytes, &self.current_snapshot())
            .map_err(|why| self.report(Status::Error, format!("{}: {why}", call.name())))
    }
}
