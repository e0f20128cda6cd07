//! The FMI 3.0 arrays over the variable table: each output or input
//! `{group}.{name}.{quantity}` (a bearing's `x`, a probe's `y`, a port's
//! force) also reads (and, for inputs, writes) as one `fmi3Float64` array
//! `{group}.{quantity}` over every `{name}` in model order, e.g.
//! `bearings.x` = [`bearings.left.x`, `bearings.right.x`]. The arrays add no
//! state: an array's value reference stands for its elements' references in
//! the table, so the structured names stay as they are.

use crate::fmu::variables::{Causality, Kind, Variability, Variable};

/// The value reference of the first array; the `k`-th is `ARRAY_BASE + k`,
/// outside the table's range (appending table variables moves no array).
pub const ARRAY_BASE: u32 = 1_000_000_000;

/// One array.
#[derive(Debug, Clone, PartialEq)]
pub struct Array {
    /// `{group}.{quantity}`.
    pub name: String,
    /// Its value reference.
    pub value_reference: u32,
    /// The table's value references of its elements, in model order.
    pub elements: Vec<u32>,
    /// The elements' causality (input or output).
    pub causality: Causality,
    /// The elements' variability.
    pub variability: Variability,
    /// The elements' unit.
    pub unit: Option<&'static str>,
    /// The elements' display unit.
    pub display_unit: Option<&'static str>,
}

/// The arrays of the table `vars`, in order of their first element.
pub fn arrays(vars: &[Variable]) -> Vec<Array> {
    let mut out: Vec<Array> = Vec::new();
    for v in vars {
        let parts: Vec<&str> = v.name.split('.').collect();
        let [group, _, quantity] = parts.as_slice() else {
            continue;
        };
        if v.kind != Kind::Real || v.causality == Causality::Parameter {
            continue;
        }
        let name = format!("{group}.{quantity}");
        match out.iter_mut().find(|a| a.name == name) {
            Some(a) if a.causality == v.causality && a.unit == v.unit => {
                a.elements.push(v.value_reference);
            }
            Some(_) => {}
            None => out.push(Array {
                value_reference: ARRAY_BASE + out.len() as u32,
                name,
                elements: vec![v.value_reference],
                causality: v.causality,
                variability: v.variability,
                unit: v.unit,
                display_unit: v.display_unit,
            }),
        }
    }
    // A name the table uses for a scalar is not taken by an array.
    out.retain(|a| vars.iter().all(|v| v.name != a.name));
    for (k, a) in out.iter_mut().enumerate() {
        a.value_reference = ARRAY_BASE + k as u32;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmu::variables::variables;
    use crate::model::RotorModel;

    #[test]
    fn bearings_probes_and_ports_read_as_arrays_in_model_order() {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/torque_ports.toml");
        let model = RotorModel::from_file(&path).unwrap();
        let vars = variables(&model);
        let list = arrays(&vars);
        let find = |name: &str| list.iter().find(|a| a.name == name).unwrap();
        let names = |a: &Array| -> Vec<String> {
            a.elements
                .iter()
                .map(|&vr| vars[vr as usize].name.clone())
                .collect()
        };
        assert_eq!(
            names(find("bearings.x")),
            ["bearings.drive_end.x", "bearings.non_drive_end.x"]
        );
        let fx = find("ports.fx");
        assert_eq!(names(fx), ["ports.amb.fx"]);
        assert_eq!(fx.causality, Causality::Input);
        assert_eq!(find("bearings.contact_force").unit, Some("N"));
        assert!(list.iter().all(|a| a.value_reference >= ARRAY_BASE));
        assert!(list.iter().all(|a| vars.iter().all(|v| v.name != a.name)));
        // Parameters and the indexed shaft torques make no array.
        assert!(
            list.iter()
                .all(|a| !a.name.starts_with("unbalance.") && !a.name.starts_with("shaft."))
        );
    }
}
