//! `rotor fmu-stage`: the generated parts of an FMU (fmu_pack.sh adds the binary).

use std::path::Path;

use crate::write_file;

/// Writes modelDescription.xml, resources/model.toml (with the coefficient
/// tables it reads, at the same relative paths) and documentation/index.html
/// for `model` into `dir`, the model description of FMI version `fmi` (2 or
/// 3); prints the model name and GUID (FMI 3: instantiation token).
pub fn stage(model: &Path, dir: &Path, fmi: u8) -> Result<(), String> {
    let m = crate::read_model(model)?;
    let text = std::fs::read_to_string(model).map_err(|e| format!("{}: {e}", model.display()))?;
    let (xml, guid) = if fmi == 3 {
        rotor_bearing::fmi3::xml::model_description(&m)
    } else {
        rotor_bearing::fmi2::xml::model_description(&m)
    };
    let binaries = if fmi == 3 {
        "binaries/x86_64-linux"
    } else {
        "binaries/linux64"
    };
    for sub in ["resources", "documentation", binaries] {
        std::fs::create_dir_all(dir.join(sub))
            .map_err(|e| format!("{}: {e}", dir.join(sub).display()))?;
    }
    write_file(&dir.join("modelDescription.xml"), &xml)?;
    write_file(&dir.join("resources/model.toml"), &text)?;
    // Coefficient tables travel with the model, at the path it names them by.
    for (written, path) in m.table_files() {
        let relative = Path::new(written);
        if relative.is_absolute()
            || relative
                .components()
                .any(|c| !matches!(c, std::path::Component::Normal(_)))
        {
            return Err(format!(
                "{}: table = {written:?}: an FMU carries its tables in resources/, so give the table file as a path beside or below the model file (no absolute path, no ..)",
                model.display()
            ));
        }
        let target = dir.join("resources").join(relative);
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
        }
        std::fs::copy(path, &target).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    // Force tables of finite films (plain films' and tilting pads') travel
    // in resources/film_tables.
    rotor_bearing::fmu::resources::write_film_tables(&m, &dir.join("resources"))?;
    write_file(
        &dir.join("documentation/index.html"),
        &rotor_bearing::fmi2::docs::index_html(&m),
    )?;
    println!("{} {guid}", m.name);
    Ok(())
}
