//! An FMI 3.0 instance: `Instance::new_fmi3` with the instantiation token of
//! the FMI 3.0 model description, and the instantiation from the
//! `resourcePath` folder ([`crate::fmu::resources`]) checked against it.

use std::path::Path;

use super::xml::model_description;
use crate::fmu::instance::{Instance, Version};
use crate::model::RotorModel;

impl Instance {
    /// A new FMI 3.0 instance of `model`, named `name` (the token is the
    /// instantiation token of [`model_description`]); the model's
    /// plausibility warnings are queued for the logger (`logStatusWarning`).
    pub fn new_fmi3(name: &str, model: RotorModel) -> Result<Self, String> {
        let (_, token) = model_description(&model);
        Self::with_token(name, model, Version::Fmi3, token)
    }
}

/// A new FMI 3.0 instance named `name` of the model in the resources folder
/// `dir` (FMI 3.0 passes a path, not a URI), whose model description must
/// have the instantiation token `token`.
pub fn instantiate(name: &str, token: &str, dir: &Path) -> Result<Instance, String> {
    crate::fmu::resources::instantiate_in(name, token, dir, Instance::new_fmi3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fmu::resources::MODEL_FILE;

    #[test]
    fn the_model_loads_and_its_token_is_checked() {
        let models = Path::new(env!("CARGO_MANIFEST_DIR")).join("models");
        let dir = std::env::temp_dir().join(format!("rotor fmi3 resources {}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::copy(models.join("jeffcott.toml"), dir.join(MODEL_FILE)).unwrap();
        let model = RotorModel::from_file(&dir.join(MODEL_FILE)).unwrap();
        let (_, token) = model_description(&model);
        let (_, guid) = crate::fmi2::xml::model_description(&model);
        assert_ne!(
            token, guid,
            "FMI 2 and FMI 3 describe the model differently"
        );
        let instance = instantiate("x", &token, &dir).unwrap();
        assert_eq!(instance.guid(), token);
        assert_eq!(instance.version(), Version::Fmi3);
        let e = instantiate("x", &guid, &dir).unwrap_err();
        assert!(
            e.starts_with(&format!("instantiationToken {guid} does not match")),
            "{e}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
        let e = instantiate("x", &token, &dir).unwrap_err();
        assert!(e.contains(MODEL_FILE), "{e}");
    }
}
