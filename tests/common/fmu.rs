//! Shared helpers of the tests that drive the safe FMU instance: a shipped
//! model by name and a variable's value reference by name.

use rotor_bearing::fmi2::variables::variables;
use rotor_bearing::model::RotorModel;

/// The shipped model `models/NAME.toml`.
pub fn model(name: &str) -> RotorModel {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("models/{name}.toml"));
    RotorModel::from_file(&path).unwrap()
}

/// The value reference of the variable `name` of `model`'s FMU.
pub fn vr(model: &RotorModel, name: &str) -> u32 {
    variables(model)
        .iter()
        .find(|v| v.name == name)
        .unwrap_or_else(|| panic!("no variable {name}"))
        .value_reference
}
