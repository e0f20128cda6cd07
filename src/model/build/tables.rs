//! Coefficient tables of `type = "table"` bearings and `[[seals]]`: inline
//! (`speeds_rpm` and one value or one value per speed for each of `kxx` …
//! `cyy`) or from a CSV file beside the model file (`table = "file.csv"`,
//! a `speed_rpm` column and any of the coefficient columns), with errors
//! naming the file, line and column. Negative and cross-coupled values are
//! allowed; non-finite values, unsorted or repeated speeds and columns of
//! another length than the speeds are not.

use std::path::{Path, PathBuf};

use crate::bearing::table::{COLUMNS, CoefficientTable};
use crate::model::context::Ctx;
use crate::model::error::FieldPath;
use crate::model::file::Coefficient;
use crate::model::{ModelError, TableFile};

/// The table keys of one entry as written.
pub(super) struct TableInput<'a> {
    pub speeds_rpm: &'a Option<Vec<f64>>,
    /// `kxx` … `cyy` in the order of [`COLUMNS`].
    pub columns: [&'a Option<Coefficient>; 8],
    pub table: &'a Option<String>,
    /// `mxx`, `mxy`, `myx`, `myy`.
    pub mass: [Option<f64>; 4],
}

/// A validated table entry.
pub(super) struct TableRead {
    pub table: CoefficientTable,
    /// Added mass (kg, row-major).
    pub added_mass: [[f64; 2]; 2],
    /// The file it was read from, if any.
    pub file: Option<TableFile>,
}

/// The validated table of entry `p`, its added mass and its file.
pub(super) fn coefficient_table(
    ctx: &Ctx,
    p: &FieldPath,
    input: &TableInput,
) -> Result<TableRead, ModelError> {
    let given = input.columns.iter().any(|c| c.is_some()) || input.speeds_rpm.is_some();
    let (table, file) = match (input.table, given) {
        (Some(_), true) => {
            return Err(ctx.err(
                p.key("table"),
                format!("{:?}", input.table.as_deref().unwrap_or_default()),
                "give either a table file or speeds_rpm and coefficient columns, not both",
            ));
        }
        (Some(name), false) => {
            let path = resolve(ctx, name);
            (from_csv(&path)?, Some((name.clone(), path)))
        }
        (None, _) => (inline(ctx, p, input)?, None),
    };
    let f = |key: &str, v: Option<f64>| ctx.finite(p.key(key), v.unwrap_or(0.0));
    let [mxx, mxy, myx, myy] = input.mass;
    let mass = [
        [f("mxx", mxx)?, f("mxy", mxy)?],
        [f("myx", myx)?, f("myy", myy)?],
    ];
    Ok(TableRead {
        table,
        added_mass: mass,
        file,
    })
}

/// A table file's path: as written if absolute, else beside the model file.
fn resolve(ctx: &Ctx, name: &str) -> PathBuf {
    let written = Path::new(name);
    if written.is_absolute() {
        return written.to_path_buf();
    }
    match Path::new(ctx.source).parent() {
        Some(dir) => dir.join(written),
        None => written.to_path_buf(),
    }
}

/// The inline table: `speeds_rpm` and the columns (constants without speeds).
fn inline(ctx: &Ctx, p: &FieldPath, input: &TableInput) -> Result<CoefficientTable, ModelError> {
    let speeds_rpm = match input.speeds_rpm {
        Some(s) => {
            if s.is_empty() {
                return Err(ctx.err(p.key("speeds_rpm"), "[]", "needs at least one speed"));
            }
            for (k, v) in s.iter().enumerate() {
                ctx.finite(p.key("speeds_rpm").index(k), *v)?;
                if k > 0 && *v <= s[k - 1] {
                    return Err(ctx.err(
                        p.key("speeds_rpm").index(k),
                        v,
                        &format!(
                            "speeds must increase (the entry before is {}); no speed may repeat",
                            s[k - 1]
                        ),
                    ));
                }
            }
            s.clone()
        }
        None => vec![0.0],
    };
    let n = speeds_rpm.len();
    let mut columns: [Vec<f64>; 8] = Default::default();
    for ((column, name), given) in columns.iter_mut().zip(COLUMNS).zip(input.columns) {
        *column = match given {
            None => vec![0.0; n],
            Some(Coefficient::Constant(v)) => vec![ctx.finite(p.key(name), *v)?; n],
            Some(Coefficient::Column(values)) => {
                if input.speeds_rpm.is_none() {
                    return Err(ctx.err(
                        p.key(name),
                        format!("{values:?}"),
                        "a column of values needs speeds_rpm (or give one value)",
                    ));
                }
                if values.len() != n {
                    return Err(ctx.err(
                        p.key(name),
                        format!("{values:?}"),
                        &format!("has {} values for {n} speeds in speeds_rpm", values.len()),
                    ));
                }
                for (k, v) in values.iter().enumerate() {
                    ctx.finite(p.key(name).index(k), *v)?;
                }
                values.clone()
            }
        };
    }
    let speeds = speeds_rpm
        .iter()
        .map(|&s| s * std::f64::consts::PI / 30.0)
        .collect();
    CoefficientTable::new(speeds, columns)
        .map_err(|e| ctx.err(p.key(e.column), "(table)", &e.source.to_string()))
}

/// A CSV table: a header naming `speed_rpm` and any of the coefficient
/// columns (missing ones are zero), then one row of numbers per speed;
/// blank lines and lines starting with `#` are skipped.
fn from_csv(path: &Path) -> Result<CoefficientTable, ModelError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| ModelError::Io {
        file: file.clone(),
        message: e.to_string(),
    })?;
    let invalid = |line: usize, field: &str, value: &str, problem: String| ModelError::Invalid {
        file: file.clone(),
        line: Some(line),
        field: field.to_string(),
        value: value.to_string(),
        problem,
    };
    let mut rows = text
        .lines()
        .enumerate()
        .map(|(k, l)| (k + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let Some((header_line, header)) = rows.next() else {
        return Err(invalid(1, "(header)", "", "the table file is empty".into()));
    };
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut column_of = [None; 8];
    let mut speed_column = None;
    for (c, name) in names.iter().enumerate() {
        let slot = if *name == "speed_rpm" {
            &mut speed_column
        } else if let Some(k) = COLUMNS.iter().position(|n| n == name) {
            &mut column_of[k]
        } else {
            return Err(invalid(
                header_line,
                name,
                name,
                format!("unknown column (known: speed_rpm, {})", COLUMNS.join(", ")),
            ));
        };
        if slot.is_some() {
            return Err(invalid(
                header_line,
                name,
                name,
                "column given twice".into(),
            ));
        }
        *slot = Some(c);
    }
    let Some(speed_column) = speed_column else {
        return Err(invalid(
            header_line,
            "speed_rpm",
            header,
            "the header has no speed_rpm column".into(),
        ));
    };
    let mut speeds_rpm: Vec<f64> = Vec::new();
    let mut columns: [Vec<f64>; 8] = Default::default();
    for (line, row) in rows {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        if cells.len() != names.len() {
            return Err(invalid(
                line,
                "(row)",
                row,
                format!("has {} values for {} columns", cells.len(), names.len()),
            ));
        }
        let number = |c: usize| -> Result<f64, ModelError> {
            match cells[c].parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(invalid(
                    line,
                    names[c],
                    cells[c],
                    "must be a finite number".into(),
                )),
            }
        };
        let speed = number(speed_column)?;
        if let Some(&last) = speeds_rpm.last() {
            if speed <= last {
                return Err(invalid(
                    line,
                    "speed_rpm",
                    cells[speed_column],
                    format!(
                        "speeds must increase (the row before has {last}); no speed may repeat"
                    ),
                ));
            }
        }
        speeds_rpm.push(speed);
        for (column, at) in columns.iter_mut().zip(column_of) {
            column.push(match at {
                Some(c) => number(c)?,
                None => 0.0,
            });
        }
    }
    if speeds_rpm.is_empty() {
        return Err(invalid(
            header_line,
            "(rows)",
            "",
            "the table has a header but no rows".into(),
        ));
    }
    let speeds = speeds_rpm
        .iter()
        .map(|&s| s * std::f64::consts::PI / 30.0)
        .collect();
    CoefficientTable::new(speeds, columns)
        .map_err(|e| invalid(header_line, e.column, "(table)", e.source.to_string()))
}
