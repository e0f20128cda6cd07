//! Speed tables: CSV text with lines `time_s,speed_rpm` (a header line, blank
//! lines and `#` comments allowed), the speed input of a simulation.

/// A line of a speed table that is not two numbers.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{file}:{line}: expected two numbers time_s,speed_rpm, got {text:?}")]
pub struct SpeedTableError {
    /// File name as given.
    pub file: String,
    /// 1-based line number.
    pub line: usize,
    /// The offending line, trimmed.
    pub text: String,
}

/// The points `(time (s), speed (rpm))` of the speed table `text`, in file
/// order; `file` names it in errors. A first line that is not two numbers is
/// taken as a header. Ordering and finiteness are checked by the user of the
/// table (the solver's speed profile).
pub fn parse(text: &str, file: &str) -> Result<Vec<(f64, f64)>, SpeedTableError> {
    let mut points = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let cols: Vec<&str> = line.split(',').collect();
        let parsed: Option<(f64, f64)> = match cols.as_slice() {
            [a, b] => a.trim().parse().ok().zip(b.trim().parse().ok()),
            _ => None,
        };
        match parsed {
            Some(point) => points.push(point),
            None if k == 0 => {}
            None => {
                return Err(SpeedTableError {
                    file: file.to_string(),
                    line: k + 1,
                    text: line.to_string(),
                });
            }
        }
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_comments_and_blank_lines_are_skipped() {
        let text = "time_s,speed_rpm\n# run-up\n0, 0\n\n1.5,3000\n 2 , 3000.5 \n";
        let points = parse(text, "s.csv").unwrap();
        assert_eq!(points, vec![(0.0, 0.0), (1.5, 3000.0), (2.0, 3000.5)]);
        assert_eq!(parse("0,0\n1,10\n", "s.csv").unwrap().len(), 2);
    }

    #[test]
    fn a_bad_line_names_file_and_line() {
        let e = parse("time_s,speed_rpm\n0,0\n1;10\n", "s.csv").unwrap_err();
        assert_eq!(
            e.to_string(),
            "s.csv:3: expected two numbers time_s,speed_rpm, got \"1;10\""
        );
        assert!(parse("0,0\n1,2,3\n", "s.csv").is_err());
    }
}
