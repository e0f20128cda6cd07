//! Between field paths and positions in the model text, from the TOML parser's
//! spans: the line of a field (for validation errors) and the field covering a
//! span (for type and syntax errors, whose messages the parser gives without
//! the path).

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use super::error::{FieldPath, Seg};

/// 1-based line of a byte offset.
pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Line of the field at `path` in `text`, `None` when the text does not hold it.
pub(crate) fn line_of_field(text: &str, path: &FieldPath) -> Option<usize> {
    let root = DeTable::parse(text).ok()?;
    let mut span = root.span();
    let mut table = Some(root.get_ref());
    let mut value: Option<&DeValue> = None;
    for seg in &path.0 {
        let next = match (seg, table, value) {
            (Seg::Key(k), Some(t), _) => t.get(k.as_str()),
            (Seg::Key(k), None, Some(v)) => v.get(k.as_str()),
            (Seg::Index(i), _, Some(v)) => v.get(*i),
            _ => None,
        }?;
        span = next.span();
        table = None;
        value = Some(next.get_ref());
    }
    Some(line_of(text, span.start))
}

/// The deepest field of `text` whose key or value covers the byte range `at`
/// (an error's span); `None` when no field does (an error of the whole
/// document). Tolerates syntax errors: the parser's partial document is searched.
pub(crate) fn field_at(text: &str, at: &Range<usize>) -> Option<FieldPath> {
    let (root, _) = DeTable::parse_recoverable(text);
    let segs = in_table(root.get_ref(), at)?;
    (!segs.is_empty()).then_some(FieldPath(segs))
}

/// Whether `span` covers all of `at`.
fn covers(span: &Range<usize>, at: &Range<usize>) -> bool {
    span.start <= at.start && at.end <= span.end && (span.start < span.end || span == at)
}

fn in_table(table: &DeTable, at: &Range<usize>) -> Option<Vec<Seg>> {
    for (key, value) in table.iter() {
        let here = Seg::Key(key.get_ref().to_string());
        if covers(&key.span(), at) {
            return Some(vec![here]);
        }
        if let Some(mut rest) = in_value(value.get_ref(), &value.span(), at) {
            rest.insert(0, here);
            return Some(rest);
        }
    }
    None
}

fn in_value(value: &DeValue, span: &Range<usize>, at: &Range<usize>) -> Option<Vec<Seg>> {
    let inner = match value {
        DeValue::Table(t) => in_table(t, at),
        DeValue::Array(a) => a.iter().enumerate().find_map(|(i, e)| {
            in_value(e.get_ref(), &e.span(), at).map(|mut rest| {
                rest.insert(0, Seg::Index(i));
                rest
            })
        }),
        _ => None,
    };
    inner.or_else(|| covers(span, at).then(Vec::new))
}

/// The key of the table entry at `entry` (e.g. `bearings[0]`, which serde reads
/// whole to choose its `type`, losing the key's position) that holds the value
/// a type error names (`invalid type: floating point \`inf\`, expected i64`).
pub(crate) fn culprit_in_entry(text: &str, entry: &FieldPath, message: &str) -> Option<FieldPath> {
    let found = message
        .strip_prefix("invalid type: ")?
        .split(", expected")
        .next()?;
    let literal = found.split('`').nth(1);
    let number = |raw: &str| raw.replace('_', "").parse::<f64>().ok();
    let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
    let matches = |value: &DeValue| -> bool {
        match value {
            DeValue::Float(f) if found.starts_with("floating point") => {
                matches!((number(f.as_str()), literal.and_then(number)), (Some(a), Some(b)) if same(a, b))
            }
            DeValue::Integer(i) if found.starts_with("integer") => {
                matches!((number(i.as_str()), literal.and_then(number)), (Some(a), Some(b)) if same(a, b))
            }
            DeValue::String(t) if found.starts_with("string") => {
                found.strip_prefix("string ").map(|q| q.trim_matches('"')) == Some(&**t)
            }
            DeValue::Boolean(b) if found.starts_with("boolean") => literal == Some(&b.to_string()),
            DeValue::Array(_) => found == "sequence",
            DeValue::Table(_) => found == "map",
            _ => false,
        }
    };
    let root = DeTable::parse(text).ok()?;
    let mut table: &DeTable = root.get_ref();
    let mut value: Option<&DeValue> = None;
    for seg in &entry.0 {
        let next = match (seg, value) {
            (Seg::Key(k), None) => table.get(k.as_str()),
            (Seg::Key(k), Some(v)) => v.get(k.as_str()),
            (Seg::Index(i), Some(v)) => v.get(*i),
            _ => None,
        }?;
        value = Some(next.get_ref());
    }
    if let Some(DeValue::Table(t)) = value {
        table = t;
    } else {
        return None;
    }
    table
        .iter()
        .find(|(_, v)| matches(v.get_ref()))
        .map(|(k, _)| entry.clone().key(k.get_ref()))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "name = \"a\"\n[[shaft]]\nlength = 1.0\n[[shaft]]\nlength = 2.0\nelements = 3\n[[bearings]]\ntype = \"plain\"\nradius = 0.1\n";

    fn at(needle: &str) -> String {
        let start = TEXT.find(needle).unwrap();
        field_at(TEXT, &(start..start + needle.trim().len()))
            .map(|p| p.to_string())
            .unwrap_or_default()
    }

    #[test]
    fn spans_map_to_field_paths() {
        assert_eq!(at("\"a\""), "name");
        assert_eq!(at("2.0"), "shaft[1].length");
        assert_eq!(at("elements"), "shaft[1].elements");
        assert_eq!(at("3\n"), "shaft[1].elements");
        assert_eq!(at("0.1"), "bearings[0].radius");
        assert_eq!(field_at(TEXT, &(0..TEXT.len())), None);
    }

    #[test]
    fn a_type_error_in_a_whole_entry_finds_its_key() {
        let text = "[[bearings]]\ntype = \"plain\"\nnode = inf\nradius = 0.1\n[[bearings]]\npads = -1e-3\nname = \"x\"\n";
        let entry = |i| FieldPath::default().key("bearings").index(i);
        let found = |i, m: &str| culprit_in_entry(text, &entry(i), m).map(|p| p.to_string());
        assert_eq!(
            found(0, "invalid type: floating point `inf`, expected i64").as_deref(),
            Some("bearings[0].node")
        );
        assert_eq!(
            found(1, "invalid type: floating point `-0.001`, expected usize").as_deref(),
            Some("bearings[1].pads")
        );
        assert_eq!(found(0, "missing field `length`"), None);
    }

    #[test]
    fn field_paths_map_to_lines() {
        let path = FieldPath::default().key("shaft").index(1).key("elements");
        assert_eq!(line_of_field(TEXT, &path), Some(6));
        let missing = FieldPath::default().key("disks").index(0);
        assert_eq!(line_of_field(TEXT, &missing), None);
        assert_eq!(line_of(TEXT, 0), 1);
        assert_eq!(line_of(TEXT, TEXT.len()), 10);
    }
}
