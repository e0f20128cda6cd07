//! `rotor fmu-stage`: the generated parts of an FMU (fmu_pack.sh adds the binary).

use std::path::Path;

use crate::write_file;

/// Writes modelDescription.xml, resources/model.toml and
/// documentation/index.html for `model` into `dir`; prints the model name and GUID.
pub fn stage(model: &Path, dir: &Path) -> Result<(), String> {
    let m = crate::read_model(model)?;
    let text = std::fs::read_to_string(model).map_err(|e| format!("{}: {e}", model.display()))?;
    let (xml, guid) = rotor_bearing::fmi2::xml::model_description(&m);
    for sub in ["resources", "documentation", "binaries/linux64"] {
        std::fs::create_dir_all(dir.join(sub))
            .map_err(|e| format!("{}: {e}", dir.join(sub).display()))?;
    }
    write_file(&dir.join("modelDescription.xml"), &xml)?;
    write_file(&dir.join("resources/model.toml"), &text)?;
    write_file(
        &dir.join("documentation/index.html"),
        &rotor_bearing::fmi2::docs::index_html(&m),
    )?;
    println!("{} {guid}", m.name);
    Ok(())
}
