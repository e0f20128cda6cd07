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
    fn field_paths_map_to_lines() {
        let path = FieldPath::default().key("shaft").index(1).key("elements");
        assert_eq!(line_of_field(TEXT, &path), Some(6));
        let missing = FieldPath::default().key("disks").index(0);
        assert_eq!(line_of_field(TEXT, &missing), None);
        assert_eq!(line_of(TEXT, 0), 1);
        assert_eq!(line_of(TEXT, TEXT.len()), 10);
    }
}
