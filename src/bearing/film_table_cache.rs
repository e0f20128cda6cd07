//! The on-disk cache of plain-film force tables ([`super::film_table`]):
//! one file per table geometry, `film-<key>.table` in the cache directory,
//! `<key>` the 64-bit FNV-1a hash of the geometry and the table format, in
//! hex.
//!
//! **Directory** ([`cache_dir`]): `$ROTOR_CACHE_DIR` if set, else
//! `$XDG_CACHE_HOME/rotor`, else `$HOME/.cache/rotor`; none of them: no
//! cache (the table is built in memory every run).
//!
//! **File**: the magic `rotor-film-table`, the format version, the geometry
//! in full (slenderness bits, mesh, cavitation), the node counts, the nodal
//! values `W` as little-endian `f64`, then the FNV-1a hash of all that. A
//! file that is short, of another version or geometry, with a wrong hash or
//! a non-finite value is not trusted: the table is rebuilt and the file
//! replaced ([`TableOrigin::Rebuilt`] says why). Files are written to a
//! temporary name and renamed, so a reader never sees half a file.

use std::path::{Path, PathBuf};
use std::time::Instant;

use super::film_table::{DIRECTIONS, ECCENTRICITY_INTERVALS, FilmTable, TableGeometry};
use super::finite_film::FiniteFilm;
use super::reynolds::{Cavitation, ReynoldsError, ReynoldsMesh};

/// Format version of the file and of the table (grid, factor, spline).
const VERSION: u32 = 1;
const MAGIC: &[u8; 16] = b"rotor-film-table";

/// Where a table came from.
#[derive(Debug, Clone, PartialEq)]
pub enum TableOrigin {
    /// Read from the cache file.
    Loaded(PathBuf),
    /// Built: no cache directory, or no file for this geometry yet (then
    /// written to the path given, if it could be).
    Built(Option<PathBuf>),
    /// The cache file was not trusted (the reason) and the table rebuilt.
    Rebuilt(PathBuf, String),
}

/// The cache directory (see the module docs), `None` without one.
pub fn cache_dir() -> Option<PathBuf> {
    let var = |name| std::env::var_os(name).filter(|v| !v.is_empty());
    if let Some(dir) = var("ROTOR_CACHE_DIR") {
        return Some(PathBuf::from(dir));
    }
    if let Some(dir) = var("XDG_CACHE_HOME") {
        return Some(PathBuf::from(dir).join("rotor"));
    }
    var("HOME").map(|home| PathBuf::from(home).join(".cache").join("rotor"))
}

/// 64-bit FNV-1a of `bytes`.
fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

fn cavitation_code(c: Cavitation) -> u8 {
    match c {
        Cavitation::Gumbel => 0,
        Cavitation::SwiftStieber => 1,
        Cavitation::FullFilm => 2,
    }
}

/// The file's header: magic, version, geometry and node counts.
fn header(geometry: &TableGeometry) -> Vec<u8> {
    let mut out = Vec::new();
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&geometry.slenderness.to_bits().to_le_bytes());
    out.extend_from_slice(&(geometry.mesh.circumferential as u64).to_le_bytes());
    out.extend_from_slice(&(geometry.mesh.axial as u64).to_le_bytes());
    out.push(cavitation_code(geometry.cavitation));
    out.extend_from_slice(&((ECCENTRICITY_INTERVALS + 1) as u64).to_le_bytes());
    out.extend_from_slice(&(DIRECTIONS as u64).to_le_bytes());
    out
}

/// The cache file of `geometry` in `dir`.
pub fn table_path(dir: &Path, geometry: &TableGeometry) -> PathBuf {
    dir.join(format!("film-{:016x}.table", fnv1a(&header(geometry))))
}

/// The bytes of a table's file.
pub fn encode(table: &FilmTable) -> Vec<u8> {
    let mut out = header(&table.geometry());
    for w in table.values() {
        for v in w {
            out.extend_from_slice(&v.to_le_bytes());
        }
    }
    let hash = fnv1a(&out);
    out.extend_from_slice(&hash.to_le_bytes());
    out
}

/// The table of a file's bytes, or why they are not one of `geometry`.
pub fn decode(bytes: &[u8], geometry: &TableGeometry) -> Result<FilmTable, String> {
    let head = header(geometry);
    let (nt, nc) = (ECCENTRICITY_INTERVALS + 1, DIRECTIONS);
    let size = head.len() + nt * nc * 16 + 8;
    if bytes.len() != size {
        return Err(format!("{} bytes, not {size}", bytes.len()));
    }
    if bytes[..MAGIC.len()] != MAGIC[..] {
        return Err("not a film table".into());
    }
    if bytes[..head.len()] != head[..] {
        return Err("another format version or geometry".into());
    }
    let (body, tail) = bytes.split_at(size - 8);
    let stored = u64::from_le_bytes(tail.try_into().expect("8 bytes"));
    if fnv1a(body) != stored {
        return Err("hash mismatch (corrupt file)".into());
    }
    let numbers: Vec<f64> = body[head.len()..]
        .chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().expect("8 bytes")))
        .collect();
    if let Some(bad) = numbers.iter().find(|v| !v.is_finite()) {
        return Err(format!("non-finite value {bad}"));
    }
    let values = numbers.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
    Ok(FilmTable::from_values(*geometry, nt, nc, values))
}

/// The table of `geometry`: read from `dir` if a trusted file is there,
/// else built ([`FilmTable::build`]) and written there (a failed write
/// only loses the cache); with the seconds the build took (0 when read).
pub fn load_or_build(
    geometry: &TableGeometry,
    dir: Option<&Path>,
) -> Result<(FilmTable, TableOrigin, f64), ReynoldsError> {
    let path = dir.map(|d| table_path(d, geometry));
    let mut rejected = None;
    if let Some(path) = &path {
        if let Ok(bytes) = std::fs::read(path) {
            match decode(&bytes, geometry) {
                Ok(table) => return Ok((table, TableOrigin::Loaded(path.clone()), 0.0)),
                Err(why) => rejected = Some(why),
            }
        }
    }
    let start = Instant::now();
    let table = FilmTable::build(*geometry)?;
    let seconds = start.elapsed().as_secs_f64();
    let written = path.filter(|p| write(p, &encode(&table)).is_ok());
    let origin = match (rejected, dir) {
        (Some(why), Some(dir)) => TableOrigin::Rebuilt(table_path(dir, geometry), why),
        _ => TableOrigin::Built(written),
    };
    Ok((table, origin, seconds))
}

/// Write `bytes` to `path` through a temporary file in the same directory.
fn write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let dir = path.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    // A name of this process and call: concurrent writers never share one.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = path.with_extension(format!("tmp{}-{call}", std::process::id()));
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(&tmp, path).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}

/// The mesh a table geometry names (for messages).
pub fn describe(geometry: &TableGeometry) -> String {
    let ReynoldsMesh {
        circumferential,
        axial,
    } = geometry.mesh;
    format!(
        "L/D = {:.4}, mesh {circumferential} × {axial}, {} cavitation",
        1.0 / geometry.slenderness.sqrt(),
        geometry.cavitation.name()
    )
}

/// A plain film's table with where it came from and what its build took:
/// what a bearing carries. Two are equal when their tables are.
#[derive(Debug, Clone)]
pub struct PreparedTable {
    pub table: FilmTable,
    pub origin: TableOrigin,
    /// Seconds the build took (0 when read from the cache).
    pub build_seconds: f64,
}

impl PartialEq for PreparedTable {
    fn eq(&self, other: &Self) -> bool {
        self.table == other.table
    }
}

impl PreparedTable {
    /// The table of `film`'s geometry ([`TableGeometry::of`]) through the
    /// cache in `dir` ([`load_or_build`]).
    pub fn load_or_build(film: &FiniteFilm, dir: Option<&Path>) -> Result<Self, ReynoldsError> {
        film.check()?;
        let (table, origin, build_seconds) = load_or_build(&TableGeometry::of(film), dir)?;
        Ok(Self {
            table,
            origin,
            build_seconds,
        })
    }

    /// One line on the table: its geometry, and built (seconds) or read.
    pub fn describe(&self) -> String {
        let what = describe(&self.table.geometry());
        match &self.origin {
            TableOrigin::Loaded(path) => format!("{what}: read from {}", path.display()),
            TableOrigin::Built(path) => format!(
                "{what}: built in {:.2} s{}",
                self.build_seconds,
                path.as_ref()
                    .map_or(String::new(), |p| format!(", cached at {}", p.display()))
            ),
            TableOrigin::Rebuilt(path, why) => format!(
                "{what}: cache file {} not trusted ({why}), rebuilt in {:.2} s",
                path.display(),
                self.build_seconds
            ),
        }
    }
}
