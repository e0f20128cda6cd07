//! One self-contained HTML page of analysis results: a stamp (what was judged,
//! by which software, when), sections of real tables, paragraphs and PNG
//! figures inlined as base64 `data:` URIs, with print CSS so that "print to
//! PDF" gives clean A4 pages. Written as well-formed XHTML (every element
//! closed, text escaped) so an XML parser can check it.

use std::fmt::Write as _;

/// How a table cell is judged, for its colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Meets its criterion (green).
    Pass,
    /// Fails its criterion (red).
    Fail,
    /// Not judged (grey).
    NotJudged,
}

impl Verdict {
    /// `pass`/`fail`/`na`: the cell's CSS class.
    pub fn class(self) -> &'static str {
        match self {
            Self::Pass => "pass",
            Self::Fail => "fail",
            Self::NotJudged => "na",
        }
    }

    /// `pass` or `FAIL` (as the commands print them), or `not judged`.
    pub fn text(self) -> &'static str {
        match self {
            Self::Pass => "pass",
            Self::Fail => "FAIL",
            Self::NotJudged => "not judged",
        }
    }

    /// Pass or fail from a boolean.
    pub fn of(pass: bool) -> Self {
        if pass { Self::Pass } else { Self::Fail }
    }
}

/// A table cell: text, and a verdict colouring it.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    /// The text.
    pub text: String,
    /// Its verdict, if it is one.
    pub verdict: Option<Verdict>,
}

impl<T: Into<String>> From<T> for Cell {
    fn from(text: T) -> Self {
        Self {
            text: text.into(),
            verdict: None,
        }
    }
}

impl Cell {
    /// A verdict cell (`pass`, `FAIL`, `not judged`), coloured.
    pub fn verdict(v: Verdict) -> Self {
        Self {
            text: v.text().into(),
            verdict: Some(v),
        }
    }
}

/// A table with a caption and a heading row.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    /// Element id (letters, digits, `-`), for tests and links.
    pub id: String,
    /// Caption above the table.
    pub caption: String,
    /// Column headings.
    pub headers: Vec<String>,
    /// Rows of cells.
    pub rows: Vec<Vec<Cell>>,
}

/// A piece of a section.
#[derive(Debug, Clone, PartialEq)]
pub enum Block {
    /// A paragraph.
    Text(String),
    /// A table.
    Table(Table),
    /// A PNG figure with its caption.
    Figure(Vec<u8>, String),
    /// What could not be computed, and why: shown in red; the page goes on.
    Failure(String),
}

/// A section of the page.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Element id (letters, digits, `-`).
    pub id: String,
    /// Heading.
    pub title: String,
    /// Its content in order.
    pub blocks: Vec<Block>,
}

/// Base64 of `bytes` (RFC 4648, standard alphabet, `=` padding).
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(ALPHABET[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// `text` with `&`, `<`, `>`, `"` and `'` escaped for XML.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Screen and print styles: tables that wrap instead of overflowing, verdict
/// colours that print (`print-color-adjust`), A4 pages, each section from a
/// new page, figures and table rows never split.
const STYLE: &str = "body{font-family:sans-serif;max-width:1200px;margin:auto;padding:1em;color:#111}\
h1{font-size:1.6em}h2{border-bottom:2px solid #444;padding-bottom:0.2em}\
table{border-collapse:collapse;margin:0.6em 0 1.2em 0;width:100%;table-layout:auto}\
caption{text-align:left;font-weight:bold;padding:0.3em 0}\
th,td{border:1px solid #999;padding:0.25em 0.5em;text-align:left;vertical-align:top;overflow-wrap:anywhere}\
th{background:#e8e8e8}\
td.pass{background:#c8f0c8;color:#064006;font-weight:bold}\
td.fail{background:#f8c4c4;color:#8a0000;font-weight:bold}\
td.na{background:#eeeeee;color:#555}\
p.failure{background:#f8c4c4;color:#8a0000;padding:0.5em;font-weight:bold}\
figure{margin:0.6em 0;page-break-inside:avoid;break-inside:avoid}\
figcaption{font-size:0.9em;color:#333}\
img{max-width:100%;height:auto;border:1px solid #ccc}\
table.stamp td{border:none;padding:0.1em 0.6em 0.1em 0}table.stamp{width:auto}\
@page{size:A4;margin:14mm}\
@media print{body{max-width:none;padding:0;font-size:10pt}nav{display:none}\
section{break-before:page;page-break-before:always}section#summary{break-before:auto;page-break-before:auto}\
tr{break-inside:avoid;page-break-inside:avoid}thead{display:table-header-group}\
td.pass,td.fail,td.na,p.failure{-webkit-print-color-adjust:exact;print-color-adjust:exact}}";

/// Records, once the page has loaded, each figure's decoded size on it
/// (`data-decoded="W×H"`, 0×0 when a PNG fails to decode) and the page's
/// sideways overflow in pixels on the body: a headless browser's DOM dump
/// then shows that every figure rendered and nothing runs off the page.
const PROBE: &str = "window.addEventListener('load', function () {\
var ims = document.images; for (var i = 0; i !== ims.length; i++) {\
ims[i].setAttribute('data-decoded', ims[i].naturalWidth + 'x' + ims[i].naturalHeight); }\
document.body.setAttribute('data-overflow', String(document.documentElement.scrollWidth - document.documentElement.clientWidth)); });";

fn table(s: &mut String, t: &Table) {
    if t.id.is_empty() {
        s.push_str("<table>\n");
    } else {
        writeln!(s, "<table id=\"{}\">", escape(&t.id)).ok();
    }
    if !t.caption.is_empty() {
        writeln!(s, "<caption>{}</caption>", escape(&t.caption)).ok();
    }
    s.push_str("<thead><tr>");
    for h in &t.headers {
        write!(s, "<th>{}</th>", escape(h)).ok();
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for row in &t.rows {
        s.push_str("<tr>");
        for c in row {
            match c.verdict {
                Some(v) => write!(s, "<td class=\"{}\">{}</td>", v.class(), escape(&c.text)),
                None => write!(s, "<td>{}</td>", escape(&c.text)),
            }
            .ok();
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table>\n");
}

/// The page: a title, the stamp (label–value rows: model file, its SHA-256,
/// software version, date…), a table of contents and the sections in order.
pub fn page(title: &str, stamp: &[(String, String)], sections: &[Section]) -> String {
    let mut s = String::from(
        "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n",
    );
    writeln!(s, "<title>{}</title>", escape(title)).ok();
    writeln!(s, "<style>{STYLE}</style>").ok();
    writeln!(s, "<script>{PROBE}</script>").ok();
    s.push_str("</head>\n<body>\n");
    writeln!(s, "<h1>{}</h1>", escape(title)).ok();
    s.push_str("<table class=\"stamp\" id=\"stamp\">\n<tbody>\n");
    for (k, v) in stamp {
        writeln!(s, "<tr><td>{}</td><td>{}</td></tr>", escape(k), escape(v)).ok();
    }
    s.push_str("</tbody>\n</table>\n<nav>\n<ul>\n");
    for sec in sections {
        writeln!(
            s,
            "<li><a href=\"#{}\">{}</a></li>",
            escape(&sec.id),
            escape(&sec.title)
        )
        .ok();
    }
    s.push_str("</ul>\n</nav>\n");
    for sec in sections {
        writeln!(s, "<section id=\"{}\">", escape(&sec.id)).ok();
        writeln!(s, "<h2>{}</h2>", escape(&sec.title)).ok();
        for block in &sec.blocks {
            match block {
                Block::Text(t) => {
                    writeln!(s, "<p>{}</p>", escape(t)).ok();
                }
                Block::Table(t) => table(&mut s, t),
                Block::Figure(png, caption) => {
                    writeln!(
                        s,
                        "<figure><img alt=\"{}\" src=\"data:image/png;base64,{}\"/><figcaption>{}</figcaption></figure>",
                        escape(caption),
                        base64(png),
                        escape(caption)
                    )
                    .ok();
                }
                Block::Failure(t) => {
                    writeln!(s, "<p class=\"failure\">{}</p>", escape(t)).ok();
                }
            }
        }
        s.push_str("</section>\n");
    }
    s.push_str("</body>\n</html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// RFC 4648 §10 test vectors.
    #[test]
    fn base64_matches_the_rfc_vectors() {
        for (plain, coded) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
        assert_eq!(base64(&[0xff, 0xfe, 0x00]), "//4A");
    }

    #[test]
    fn text_is_escaped_and_tables_are_tables() {
        assert_eq!(
            escape("a < b & \"c\" > 'd'"),
            "a &lt; b &amp; &quot;c&quot; &gt; &#39;d&#39;"
        );
        let p = page(
            "T & U",
            &[("model".into(), "a<b>.toml".into())],
            &[Section {
                id: "s".into(),
                title: "<x>".into(),
                blocks: vec![
                    Block::Text("1 < 2".into()),
                    Block::Table(Table {
                        id: "t".into(),
                        caption: "c".into(),
                        headers: vec!["h".into()],
                        rows: vec![vec![Cell::verdict(Verdict::Fail)], vec!["x".into()]],
                    }),
                    Block::Figure(vec![1, 2, 3], "alt".into()),
                    Block::Failure("could not".into()),
                ],
            }],
        );
        assert!(p.contains("<title>T &amp; U</title>"));
        assert!(p.contains("<td>a&lt;b&gt;.toml</td>"));
        assert!(p.contains("<p>1 &lt; 2</p>"));
        assert!(p.contains("<td class=\"fail\">FAIL</td>"));
        assert!(p.contains("src=\"data:image/png;base64,AQID\""));
        assert!(p.contains("<p class=\"failure\">could not</p>"));
        // The probe script is XML text: no markup characters in it.
        assert!(!PROBE.contains('<') && !PROBE.contains('&'));
    }
}
