//! The cache round trip of a film force table (plain or pad,
//! `bearing::film_table_cache`), checked alike for both kinds.

use std::path::Path;

use rotor_bearing::bearing::film_table_cache::{
    CacheKey, TableOrigin, decode, encode, load_or_build,
};

/// In the empty folder `dir` (removed at the end): the table of `geometry`
/// is built and written as `<prefix>-<hash>.table`, then read back as the
/// identical table at no build time; its image decodes to it; the image is
/// refused for `other` (another geometry), truncated, or with one bit
/// flipped (named by the hash); a file with that bit flipped is rebuilt,
/// bit for bit the same table, and rewritten.
pub fn assert_round_trip<K>(geometry: &K, other: &K, dir: &Path)
where
    K: CacheKey + std::fmt::Debug,
    K::Table: std::fmt::Debug,
{
    let _ = std::fs::remove_dir_all(dir);
    let (built, origin, _) = load_or_build(geometry, Some(dir)).unwrap();
    let TableOrigin::Built(Some(path)) = origin else {
        panic!("not built and written: {origin:?}")
    };
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    assert!(name.starts_with(&format!("{}-", K::PREFIX)), "{name}");
    let (loaded, origin, seconds) = load_or_build(geometry, Some(dir)).unwrap();
    assert_eq!(origin, TableOrigin::Loaded(path.clone()));
    assert_eq!((loaded == built, seconds), (true, 0.0));
    let bytes = encode(&built);
    assert!(decode(&bytes, geometry).unwrap() == built);
    assert!(decode(&bytes, other).is_err(), "{other:?}");
    assert!(decode(&bytes[..bytes.len() - 1], geometry).is_err());
    let mut flipped = bytes.clone();
    flipped[bytes.len() / 2] ^= 4;
    assert!(decode(&flipped, geometry).unwrap_err().contains("hash"));
    std::fs::write(&path, &flipped).unwrap();
    let (rebuilt, origin, _) = load_or_build(geometry, Some(dir)).unwrap();
    assert!(matches!(origin, TableOrigin::Rebuilt(_, ref why) if why.contains("hash")));
    assert!(rebuilt == built, "the rebuild is the same table to the bit");
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
    std::fs::remove_dir_all(dir).unwrap();
}
