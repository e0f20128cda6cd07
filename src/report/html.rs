//! One self-contained HTML page of analysis results: text blocks and PNG
//! figures inlined as base64 `data:` URIs, written as well-formed XHTML (every
//! element closed, text escaped) so an XML parser can check it.

use std::fmt::Write as _;

/// A section of the page.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Element id (letters, digits, `-`).
    pub id: String,
    /// Heading.
    pub title: String,
    /// Preformatted text (tables as the command line prints them).
    pub text: String,
    /// PNG figures with their alternative text.
    pub images: Vec<(Vec<u8>, String)>,
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

/// The page: a title, a table of contents and the sections in order.
pub fn page(title: &str, sections: &[Section]) -> String {
    let mut s = String::from(
        "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n",
    );
    writeln!(s, "<title>{}</title>", escape(title)).ok();
    s.push_str(
        "<style>body{font-family:sans-serif;max-width:1500px;margin:auto;padding:1em}pre{background:#f4f4f4;padding:0.6em;overflow-x:auto}img{max-width:100%;border:1px solid #ccc}</style>\n</head>\n<body>\n",
    );
    writeln!(s, "<h1>{}</h1>", escape(title)).ok();
    s.push_str("<ul>\n");
    for sec in sections {
        writeln!(
            s,
            "<li><a href=\"#{}\">{}</a></li>",
            escape(&sec.id),
            escape(&sec.title)
        )
        .ok();
    }
    s.push_str("</ul>\n");
    for sec in sections {
        writeln!(s, "<section id=\"{}\">", escape(&sec.id)).ok();
        writeln!(s, "<h2>{}</h2>", escape(&sec.title)).ok();
        if !sec.text.is_empty() {
            writeln!(s, "<pre>{}</pre>", escape(&sec.text)).ok();
        }
        for (png, alt) in &sec.images {
            writeln!(
                s,
                "<p><img alt=\"{}\" src=\"data:image/png;base64,{}\"/></p>",
                escape(alt),
                base64(png)
            )
            .ok();
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
    fn text_is_escaped() {
        assert_eq!(
            escape("a < b & \"c\" > 'd'"),
            "a &lt; b &amp; &quot;c&quot; &gt; &#39;d&#39;"
        );
        let p = page(
            "T & U",
            &[Section {
                id: "s".into(),
                title: "<x>".into(),
                text: "1 < 2".into(),
                images: vec![(vec![1, 2, 3], "alt".into())],
            }],
        );
        assert!(p.contains("<title>T &amp; U</title>"));
        assert!(p.contains("<pre>1 &lt; 2</pre>"));
        assert!(p.contains("src=\"data:image/png;base64,AQID\""));
    }
}
