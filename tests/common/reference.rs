//! Reading the reference data in `tests/data/` (see its README): shared by the
//! tests that compare against the quadrature oracles.

use std::path::PathBuf;

use nalgebra::Matrix2;
use serde_json::Value;

/// The JSON file `tests/data/{name}`.
pub fn reference(name: &str) -> Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap()
}

/// A JSON number.
pub fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A 2×2 JSON matrix `[[a, b], [c, d]]`.
#[allow(dead_code)]
pub fn mat(v: &Value) -> Matrix2<f64> {
    Matrix2::new(num(&v[0][0]), num(&v[0][1]), num(&v[1][0]), num(&v[1][1]))
}
