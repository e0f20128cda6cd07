//! An FMI 2.0 instance: [`Instance::new`] with the GUID of the FMI 2.0 model
//! description, and the instantiation from the `fmuResourceLocation` URI
//! ([`crate::fmu::resources`]) checked against that GUID.

use super::xml::model_description;
use crate::fmu::instance::{Instance, Version};
pub use crate::fmu::resources::{MODEL_FILE, resource_dir};
use crate::model::RotorModel;

impl Instance {
    /// A new FMI 2.0 instance of `model`, named `name` (the token is the
    /// GUID of [`model_description`]); the model's plausibility warnings are
    /// queued for the logger (`logStatusWarning`).
    pub fn new(name: &str, model: RotorModel) -> Result<Self, String> {
        let (_, guid) = model_description(&model);
        Self::with_token(name, model, Version::Fmi2, guid)
    }
}

/// A new FMI 2.0 instance named `name` of the model in the resources at
/// `uri`, whose model description must have the GUID `guid`.
pub fn instantiate(name: &str, guid: &str, uri: &str) -> Result<Instance, String> {
    crate::fmu::resources::instantiate(name, guid, uri, Instance::new)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_loads_and_its_guid_is_checked() {
        let models = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("models");
        let dir = std::env::temp_dir().join(format!("rotor fmu resources {}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::copy(models.join("jeffcott.toml"), dir.join(MODEL_FILE)).unwrap();
        let uri = format!("file://{}", dir.display()).replace(' ', "%20");
        let model = RotorModel::from_file(&dir.join(MODEL_FILE)).unwrap();
        let (_, guid) = model_description(&model);
        let instance = instantiate("x", &guid, &uri).unwrap();
        assert_eq!(instance.guid(), guid);
        let e = instantiate("x", "{other}", &uri).unwrap_err();
        assert!(e.contains("GUID {other} does not match"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
        let e = instantiate("x", &guid, &uri).unwrap_err();
        assert!(e.contains(MODEL_FILE), "{e}");
    }
}
