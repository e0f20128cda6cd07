//! `rotor report`: one self-contained page to sign. Parsed as XML
//! (well-formed), its stamp checked against independent tools (`sha256sum`,
//! `date`, `git describe`), its summary's verdicts and its tables against the
//! single commands' output, and rendered in a real headless Chromium (Debian's
//! package, installed by `scripts/setup.sh`): every figure decodes at its
//! PNG's own size, no table runs off the page, and print to PDF gives one
//! page per section at least.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use quick_xml::Reader;
use quick_xml::events::Event;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn rotor(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(args)
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

/// A table: headings and rows of `(text, class)` cells.
#[derive(Debug, Default, Clone)]
struct Table {
    headers: Vec<String>,
    rows: Vec<Vec<(String, String)>>,
}

impl Table {
    fn column(&self, name: &str) -> usize {
        self.headers
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name} in {:?}", self.headers))
    }
}

#[derive(Debug, Default)]
struct Section {
    tables: BTreeMap<String, Table>,
    images: Vec<Vec<u8>>,
    failures: Vec<String>,
    text: String,
}

#[derive(Debug, Default)]
struct Page {
    stamp: BTreeMap<String, String>,
    sections: BTreeMap<String, Section>,
    order: Vec<String>,
}

fn attributes(e: &quick_xml::events::BytesStart) -> BTreeMap<String, String> {
    e.attributes()
        .map(|a| {
            let a = a.unwrap();
            (
                String::from_utf8(a.key.as_ref().to_vec()).unwrap(),
                a.normalized_value(quick_xml::XmlVersion::Implicit1_0)
                    .unwrap()
                    .into_owned(),
            )
        })
        .collect()
}

/// The page parsed as XML: a malformed page panics.
fn parse(html: &str) -> Page {
    let mut reader = Reader::from_str(html);
    let mut page = Page::default();
    let mut section: Option<String> = None;
    let mut table: Option<(String, Table)> = None;
    let mut cell: Option<(String, String)> = None;
    let mut in_header = false;
    let mut row: Vec<(String, String)> = Vec::new();
    let mut failure: Option<String> = None;
    let mut paragraph = false;
    let mut stamp_cells: Vec<String> = Vec::new();
    loop {
        let event = reader
            .read_event()
            .unwrap_or_else(|e| panic!("not well-formed at {}: {e}", reader.buffer_position()));
        match event {
            Event::Start(e) | Event::Empty(e) => {
                let attrs = attributes(&e);
                match e.name().as_ref() {
                    b"section" => {
                        let id = attrs["id"].clone();
                        page.order.push(id.clone());
                        page.sections.insert(id.clone(), Section::default());
                        section = Some(id);
                    }
                    b"table" => {
                        table = Some((
                            attrs.get("id").cloned().unwrap_or_default(),
                            Table::default(),
                        ))
                    }
                    b"thead" => in_header = true,
                    b"tr" => row.clear(),
                    b"th" | b"td" => {
                        cell = Some((
                            String::new(),
                            attrs.get("class").cloned().unwrap_or_default(),
                        ))
                    }
                    b"p" if attrs.get("class").is_some_and(|c| c == "failure") => {
                        failure = Some(String::new())
                    }
                    b"p" => paragraph = true,
                    b"img" => {
                        let src = &attrs["src"];
                        let data = src.strip_prefix("data:image/png;base64,").unwrap();
                        let id = section.clone().expect("image outside a section");
                        page.sections
                            .get_mut(&id)
                            .unwrap()
                            .images
                            .push(decode_base64(data));
                    }
                    _ => {}
                }
            }
            Event::Text(t) => {
                let text = t.decode().unwrap().into_owned();
                push_text(
                    &mut cell,
                    &mut failure,
                    paragraph,
                    &section,
                    &mut page,
                    &text,
                );
            }
            Event::GeneralRef(r) => {
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
                push_text(
                    &mut cell,
                    &mut failure,
                    paragraph,
                    &section,
                    &mut page,
                    &c.to_string(),
                );
            }
            Event::End(e) => match e.name().as_ref() {
                b"th" | b"td" => {
                    let c = cell.take().unwrap();
                    if table.as_ref().is_some_and(|(id, _)| id == "stamp") {
                        stamp_cells.push(c.0.clone());
                    }
                    row.push(c);
                }
                b"tr" => {
                    if let Some((id, t)) = table.as_mut() {
                        if id == "stamp" {
                            page.stamp
                                .insert(stamp_cells[0].clone(), stamp_cells[1].clone());
                            stamp_cells.clear();
                        } else if in_header {
                            t.headers = row.iter().map(|c| c.0.clone()).collect();
                        } else {
                            t.rows.push(row.clone());
                        }
                    }
                }
                b"thead" => in_header = false,
                b"table" => {
                    let (id, t) = table.take().unwrap();
                    if let Some(s) = &section {
                        page.sections.get_mut(s).unwrap().tables.insert(id, t);
                    }
                }
                b"p" => {
                    paragraph = false;
                    if let (Some(f), Some(s)) = (failure.take(), &section) {
                        page.sections.get_mut(s).unwrap().failures.push(f);
                    }
                }
                b"section" => section = None,
                _ => {}
            },
            Event::Eof => break,
            _ => {}
        }
    }
    page
}

fn push_text(
    cell: &mut Option<(String, String)>,
    failure: &mut Option<String>,
    paragraph: bool,
    section: &Option<String>,
    page: &mut Page,
    text: &str,
) {
    if let Some(c) = cell.as_mut() {
        c.0.push_str(text);
    } else if let Some(f) = failure.as_mut() {
        f.push_str(text);
    } else if paragraph {
        if let Some(s) = section {
            page.sections.get_mut(s).unwrap().text.push_str(text);
        }
    }
}

/// Width and height from a PNG's IHDR chunk.
fn png_size(png: &[u8]) -> (u32, u32) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&png[12..16], b"IHDR");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&png[16..20]), be(&png[20..24]))
}

fn write_report(args: &[&str], name: &str) -> (PathBuf, Page) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join(format!("{name}.html"));
    let _ = std::fs::remove_file(&out);
    let mut all: Vec<&str> = args.to_vec();
    let out_text = out.to_str().unwrap().to_string();
    all.extend(["--out", &out_text]);
    rotor(&all);
    let html = std::fs::read_to_string(&out).unwrap();
    assert!(html.starts_with("<!DOCTYPE html>"));
    (out, parse(&html))
}

const SECTIONS: [&str; 8] = [
    "summary",
    "model",
    "campbell",
    "unbalance",
    "operating-point",
    "modes",
    "stability",
    "ucs",
];

/// Summary rows of check `check`: (item, value, criterion, verdict text, class).
fn summary_rows<'a>(page: &'a Page, check: &str) -> Vec<&'a Vec<(String, String)>> {
    page.sections["summary"].tables["summary-table"]
        .rows
        .iter()
        .filter(|r| r[0].0 == check)
        .collect()
}

/// The verdict column of the margins table `rotor campbell` prints.
fn campbell_verdicts(stdout: &str) -> Vec<String> {
    let table = stdout
        .split("separation margins (API 684, AF = 1/(2ζ))")
        .nth(1)
        .unwrap_or_else(|| panic!("{stdout}"));
    table
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with("  "))
        .map(|l| l.split_whitespace().last().unwrap().to_string())
        .collect()
}

/// The pump with its stage data: every section, figure and table; the stamp
/// against independent tools; the summary's verdicts those of the single
/// commands, coloured.
#[test]
fn report_of_the_pump_is_complete_and_agrees_with_the_commands() {
    let pump = root().join("examples/my_pump.toml");
    let pump_s = pump.to_str().unwrap();
    let stage = [
        "--power",
        "150e3",
        "--impeller-diameter",
        "0.3",
        "--flow-width",
        "0.02",
    ];
    let mut args = vec!["report", pump_s];
    args.extend(stage);
    let (_, page) = write_report(&args, "pump");
    assert_eq!(page.order, SECTIONS);
    for id in SECTIONS {
        let s = &page.sections[id];
        assert!(s.failures.is_empty(), "{id}: {:?}", s.failures);
        let want = usize::from(!matches!(id, "summary" | "operating-point"));
        assert_eq!(s.images.len(), want, "{id}");
        for png in &s.images {
            let (w, h) = png_size(png);
            assert!(w >= 800 && h >= 500, "{id}: {w}×{h}");
        }
    }
    // The stamp: the file, its SHA-256 (sha256sum), today (date -u), the build.
    assert_eq!(page.stamp["model file"], pump_s);
    let sum = Command::new("sha256sum").arg(&pump).output().unwrap();
    let sum = String::from_utf8(sum.stdout).unwrap();
    assert_eq!(
        page.stamp["model SHA-256"],
        sum.split_whitespace().next().unwrap()
    );
    let today = Command::new("date")
        .args(["-u", "+%Y-%m-%d"])
        .output()
        .unwrap();
    let today = String::from_utf8(today.stdout).unwrap();
    assert!(
        page.stamp["date"].starts_with(today.trim()),
        "{:?}",
        page.stamp
    );
    assert!(page.stamp["date"].ends_with(" UTC"));
    let commit = Command::new("git")
        .args(["describe", "--always", "--tags"])
        .current_dir(root())
        .output()
        .unwrap();
    let commit = String::from_utf8(commit.stdout).unwrap();
    let software = &page.stamp["software"];
    assert!(
        software.starts_with(&format!("rotor_bearing {} (", env!("CARGO_PKG_VERSION")))
            && software.contains(commit.trim()),
        "{software} vs {commit}"
    );
    assert_eq!(page.stamp["operating speed"], "3600 rpm");

    // Campbell: the summary's verdicts are `rotor campbell`'s, in order.
    let campbell = rotor(&["campbell", pump_s, "--operating-rpm", "3600:3600"]);
    let expected = campbell_verdicts(&campbell);
    let rows = summary_rows(&page, "critical speed (Campbell)");
    assert_eq!(rows.len(), expected.len());
    for (row, v) in rows.iter().zip(&expected) {
        assert_eq!(&row[4].0, v);
        assert_eq!(row[4].1, if v == "pass" { "pass" } else { "fail" });
    }
    let table = &page.sections["campbell"].tables["critical-speeds"];
    let speeds: Vec<&str> = campbell
        .lines()
        .filter(|l| l.contains(" rpm (") && l.contains("ζ = "))
        .take(table.rows.len())
        .map(|l| l.split_whitespace().next().unwrap())
        .collect();
    let col = table.column("speed (rpm)");
    assert_eq!(
        table
            .rows
            .iter()
            .map(|r| r[col].0.as_str())
            .collect::<Vec<_>>(),
        speeds
    );

    // Unbalance: the table is the command's, cell for cell; verdicts too.
    let unbalance = rotor(&["unbalance", pump_s, "--operating-rpm", "3600:3600"]);
    let printed: Vec<Vec<&str>> = unbalance
        .lines()
        .skip_while(|l| !l.starts_with("point "))
        .skip(1)
        .map(|l| l.split_whitespace().collect())
        .collect();
    let table = &page.sections["unbalance"].tables["unbalance-peaks"];
    assert_eq!(table.rows.len(), printed.len());
    for (row, words) in table.rows.iter().zip(&printed) {
        let cells: Vec<&str> = row.iter().flat_map(|c| c.0.split_whitespace()).collect();
        assert_eq!(&cells, words);
    }
    let rows = summary_rows(&page, "unbalance response peak");
    assert_eq!(rows.len(), printed.len());
    for (row, words) in rows.iter().zip(&printed) {
        assert_eq!(row[4].0, *words.last().unwrap());
    }

    // Stability: Level I verdict as `rotor stability` prints it.
    let mut st = vec!["stability", pump_s, "--rpm", "3600"];
    st.extend(stage);
    let stability = rotor(&st);
    let level = stability
        .lines()
        .find(|l| l.starts_with("  Level I: "))
        .unwrap_or_else(|| panic!("{stability}"));
    let rows = summary_rows(&page, "stability margin (API 617 Level I)");
    assert_eq!(rows.len(), 1);
    let verdict = if level.contains("FAIL") {
        "FAIL"
    } else {
        "pass"
    };
    assert_eq!(rows[0][4].0, verdict);
    let qa = stability
        .lines()
        .find(|l| l.contains("anticipated cross-coupling"))
        .unwrap();
    assert!(
        qa.ends_with(&format!("= {}", rows[0][1].0.trim_start_matches("Q_A = "))),
        "{qa} vs {}",
        rows[0][1].0
    );

    // Modes: the table is `rotor modes`'s.
    let modes = rotor(&["modes", pump_s, "--rpm", "3600", "--modes", "8"]);
    let table = &page.sections["modes"].tables["modes"];
    for (row, line) in table.rows.iter().zip(modes.lines().skip(2)) {
        let w: Vec<&str> = line.split_whitespace().collect();
        // mode, ω_d, f_d, ζ, δ, whirl in the command; mode, f_d, ω_d, … here.
        assert_eq!(
            [
                &row[0].0, &row[2].0, &row[1].0, &row[3].0, &row[4].0, &row[5].0
            ],
            [w[0], w[1], w[2], w[3], w[4], w[5]]
        );
    }

    // Bearings: h_min and power loss are the operating point's.
    let op = rotor(&["operating-point", pump_s, "--rpm", "3600"]);
    for row in summary_rows(&page, "bearing film") {
        let block = op
            .split(&format!("bearing {} at 3600 rpm:", row[1].0))
            .nth(1)
            .unwrap();
        let h = block
            .split("minimum film thickness ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap();
        let p = block
            .split("power loss ")
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap();
        assert!(
            row[2]
                .0
                .contains(&format!("h_min = {h} µm, power loss {p} W")),
            "{}",
            row[2].0
        );
        assert_eq!(row[4].0, "pass");
    }
}

/// The built-in classic rotor at 3000 rpm stopped with "matrix is singular"
/// (its grid landed on an undamped critical); now the page is written, and
/// the undamped resonance is "unbounded", as `rotor unbalance` says.
#[test]
fn report_never_fails_on_the_undamped_classic_rotor() {
    let (_, page) = write_report(&["report", "--rpm", "3000"], "classic");
    assert_eq!(page.order, SECTIONS);
    for id in SECTIONS {
        assert!(page.sections[id].failures.is_empty(), "{id}");
    }
    assert_eq!(page.stamp["model file"], "built-in classic_disk_rotor.toml");
    let unbalance = rotor(&["unbalance", "--operating-rpm", "3000:3000"]);
    let table = &page.sections["unbalance"].tables["unbalance-peaks"];
    assert!(!table.rows.is_empty());
    for row in &table.rows {
        assert_eq!(row[2].0, "unbounded");
        assert_eq!(row[3].0, "∞");
    }
    let printed: Vec<&str> = unbalance
        .lines()
        .filter(|l| l.contains("unbounded"))
        .collect();
    assert_eq!(printed.len(), table.rows.len(), "{unbalance}");
    // No damping: the stability check fails, and says why.
    let rows = summary_rows(&page, "stability without cross-coupling");
    assert_eq!(rows[0][2].0, "log dec 0 (no damping)");
    assert_eq!(
        (rows[0][4].0.as_str(), rows[0][4].1.as_str()),
        ("FAIL", "fail")
    );
    // Critical speeds of an undamped rotor: AF unbounded, never 3.9e27.
    for row in summary_rows(&page, "critical speed (Campbell)") {
        assert!(row[2].0.ends_with("AF ∞"), "{}", row[2].0);
    }
}

/// `--operating-rpm` and the model's `operating_rpm` (issue 48): the damped
/// classic rotor at 600 rpm has its
/// critical speeds at 1113 rpm, 85 % above the operating speed (26 %
/// required: AF 23.8): every Campbell margin passes; with the operating range
/// 600–1200 rpm the critical lies inside it and every one fails, as `rotor
/// campbell --operating-rpm 600:1200` judges them, and the stamp names the
/// range.
#[test]
fn an_operating_range_judges_the_margins_of_the_report() {
    let model = root().join("models/classic_disk_rotor_damped.toml");
    let model = model.to_str().unwrap();
    let verdicts = |page: &Page| -> Vec<String> {
        summary_rows(page, "critical speed (Campbell)")
            .iter()
            .map(|r| r[4].0.clone())
            .collect()
    };
    let (_, alone) = write_report(&["report", model, "--rpm", "600"], "range_alone");
    let (_, range) = write_report(
        &[
            "report",
            model,
            "--rpm",
            "600",
            "--operating-rpm",
            "600:1200",
        ],
        "range_600_1200",
    );
    let (alone, inside) = (verdicts(&alone), verdicts(&range));
    assert!(
        !alone.is_empty() && alone.iter().all(|v| v == "pass"),
        "{alone:?}"
    );
    assert_eq!(inside.len(), alone.len());
    assert!(inside.iter().all(|v| v == "FAIL"), "{inside:?}");
    let printed = campbell_verdicts(&rotor(&["campbell", model, "--operating-rpm", "600:1200"]));
    assert!(
        printed.iter().all(|v| v == "FAIL") && !printed.is_empty(),
        "{printed:?}"
    );
    // The model's own `operating_rpm` is the range without the flag.
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("report");
    std::fs::create_dir_all(&dir).unwrap();
    let keyed = dir.join("classic_damped_operating.toml");
    let text = std::fs::read_to_string(model).unwrap();
    std::fs::write(&keyed, format!("operating_rpm = [600.0, 1200.0]\n{text}")).unwrap();
    let keyed = keyed.to_str().unwrap();
    assert_eq!(campbell_verdicts(&rotor(&["campbell", keyed])), printed);
    let (_, from_file) = write_report(&["report", keyed, "--rpm", "600"], "range_from_file");
    assert_eq!(verdicts(&from_file), inside);
    assert_eq!(
        range.stamp["operating range (separation margins)"],
        "600 to 1200 rpm"
    );
    // A malformed range is an error naming the flag.
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args([
            "report",
            model,
            "--operating-rpm",
            "1200:600",
            "--out",
            "/dev/null",
        ])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--operating-rpm"));
}

/// Every element of the model listed as what it is (issue 48): the unit on
/// brackets' seal as a seal, its generator's pull as a magnetic pull, its
/// pedestals, forces and guide bearings each once, by the model parser's own
/// lists; the stability section notes that the seal's table is synchronous.
#[test]
fn the_report_lists_every_element_as_what_it_is() {
    let path = root().join("models/hydro_unit_brackets.toml");
    let model = rotor_bearing::model::RotorModel::from_file(&path).unwrap();
    let (_, page) = write_report(&["report", path.to_str().unwrap()], "brackets_parts");
    let table = &page.sections["model"].tables["model-parts"];
    let (kind, name) = (table.column("kind"), table.column("name"));
    let listed = |k: &str| -> Vec<String> {
        table
            .rows
            .iter()
            .filter(|r| r[kind].0 == k)
            .map(|r| r[name].0.clone())
            .collect()
    };
    let of = |pick: &dyn Fn(&rotor_bearing::bearing::BearingKind) -> bool| -> Vec<String> {
        model
            .bearings
            .iter()
            .filter(|b| pick(&b.kind))
            .map(|b| b.name.clone())
            .collect()
    };
    assert_eq!(listed("seal"), of(&|k| k.is_seal()));
    assert_eq!(listed("seal"), ["runner_seal"]);
    assert_eq!(listed("magnetic pull"), of(&|k| k.is_magnetic_pull()));
    assert_eq!(listed("magnetic pull"), ["generator"]);
    assert_eq!(
        listed("bearing"),
        of(&|k| !k.is_seal() && !k.is_magnetic_pull() && !k.is_rub())
    );
    let names = |v: Vec<&String>| v.into_iter().cloned().collect::<Vec<_>>();
    assert_eq!(
        listed("pedestal"),
        names(model.pedestals.iter().map(|p| &p.name).collect())
    );
    assert_eq!(
        listed("force"),
        names(model.forces.iter().map(|f| &f.name).collect())
    );
    assert!(listed("force").len() >= 2);
    assert!(
        page.sections["stability"]
            .text
            .contains("the coefficients of runner_seal come from a table"),
        "{}",
        page.sections["stability"].text
    );
}

/// A malformed page is caught by the parser the tests use.
#[test]
fn a_broken_page_is_caught() {
    let html = "<!DOCTYPE html>\n<html><body><section id=\"a\"><p>x</section></body></html>";
    assert!(std::panic::catch_unwind(|| parse(html)).is_err());
}

/// The installed Chromium (Debian's `chromium`, from `scripts/setup.sh`).
fn chromium() -> &'static Path {
    let path = Path::new("/usr/bin/chromium");
    assert!(
        path.exists(),
        "/usr/bin/chromium is missing: scripts/setup.sh installs it (scripts/test.sh runs that)"
    );
    path
}

fn headless(extra: &[String], page: &Path) -> std::process::Output {
    let out = Command::new(chromium())
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--window-size=1280,4000",
            "--virtual-time-budget=20000",
        ])
        .args(extra)
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "chromium: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// The page in a real browser: after load every figure has decoded to its
/// PNG's own width and height, nothing overflows sideways at 1280 px, every
/// table of the file is in the browser's DOM, the screenshot is a PNG of the
/// window, and print to PDF gives a page per section at least.
#[test]
fn page_renders_in_headless_chromium() {
    let pump = root().join("examples/my_pump.toml");
    let (path, page) = write_report(&["report", pump.to_str().unwrap()], "chromium");
    let dom = headless(&["--dump-dom".into()], &path);
    let dom = String::from_utf8(dom.stdout).unwrap();
    let images: Vec<&Vec<u8>> = page.sections.values().flat_map(|s| &s.images).collect();
    let decoded: Vec<&str> = dom
        .split("data-decoded=\"")
        .skip(1)
        .map(|s| s.split('"').next().unwrap())
        .collect();
    assert_eq!(
        decoded.len(),
        images.len(),
        "every figure reported by the page script"
    );
    // Figures in document order: each decoded at its PNG's size.
    let order: Vec<(u32, u32)> = page
        .order
        .iter()
        .flat_map(|id| page.sections[id].images.iter().map(|p| png_size(p)))
        .collect();
    for (d, (w, h)) in decoded.iter().zip(order) {
        assert_eq!(*d, format!("{w}x{h}"), "a figure did not render");
    }
    let overflow: i64 = dom
        .split("data-overflow=\"")
        .nth(1)
        .expect("the page script ran")
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(overflow <= 0, "the page runs {overflow} px off the side");
    let tables_in_file: usize = page
        .sections
        .values()
        .map(|s| s.tables.len())
        .sum::<usize>()
        + 1;
    assert_eq!(dom.matches("<table").count(), tables_in_file);
    assert!(dom.contains("<td class=\"pass\">pass</td>"));

    let dir = path.parent().unwrap();
    let (shot, pdf) = (dir.join("shot.png"), dir.join("page.pdf"));
    let _ = std::fs::remove_file(&shot);
    let _ = std::fs::remove_file(&pdf);
    headless(&[format!("--screenshot={}", shot.display())], &path);
    let bytes = std::fs::read(&shot).unwrap();
    assert_eq!(png_size(&bytes), (1280, 4000));
    assert!(bytes.len() > 50_000, "screenshot of {} bytes", bytes.len());
    headless(
        &[
            format!("--print-to-pdf={}", pdf.display()),
            "--no-pdf-header-footer".into(),
        ],
        &path,
    );
    let pdf = std::fs::read(&pdf).unwrap();
    assert!(pdf.starts_with(b"%PDF-"));
    let text = String::from_utf8_lossy(&pdf);
    let pages = text.matches("/Type /Page").count() - text.matches("/Type /Pages").count();
    assert!(pages >= SECTIONS.len(), "{pages} pages");
}
