//! The README's quick start ("Your machine in 10 minutes"), run exactly as
//! written: its model block is the shipped `examples/my_pump.toml`, its
//! shell block runs unchanged from the repository root, and every number the
//! README quotes from the output is the one the commands print.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The README's quick-start section (up to the next `## ` heading).
fn section(readme: &str) -> &str {
    let start = readme
        .find("## Your machine in 10 minutes")
        .expect("README: no quick-start section");
    let rest = &readme[start..];
    let end = rest[3..].find("\n## ").map_or(rest.len(), |e| e + 3);
    &rest[..end]
}

/// The body of the first fenced block of `lang` in `text`.
fn fenced<'a>(text: &'a str, lang: &str) -> &'a str {
    let open = format!("```{lang}\n");
    let start = text
        .find(&open)
        .unwrap_or_else(|| panic!("no ```{lang} block"))
        + open.len();
    let end = text[start..].find("```\n").expect("unclosed block");
    &text[start..start + end]
}

/// The model block is the shipped example, byte for byte, so the commands run
/// on exactly what the reader sees.
#[test]
fn readme_model_block_is_the_shipped_example() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let example = std::fs::read_to_string(root().join("examples/my_pump.toml")).unwrap();
    assert_eq!(fenced(section(&readme), "toml"), example);
}

fn csv_rows(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(|s| s.trim_matches('"').to_string())
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.trim().parse::<f64>().unwrap())
                .collect()
        })
        .collect();
    (header, rows)
}

/// The first line of `out` that contains every one of `words`.
fn line_with<'a>(out: &'a str, words: &[&str]) -> &'a str {
    out.lines()
        .find(|l| words.iter().all(|w| l.contains(w)))
        .unwrap_or_else(|| panic!("no line with {words:?} in:\n{out}"))
}

fn number_after(line: &str, key: &str) -> f64 {
    let at = line.find(key).unwrap_or_else(|| panic!("{key} in {line}")) + key.len();
    line[at..]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|e| panic!("{key} in {line}: {e}"))
}

#[test]
fn readme_quick_start_runs_as_written() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let section = section(&readme);
    let script = fenced(section, "sh");
    for generated in [
        "out/my_pump_campbell.png",
        "out/my_pump_unbalance.png",
        "out/my_pump_run_up.csv",
        "out/my_pump_report.html",
        "out/my_pump.fmu",
        "out/my_pump_fmu.csv",
    ] {
        let _ = std::fs::remove_file(root().join(generated));
    }
    let out = Command::new("bash")
        .args(["-euo", "pipefail", "-c", script])
        .current_dir(root())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "the quick start failed:\n{stdout}\n{stderr}"
    );
    // The model needs no plausibility warning.
    // No warning but the short film's validity (issue 47: these bearings
    // are longer than the short film's range, and it says so).
    assert!(
        !stderr
            .lines()
            .any(|l| l.contains("warning") && !l.contains("short film at")),
        "{stderr}"
    );

    // info
    assert!(stdout.contains("11 nodes, 10 shaft elements"), "{stdout}");
    assert!(
        line_with(&stdout, &["bearing drive_end at node 1"]).contains("radial clearance C = 60 µm"),
        "{stdout}"
    );

    // campbell: the first critical speed as the README quotes it.
    let critical = line_with(&stdout, &["rpm (", "forward whirl", "ζ = "]);
    let rpm: f64 = critical.split_whitespace().next().unwrap().parse().unwrap();
    let zeta = number_after(critical, "ζ = ");
    assert_eq!(format!("{rpm:.0}"), "2803", "{critical}");
    assert_eq!(format!("{zeta:.3}"), "0.065", "{critical}");
    assert!(section.contains("crosses the 1× line at 2803 rpm\n  (forward whirl, ζ = 0.065)"));
    for png in [
        "out/my_pump_campbell.png",
        "out/my_pump_unbalance.png",
        "out/my_pump_run_up_orbits.png",
        "out/my_pump_run_up_spectrum.png",
        "out/my_pump_run_up_waterfall.png",
    ] {
        let bytes = std::fs::read(root().join(png)).unwrap_or_else(|e| panic!("{png}: {e}"));
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{png}");
    }

    // unbalance: the probe's peak, AF, required and actual margins, verdict.
    let probe = line_with(&stdout, &["probe impeller", "%"]);
    let fields: Vec<&str> = probe.split_whitespace().collect();
    assert_eq!(fields[2].parse::<f64>().unwrap().round(), 2871.0, "{probe}");
    assert_eq!(format!("{:.1}", fields[4].parse::<f64>().unwrap()), "14.2");
    assert_eq!(fields[5], "15.7", "{probe}");
    assert_eq!(fields[7], "25.4", "{probe}");
    assert_eq!(fields[9], "pass", "{probe}");
    assert!(section.contains("the probe peaks at 2871 rpm (AF 14.2), 25.4 % below 3600 rpm where\n  15.7 % is required: pass."));

    // simulate: a run-up from 0 to 3600 rpm over 3 s.
    let (header, rows) = csv_rows(&root().join("out/my_pump_run_up.csv"));
    let speed = header.iter().position(|h| h == "speed_rpm").unwrap();
    let time = header.iter().position(|h| h == "time_s").unwrap();
    let last = rows.last().unwrap();
    assert!((last[time] - 3.0).abs() < 1e-9 && (last[speed] - 3600.0).abs() < 1e-6);
    assert!(rows[0][speed].abs() < 1e-9);

    // The report: the stamp names the file and its hash; the summary is there.
    let page = std::fs::read_to_string(root().join("out/my_pump_report.html")).unwrap();
    assert!(page.contains("<td>model file</td><td>examples/my_pump.toml</td>"));
    assert!(page.contains("<td>model SHA-256</td>"));
    assert!(page.contains("<table id=\"summary-table\">"));
    assert!(page.contains("<td class=\"pass\">pass</td>"));

    // The FMU, simulated by FMPy for 1 s at 376.99 rad/s (3600 rpm).
    let (header, rows) = csv_rows(&root().join("out/my_pump_fmu.csv"));
    assert!(
        header.iter().any(|h| h == "probes.impeller.x"),
        "{header:?}"
    );
    let last = rows.last().unwrap();
    assert!((last[0] - 1.0).abs() < 1e-9, "{last:?}");
    assert!(rows.iter().flatten().all(|v| v.is_finite()));
    let x = header
        .iter()
        .position(|h| h == "probes.impeller.x")
        .unwrap();
    let y = header
        .iter()
        .position(|h| h == "probes.impeller.y")
        .unwrap();
    // A journal orbit inside the clearance: the probe moves, and by less
    // than a millimetre.
    let radius = rows.iter().map(|r| r[x].hypot(r[y])).fold(0.0, f64::max);
    assert!(radius > 1e-7 && radius < 1e-3, "{radius}");
}
