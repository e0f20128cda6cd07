//! Instantiation from the FMU's resources: decode the `fmuResourceLocation` URI,
//! load `model.toml` from that folder, check it against the GUID the importer
//! read from `modelDescription.xml`, and build the [`Instance`].

use std::path::{Path, PathBuf};

use super::instance::Instance;
use crate::model::RotorModel;

/// The folder of the plain finite films' force tables inside the resources
/// (`film_tables = true`; `rotor fmu-stage` writes them there, an instance
/// reads them, or builds them if they are missing or not trusted).
pub const FILM_TABLES: &str = "film_tables";

/// The model file inside the resources folder.
pub const MODEL_FILE: &str = "model.toml";

/// Write the force tables of `model`'s finite films (plain films' and
/// tilting pads') into `resources/`[`FILM_TABLES`], where an instance reads
/// them (`rotor fmu-stage`); the error names the file.
pub fn write_film_tables(model: &RotorModel, resources: &Path) -> Result<(), String> {
    use crate::bearing::BearingKind;
    use crate::bearing::film_table_cache::{CachedTable, encode, table_path};
    fn put<T: CachedTable>(tables: &Path, table: &T) -> Result<(), String> {
        std::fs::create_dir_all(tables).map_err(|e| format!("{}: {e}", tables.display()))?;
        let path = table_path(tables, &table.key());
        std::fs::write(&path, encode(table)).map_err(|e| format!("{}: {e}", path.display()))
    }
    let tables = resources.join(FILM_TABLES);
    for b in &model.bearings {
        if let BearingKind::FiniteFilm(f) = &b.kind {
            if let Some(t) = &f.table {
                put(&tables, &*t.table)?;
            }
            for t in &f.pad_tables {
                put(&tables, &*t.table)?;
            }
        }
    }
    Ok(())
}

/// The folder a `file` URI names: `file:///path`, `file:/path` and
/// `file://localhost/path`, percent-decoded (RFC 8089). The scheme and the host
/// are case-insensitive (`FILE:///path`, RFC 3986 §3.1, §3.2.2); a `?query` or
/// `#fragment` ends the path (§3.3) and is ignored (an escaped `%3F` or `%23`
/// stays part of it). Any other host or scheme, a bad escape or a path that is
/// not UTF-8 gives an error.
pub fn resource_dir(uri: &str) -> Result<PathBuf, String> {
    let not_file = || format!("fmuResourceLocation {uri:?} is not a local file URI");
    let scheme = uri.get(..5).ok_or_else(not_file)?;
    if !scheme.eq_ignore_ascii_case("file:") {
        return Err(not_file());
    }
    let rest = &uri[5..];
    let rest = rest.find(['?', '#']).map_or(rest, |end| &rest[..end]);
    let path = match rest.strip_prefix("//") {
        // An authority: empty or "localhost", then the absolute path.
        Some(authority_and_path) => {
            let slash = authority_and_path.find('/').ok_or_else(not_file)?;
            let (host, path) = authority_and_path.split_at(slash);
            if !(host.is_empty() || host.eq_ignore_ascii_case("localhost")) {
                return Err(format!(
                    "fmuResourceLocation {uri:?} names the host {host:?}, not this machine"
                ));
            }
            path
        }
        None if rest.starts_with('/') => rest,
        None => return Err(not_file()),
    };
    let decoded = percent_decode(path)
        .ok_or_else(|| format!("fmuResourceLocation {uri:?}: bad percent-encoding"))?;
    // `file:///C:/dir` names `C:/dir` on Windows.
    let decoded = if cfg!(windows) && decoded.as_bytes().get(2) == Some(&b':') {
        decoded[1..].to_string()
    } else {
        decoded
    };
    Ok(PathBuf::from(decoded))
}

/// `%XX` escapes replaced by their bytes; `None` for a bad escape or non-UTF-8.
fn percent_decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

/// A new instance named `name` of the model in the resources at `uri`, built
/// by `new` (the version layer's constructor), whose model description must
/// have the token `guid` (FMI 2 GUID, FMI 3 instantiation token).
pub fn instantiate(
    name: &str,
    guid: &str,
    uri: &str,
    new: impl FnOnce(&str, RotorModel) -> Result<Instance, String>,
) -> Result<Instance, String> {
    instantiate_in(name, guid, &resource_dir(uri)?, new)
}

/// [`instantiate`] from the resources folder `dir` itself (FMI 3.0's
/// `resourcePath`).
pub fn instantiate_in(
    name: &str,
    guid: &str,
    dir: &Path,
    new: impl FnOnce(&str, RotorModel) -> Result<Instance, String>,
) -> Result<Instance, String> {
    let tables = dir.join(FILM_TABLES);
    let model = RotorModel::from_file_cached(&dir.join(MODEL_FILE), Some(&tables))
        .map_err(|e| e.to_string())?;
    let instance = new(name, model)?;
    if instance.guid() != guid {
        return Err(format!(
            "{} {guid} does not match the model in the resources ({})",
            instance.version().token_name(),
            instance.guid()
        ));
    }
    Ok(instance)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_uris_decode() {
        let p = |s: &str| resource_dir(s).map(|p| p.to_string_lossy().into_owned());
        assert_eq!(p("file:///tmp/a%20b/res").unwrap(), "/tmp/a b/res");
        assert_eq!(p("file:/tmp/x").unwrap(), "/tmp/x");
        assert_eq!(p("file://localhost/tmp/x").unwrap(), "/tmp/x");
        assert_eq!(p("file://LOCALHOST/tmp/x%2Fy").unwrap(), "/tmp/x/y");
        assert_eq!(p("file:///tmp/%C3%A9t%C3%A9").unwrap(), "/tmp/été");
        assert_eq!(p("file:///end%41").unwrap(), "/endA");
        // Issue 22: the scheme is case-insensitive, query and fragment are not the path.
        assert_eq!(p("FILE:///tmp/x").unwrap(), "/tmp/x");
        assert_eq!(p("File://LocalHost/tmp/x").unwrap(), "/tmp/x");
        assert_eq!(p("file:///tmp/res?version=2").unwrap(), "/tmp/res");
        assert_eq!(p("file:///tmp/res#top").unwrap(), "/tmp/res");
        assert_eq!(p("file:///tmp/a%20b?x#y").unwrap(), "/tmp/a b");
        assert_eq!(p("file:///tmp/what%3F%23").unwrap(), "/tmp/what?#");
    }

    #[test]
    fn other_uris_are_refused() {
        for uri in [
            "http://x/y",
            "/tmp/x",
            "file:tmp/x",
            "file://server/share",
            "file://localhost",
            "file:///tmp/%zz",
            "file:///tmp/%4",
            "file:///tmp/%FF",
            "files:///tmp/x",
            "fil",
            "é:///tmp",
            "file://?/tmp",
            "file:?x",
        ] {
            assert!(resource_dir(uri).is_err(), "{uri}");
        }
        let e = resource_dir("file://server/share").unwrap_err();
        assert!(e.contains("server"), "{e}");
    }
}
