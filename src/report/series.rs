//! Series and summary numbers taken from analysis results: the largest static
//! deflection, orbits of bearings and probes from simulation records.

use crate::analysis::linear::node_xy;
use crate::model::RotorModel;
use crate::solver::Outputs;

/// A named orbit: label, `x` (m) and `y` (m) per record.
pub type Orbit = (String, Vec<f64>, Vec<f64>);

/// Node (0-based) with the largest radial displacement `√(x² + y²)` (m) of the
/// node displacements `q` (`4·node + k`), and that displacement; `(0, 0)` for no
/// deflection.
pub fn largest_deflection(q: &[f64], nodes: usize) -> (usize, f64) {
    (0..nodes)
        .map(|i| {
            let (x, y) = node_xy(q, i);
            (i, x.hypot(y))
        })
        .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a })
}

/// Orbits of every bearing journal (`bearing NAME`) and then every probe
/// (`probe NAME`) of `model` over `records`.
pub fn orbits(model: &RotorModel, records: &[Outputs]) -> Vec<Orbit> {
    let mut orbits = Vec::new();
    for (k, b) in model.bearings.iter().enumerate() {
        orbits.push((
            format!("bearing {}", b.name),
            records.iter().map(|o| o.bearings[k].x).collect(),
            records.iter().map(|o| o.bearings[k].y).collect(),
        ));
    }
    for (k, p) in model.probes.iter().enumerate() {
        orbits.push((
            format!("probe {}", p.name),
            records.iter().map(|o| o.probes[k].x).collect(),
            records.iter().map(|o| o.probes[k].y).collect(),
        ));
    }
    orbits
}

/// Displacement `(x, y)` (m) of the first probe, else of the first bearing
/// journal: the point a waterfall follows (named by [`watched_point_name`]).
pub fn watched_point(o: &Outputs) -> (f64, f64) {
    match o.probes.first() {
        Some(p) => (p.x, p.y),
        None => (o.bearings[0].x, o.bearings[0].y),
    }
}

/// The name of the point [`watched_point`] follows in `model`: `probe NAME`
/// (the first probe), else `bearing NAME` (the first bearing).
pub fn watched_point_name(model: &RotorModel) -> String {
    match (model.probes.first(), model.bearings.first()) {
        (Some(p), _) => format!("probe {}", p.name),
        (None, Some(b)) => format!("bearing {}", b.name),
        (None, None) => "no probe or bearing".to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::BearingReport;
    use crate::solver::{BearingOutput, ProbeOutput};

    fn outputs(k: f64, probe: bool) -> Outputs {
        let bearing = |s: f64| BearingOutput {
            x: s * k,
            y: -s * k,
            fx: 0.0,
            fy: 0.0,
            report: BearingReport::default(),
            ..Default::default()
        };
        Outputs {
            time: k,
            speed: 100.0,
            spin_angle: 0.0,
            bearings: vec![bearing(1.0), bearing(2.0)],
            probes: if probe {
                vec![ProbeOutput {
                    x: 5.0 * k,
                    y: 6.0 * k,
                }]
            } else {
                Vec::new()
            },
            ports: Vec::new(),
            thrust_bearings: Vec::new(),
            torques: Vec::new(),
            shaft_torques: Vec::new(),
            friction_torque: 0.0,
            power_loss: 0.0,
        }
    }

    #[test]
    fn largest_deflection_finds_the_peak_node() {
        let q = [0.0, 0.0, 1.0, 1.0, 3.0, 4.0, 0.0, 0.0, 0.0, -1.0, 9.0, 9.0];
        assert_eq!(largest_deflection(&q, 3), (1, 5.0));
        assert_eq!(largest_deflection(&[0.0; 8], 2), (0, 0.0));
    }

    #[test]
    fn orbits_of_bearings_then_probes() {
        let model = RotorModel::default_model();
        assert_eq!((model.bearings.len(), model.probes.len()), (2, 1));
        let records: Vec<Outputs> = (0..3).map(|k| outputs(k as f64, true)).collect();
        let o = orbits(&model, &records);
        assert_eq!(o.len(), 3);
        assert_eq!(o[0].0, format!("bearing {}", model.bearings[0].name));
        assert_eq!(o[1].1, vec![0.0, 2.0, 4.0]);
        assert_eq!(o[1].2, vec![0.0, -2.0, -4.0]);
        assert_eq!(o[2].0, format!("probe {}", model.probes[0].name));
        assert_eq!(o[2].2, vec![0.0, 6.0, 12.0]);
        assert_eq!(watched_point(&records[2]), (10.0, 12.0));
        assert_eq!(watched_point(&outputs(2.0, false)), (2.0, -2.0));
        assert_eq!(watched_point_name(&model), "probe disk");
        let mut bare = model.clone();
        bare.probes.clear();
        assert_eq!(watched_point_name(&bare), "bearing drive_end");
    }
}
