//! The note on coefficient tables where a sub-synchronous mode is judged
//! (issue 45): a table gives a bearing's or seal's coefficients as measured
//! or computed for synchronous whirl at each speed, so a mode whirling at
//! another frequency sees them as tabulated, not at its own frequency.

use crate::model::RotorModel;

/// One line for every table bearing or seal of `model` (empty without
/// any): its coefficients are synchronous only.
pub fn synchronous_tables(model: &RotorModel) -> String {
    let names: Vec<&str> = model
        .bearings
        .iter()
        .filter(|b| b.kind.coefficient_table().is_some())
        .map(|b| b.name.as_str())
        .collect();
    if names.is_empty() {
        return String::new();
    }
    format!(
        "note: the coefficients of {} come from a table at the running speed (synchronous whirl): every mode sees them as tabulated, whatever its own frequency; a sub-synchronous mode's damping from them is only as good as that assumption (modelled tilting pads are reduced at each mode's own frequency)\n",
        names.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_every_table_and_nothing_else() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/models/hydro_unit_brackets.toml"
        );
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        let note = synchronous_tables(&model);
        assert!(
            note.contains("runner_seal") && note.starts_with("note:"),
            "{note}"
        );
        for b in &model.bearings {
            if b.kind.coefficient_table().is_none() {
                assert!(!note.contains(&b.name), "{}", b.name);
            }
        }
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/models/jeffcott.toml");
        let model = RotorModel::from_file(std::path::Path::new(path)).unwrap();
        assert_eq!(synchronous_tables(&model), "");
    }
}
