//! The on-disk cache of film force tables, plain films' ([`super::film_table`])
//! and tilting pads' ([`super::pad_table`]): one file per table geometry,
//! `film-<key>.table` (plain) or `pad-<key>.table` in the cache directory,
//! `<key>` the 64-bit FNV-1a hash of the geometry and the table format, in
//! hex ([`CacheKey`] says what each kind's header holds).
//!
//! **Directory** ([`cache_dir`]): `$ROTOR_CACHE_DIR` if set, else
//! `$XDG_CACHE_HOME/rotor`, else `$HOME/.cache/rotor`; none of them: no
//! cache (the table is built in memory every run).
//!
//! **File**: the magic (`rotor-film-table`, `rotor-pad-tables`), the format
//! version, the geometry in full (slenderness bits, a pad's arc bits, mesh,
//! cavitation), the node counts, the nodal
//! values `W` as little-endian `f64`, then the FNV-1a hash of all that. A
//! file that is short, of another version or geometry, with a wrong hash or
//! a non-finite value is not trusted: the table is rebuilt and the file
//! replaced ([`TableOrigin::Rebuilt`] says why). Files are written to a
//! temporary name and renamed, so a reader never sees half a file.

use std::any::Any;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Instant;

use super::film_table::{DIRECTIONS, ECCENTRICITY_INTERVALS, FilmTable, TableGeometry};
use super::finite_film::FiniteFilm;
use super::pad_table::{PadGeometry, PadTable};
use super::reynolds::{Cavitation, ReynoldsError, ReynoldsMesh};

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

/// A table geometry the cache keys files by: its header bytes (magic,
/// format version, geometry in full, node counts), its table and how that
/// is built. The plain film's ([`TableGeometry`]) and a pad's
/// ([`PadGeometry`]).
pub trait CacheKey: Copy + PartialEq {
    /// The table of this geometry.
    type Table: CachedTable<Key = Self>;
    /// The file name's prefix.
    const PREFIX: &'static str;
    /// The file's header.
    fn header(&self) -> Vec<u8>;
    /// How many `f64` the table's file holds after the header.
    fn numbers(&self) -> usize;
    /// Build the table (deterministically).
    fn build(&self) -> Result<Self::Table, ReynoldsError>;
    /// The table of the nodal numbers read from a file.
    fn table(&self, numbers: Vec<f64>) -> Self::Table;
    /// The geometry in words (for messages).
    fn describe(&self) -> String;
}

/// A table the cache stores: its geometry and nodal numbers.
pub trait CachedTable: PartialEq {
    type Key: CacheKey<Table = Self>;
    /// What the table was built for.
    fn key(&self) -> Self::Key;
    /// The nodal values, in file order.
    fn numbers(&self) -> Vec<f64>;
}

fn mesh_bytes(out: &mut Vec<u8>, mesh: ReynoldsMesh, cavitation: Cavitation) {
    out.extend_from_slice(&(mesh.circumferential as u64).to_le_bytes());
    out.extend_from_slice(&(mesh.axial as u64).to_le_bytes());
    out.push(cavitation_code(cavitation));
}

impl CacheKey for TableGeometry {
    type Table = FilmTable;
    const PREFIX: &'static str = "film";

    /// Magic `rotor-film-table`, version 1, slenderness bits, mesh,
    /// cavitation, node counts.
    fn header(&self) -> Vec<u8> {
        let mut out = Vec::new();
        out.extend_from_slice(b"rotor-film-table");
        out.extend_from_slice(&1u32.to_le_bytes());
        out.extend_from_slice(&self.slenderness.to_bits().to_le_bytes());
        mesh_bytes(&mut out, self.mesh, self.cavitation);
        out.extend_from_slice(&((ECCENTRICITY_INTERVALS + 1) as u64).to_le_bytes());
        out.extend_from_slice(&(DIRECTIONS as u64).to_le_bytes());
        out
    }

    fn numbers(&self) -> usize {
        (ECCENTRICITY_INTERVALS + 1) * DIRECTIONS * 2
    }

    fn build(&self) -> Result<FilmTable, ReynoldsError> {
        FilmTable::build(*self)
    }

    fn table(&self, numbers: Vec<f64>) -> FilmTable {
        let values = numbers.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
        FilmTable::from_values(*self, ECCENTRICITY_INTERVALS + 1, DIRECTIONS, values)
    }

    fn describe(&self) -> String {
        let ReynoldsMesh {
            circumferential,
            axial,
        } = self.mesh;
        format!(
            "L/D = {:.4}, mesh {circumferential} × {axial}, {} cavitation",
            1.0 / self.slenderness.sqrt(),
            self.cavitation.name()
        )
    }
}

impl CachedTable for FilmTable {
    type Key = TableGeometry;
    fn key(&self) -> TableGeometry {
        self.geometry()
    }
    fn numbers(&self) -> Vec<f64> {
        self.values().iter().flatten().copied().collect()
    }
}

impl CacheKey for PadGeometry {
    type Table = PadTable;
    const PREFIX: &'static str = "pad";

    /// Magic `rotor-pad-tables`, version 1, slenderness and arc bits, mesh,
    /// cavitation, node counts.
    fn header(&self) -> Vec<u8> {
        let mut out = Vec::new();
        out.extend_from_slice(b"rotor-pad-tables");
        out.extend_from_slice(&1u32.to_le_bytes());
        out.extend_from_slice(&self.slenderness.to_bits().to_le_bytes());
        out.extend_from_slice(&self.arc.to_bits().to_le_bytes());
        mesh_bytes(&mut out, self.mesh, self.cavitation);
        let (nt, np, ns) = PadTable::NODES;
        for n in [nt, np, ns] {
            out.extend_from_slice(&(n as u64).to_le_bytes());
        }
        out
    }

    fn numbers(&self) -> usize {
        let (nt, np, ns) = PadTable::NODES;
        nt * np * ns * 2
    }

    fn build(&self) -> Result<PadTable, ReynoldsError> {
        PadTable::build(*self)
    }

    fn table(&self, numbers: Vec<f64>) -> PadTable {
        let values = numbers.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
        PadTable::from_values(*self, values)
    }

    fn describe(&self) -> String {
        let ReynoldsMesh {
            circumferential,
            axial,
        } = self.mesh;
        format!(
            "pad arc {:.2}°, L/(Rβ) = {:.4}, mesh {circumferential} × {axial}, {} cavitation",
            self.arc.to_degrees(),
            2.0 / (self.slenderness.sqrt() * self.arc),
            self.cavitation.name()
        )
    }
}

impl CachedTable for PadTable {
    type Key = PadGeometry;
    fn key(&self) -> PadGeometry {
        self.geometry()
    }
    fn numbers(&self) -> Vec<f64> {
        self.values().iter().flatten().copied().collect()
    }
}

/// The cache file of `geometry` in `dir`: `<prefix>-<hash of the header>.table`.
pub fn table_path<K: CacheKey>(dir: &Path, geometry: &K) -> PathBuf {
    dir.join(format!(
        "{}-{:016x}.table",
        K::PREFIX,
        fnv1a(&geometry.header())
    ))
}

/// The bytes of a table's file.
pub fn encode<T: CachedTable>(table: &T) -> Vec<u8> {
    let mut out = table.key().header();
    for v in table.numbers() {
        out.extend_from_slice(&v.to_le_bytes());
    }
    let hash = fnv1a(&out);
    out.extend_from_slice(&hash.to_le_bytes());
    out
}

/// The table of a file's bytes, or why they are not one of `geometry`.
pub fn decode<K: CacheKey>(bytes: &[u8], geometry: &K) -> Result<K::Table, String> {
    let head = geometry.header();
    let size = head.len() + geometry.numbers() * 8 + 8;
    if bytes.len() != size {
        return Err(format!("{} bytes, not {size}", bytes.len()));
    }
    if bytes[..16] != head[..16] {
        return Err("not a film table of this kind".into());
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
    Ok(geometry.table(numbers))
}

/// The table of `geometry`: read from `dir` if a trusted file is there,
/// else built ([`CacheKey::build`]) and written there (a failed write
/// only loses the cache); with the seconds the build took (0 when read).
pub fn load_or_build<K: CacheKey>(
    geometry: &K,
    dir: Option<&Path>,
) -> Result<(K::Table, TableOrigin, f64), ReynoldsError> {
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
    let table = geometry.build()?;
    let seconds = start.elapsed().as_secs_f64();
    let written = path.filter(|p| write(p, &encode(&table)).is_ok());
    let origin = match (rejected, dir) {
        (Some(why), Some(dir)) => TableOrigin::Rebuilt(table_path(dir, geometry), why),
        _ => TableOrigin::Built(written),
    };
    Ok((table, origin, seconds))
}

/// How many tables [`PreparedTable::of_geometry`] keeps for the process
/// (the oldest dropped first): a table holds its nodal values and slopes,
/// 35 MB for a pad's.
const KEPT_TABLES: usize = 8;

/// The tables this process read or built, by their file header.
type Kept = Vec<(Vec<u8>, Arc<dyn Any + Send + Sync>)>;

fn kept() -> &'static Mutex<Kept> {
    static KEPT: OnceLock<Mutex<Kept>> = OnceLock::new();
    KEPT.get_or_init(|| Mutex::new(Vec::new()))
}

/// The kept table of the file header `header`, if any.
fn recall<T: Send + Sync + 'static>(header: &[u8]) -> Option<Arc<T>> {
    let kept = kept().lock().unwrap_or_else(|e| e.into_inner());
    kept.iter()
        .find(|(h, _)| h == header)
        .and_then(|(_, t)| t.clone().downcast::<T>().ok())
}

/// Keep `table` under its file header `header`.
fn keep<T: Send + Sync + 'static>(header: Vec<u8>, table: Arc<T>) {
    let mut kept = kept().lock().unwrap_or_else(|e| e.into_inner());
    kept.retain(|(h, _)| *h != header);
    if kept.len() >= KEPT_TABLES {
        kept.remove(0);
    }
    kept.push((header, table));
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
pub fn describe<K: CacheKey>(geometry: &K) -> String {
    geometry.describe()
}

/// A film's table (a plain film's by default, or a pad's) with where it
/// came from and what its build took: what a bearing carries. Two are
/// equal when their tables are.
#[derive(Debug, Clone)]
pub struct PreparedTable<T = FilmTable> {
    /// The table, shared with every model read in this process that named
    /// the same geometry ([`PreparedTable::of_geometry`]).
    pub table: Arc<T>,
    pub origin: TableOrigin,
    /// Seconds the build took (0 when read from the cache).
    pub build_seconds: f64,
}

impl<T: PartialEq> PartialEq for PreparedTable<T> {
    fn eq(&self, other: &Self) -> bool {
        self.table == other.table
    }
}

impl PreparedTable {
    /// The table of `film`'s geometry ([`TableGeometry::of`]) through the
    /// cache in `dir` ([`load_or_build`]).
    pub fn load_or_build(film: &FiniteFilm, dir: Option<&Path>) -> Result<Self, ReynoldsError> {
        film.check()?;
        Self::of_geometry(&TableGeometry::of(film), dir)
    }
}

impl PreparedTable<PadTable> {
    /// The table of a pad of arc `arc` (rad) on `film` ([`PadGeometry::of`])
    /// through the cache in `dir` ([`load_or_build`]).
    pub fn load_or_build_pad(
        film: &FiniteFilm,
        arc: f64,
        dir: Option<&Path>,
    ) -> Result<Self, ReynoldsError> {
        film.check()?;
        Self::of_geometry(&PadGeometry::of(film, arc), dir)
    }
}

impl<T: CachedTable + Send + Sync + 'static> PreparedTable<T> {
    /// The table of `geometry` through the cache in `dir` ([`load_or_build`]);
    /// a table this process already read or built for the same geometry
    /// (its file header, [`CacheKey::header`]) is taken again when `dir`
    /// holds its file, without reading or preparing it (an FMU instantiated
    /// again, a model read again: reading the compressor takes 50 times as
    /// long as the Jeffcott rotor's otherwise, one run each, nearly all of
    /// it preparing its tables), as `Loaded` from that file. The tables are deterministic:
    /// the same geometry gives the same table to the bit.
    pub fn of_geometry(geometry: &T::Key, dir: Option<&Path>) -> Result<Self, ReynoldsError> {
        let header = geometry.header();
        if let Some(path) = dir.map(|d| table_path(d, geometry)).filter(|p| p.is_file())
            && let Some(table) = recall::<T>(&header)
        {
            return Ok(Self {
                table,
                origin: TableOrigin::Loaded(path),
                build_seconds: 0.0,
            });
        }
        let (table, origin, build_seconds) = load_or_build(geometry, dir)?;
        let table = Arc::new(table);
        keep(header, table.clone());
        Ok(Self {
            table,
            origin,
            build_seconds,
        })
    }

    /// One line on the table: its geometry, and built (seconds) or read.
    pub fn describe(&self) -> String {
        let what = self.table.key().describe();
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
