//! `rotor report`: one self-contained HTML page. Parsed as XML (well-formed),
//! every section present, every figure an inline PNG, and its tables equal to
//! what the single commands print.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use quick_xml::Reader;
use quick_xml::events::Event;

fn rotor(args: &[&str], model: &Path) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg(args[0])
        .arg(model)
        .args(&args[1..])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// Standard base64 decoding (RFC 4648), for checking the inlined images.
fn decode_base64(text: &str) -> Vec<u8> {
    let value = |c: u8| -> u32 {
        match c {
            b'A'..=b'Z' => u32::from(c - b'A'),
            b'a'..=b'z' => u32::from(c - b'a') + 26,
            b'0'..=b'9' => u32::from(c - b'0') + 52,
            b'+' => 62,
            b'/' => 63,
            _ => panic!("not base64: {c}"),
        }
    };
    let bytes = text.trim_end_matches('=').as_bytes();
    let mut out = Vec::new();
    for chunk in bytes.chunks(4) {
        let mut n = 0u32;
        for (k, &c) in chunk.iter().enumerate() {
            n |= value(c) << (18 - 6 * k);
        }
        for k in 0..chunk.len() - 1 {
            out.push((n >> (16 - 8 * k)) as u8);
        }
    }
    out
}

/// Section id → (its `<pre>` text, the decoded bytes of its images).
type Sections = BTreeMap<String, (String, Vec<Vec<u8>>)>;

fn parse(html: &str) -> Sections {
    let mut reader = Reader::from_str(html);
    let mut sections = Sections::new();
    let mut current: Option<String> = None;
    let mut in_pre = false;
    loop {
        match reader
            .read_event()
            .unwrap_or_else(|e| panic!("not well-formed at {}: {e}", reader.buffer_position()))
        {
            Event::Start(e) | Event::Empty(e) => {
                let attrs: BTreeMap<String, String> = e
                    .attributes()
                    .map(|a| {
                        let a = a.unwrap();
                        (
                            String::from_utf8(a.key.as_ref().to_vec()).unwrap(),
                            a.normalized_value(quick_xml::XmlVersion::Implicit1_0)
                                .unwrap()
                                .into_owned(),
                        )
                    })
                    .collect();
                match e.name().as_ref() {
                    b"section" => {
                        let id = attrs["id"].clone();
                        sections.insert(id.clone(), (String::new(), Vec::new()));
                        current = Some(id);
                    }
                    b"pre" => in_pre = true,
                    b"img" => {
                        let src = &attrs["src"];
                        let data = src.strip_prefix("data:image/png;base64,").unwrap();
                        let id = current.clone().expect("image outside a section");
                        sections.get_mut(&id).unwrap().1.push(decode_base64(data));
                    }
                    _ => {}
                }
            }
            Event::Text(t) if in_pre => {
                let id = current.clone().unwrap();
                let text = t.decode().unwrap().into_owned();
                sections.get_mut(&id).unwrap().0.push_str(&text);
            }
            Event::GeneralRef(r) if in_pre => {
                let id = current.clone().unwrap();
                let c = match r.resolve_char_ref().unwrap() {
                    Some(c) => c,
                    None => match r.decode().unwrap().as_ref() {
                        "amp" => '&',
                        "lt" => '<',
                        "gt" => '>',
                        "quot" => '"',
                        other => panic!("unknown entity &{other};"),
                    },
                };
                sections.get_mut(&id).unwrap().0.push(c);
            }
            Event::End(e) => match e.name().as_ref() {
                b"pre" => in_pre = false,
                b"section" => current = None,
                _ => {}
            },
            Event::Eof => break,
            _ => {}
        }
    }
    sections
}

#[test]
fn report_of_the_damped_classic_rotor_is_complete_and_well_formed() {
    let model =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/classic_disk_rotor_damped.toml");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("report.html");
    let out_text = out.to_str().unwrap();
    rotor(&["report", "--rpm", "3000", "--out", out_text], &model);
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    let sections = parse(&html);
    let ids: Vec<&str> = sections.keys().map(String::as_str).collect();
    assert_eq!(
        ids,
        [
            "model",
            "modes",
            "operating-point",
            "stability",
            "ucs",
            "unbalance"
        ]
    );
    for (id, (_, images)) in &sections {
        let want = usize::from(id != "operating-point");
        assert_eq!(images.len(), want, "{id}");
        for png in images {
            assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{id}");
            assert!(png.len() > 10_000, "{id}: {} bytes", png.len());
        }
    }
    // The tables are those of the single commands.
    assert_eq!(sections["model"].0, rotor(&["info"], &model));
    assert_eq!(
        sections["operating-point"].0,
        rotor(&["operating-point", "--rpm", "3000"], &model)
    );
    assert_eq!(
        sections["stability"].0,
        rotor(&["stability", "--rpm", "3000"], &model)
    );
    assert_eq!(
        sections["modes"].0,
        rotor(&["modes", "--rpm", "3000", "--modes", "8"], &model)
    );
    let unbalance = rotor(
        &[
            "unbalance",
            "--max-rpm",
            "6000",
            "--points",
            "201",
            "--operating-rpm",
            "3000:3000",
        ],
        &model,
    );
    let table = unbalance.lines().skip(2).collect::<Vec<_>>().join("\n");
    assert!(
        sections["unbalance"].0.ends_with(&format!("{table}\n")),
        "{}",
        sections["unbalance"].0
    );
}

#[test]
fn a_broken_page_is_caught() {
    let html = "<!DOCTYPE html>\n<html><body><section id=\"a\"><pre>x</section></body></html>";
    assert!(std::panic::catch_unwind(|| parse(html)).is_err());
}

/// The page renders in a browser: a headless Chromium screenshot of it is a
/// non-trivial PNG. Skipped (with a message) where `/usr/bin/chromium` is not
/// installed; the test never installs it.
#[test]
fn page_renders_in_headless_chromium_when_available() {
    let chromium = Path::new("/usr/bin/chromium");
    if !chromium.exists() {
        eprintln!("skipped: /usr/bin/chromium not installed");
        return;
    }
    let model = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/classic_disk_rotor.toml");
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report_chromium");
    std::fs::create_dir_all(&dir).unwrap();
    let (page, shot) = (dir.join("report.html"), dir.join("shot.png"));
    let _ = std::fs::remove_file(&shot);
    rotor(
        &["report", "--rpm", "3000", "--out", page.to_str().unwrap()],
        &model,
    );
    let out = Command::new(chromium)
        .args([
            "--headless",
            "--disable-gpu",
            "--no-sandbox",
            "--window-size=1400,4000",
        ])
        .arg(format!("--screenshot={}", shot.display()))
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&shot).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert!(bytes.len() > 50_000, "screenshot of {} bytes", bytes.len());
}
