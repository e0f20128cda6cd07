//! `rotor campbell` and `rotor modes` as a design review reads them: the
//! critical speeds' API 684 separation margins from the operating speed and
//! their distance from the maximum speed, each number against a hand
//! calculation from the printed critical speed and damping ratio; round-off
//! printed as 0.

use std::path::PathBuf;
use std::process::Command;

fn rotor() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rotor"))
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> String {
    let out = rotor().args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// API 684 §2.6.2.10 required margin (%) for AF, below or above the range.
fn required(af: f64, below: bool) -> Option<f64> {
    if af < 2.5 {
        return None;
    }
    let s = 17.0 * (1.0 - 1.0 / (af - 1.5));
    Some(if below {
        s.min(16.0)
    } else {
        (10.0 + s).min(26.0)
    })
}

#[test]
fn campbell_margins_follow_from_the_printed_critical_speeds() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("analyst_campbell");
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("pump.png");
    let _ = std::fs::remove_file(&png);
    let pump = root().join("examples/my_pump.toml");
    let stdout = run(&[
        "campbell",
        pump.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    // Without --csv no table of the diagram reaches the terminal.
    assert!(!stdout.contains("speed_rpm,"), "{stdout}");
    assert!(stdout.ends_with('\n'));
    let criticals: Vec<(f64, f64)> = stdout
        .split("overdamped crossings")
        .next()
        .unwrap()
        .lines()
        .filter(|l| l.contains(" rpm (") && l.contains("ζ = "))
        .map(|l| {
            let rpm = l.split_whitespace().next().unwrap().parse().unwrap();
            let zeta = l.rsplit("ζ = ").next().unwrap().parse().unwrap();
            (rpm, zeta)
        })
        .collect();
    assert_eq!(criticals.len(), 2, "{stdout}");
    let (_, table) = stdout
        .split_once("from the operating speed 3600 rpm, maximum speed 4000 rpm:\n")
        .expect(&stdout);
    let rows: Vec<Vec<&str>> = table
        .lines()
        .skip(1)
        .take(criticals.len())
        .map(|l| l.split_whitespace().collect())
        .collect();
    for ((rpm, zeta), row) in criticals.iter().zip(&rows) {
        // Columns: speed, AF, required %, actual %, from max %, result.
        assert_eq!(row[0].parse::<f64>().unwrap(), *rpm, "{row:?}");
        let af = 1.0 / (2.0 * zeta);
        // ζ is printed to 4 digits: AF to 2 decimals within that rounding.
        assert!(
            (row[1].parse::<f64>().unwrap() - af).abs() < 2e-3 * af,
            "{row:?}"
        );
        let below = *rpm < 3600.0;
        let req = required(af, below).unwrap();
        assert!(
            (row[2].parse::<f64>().unwrap() - req).abs() <= 0.051,
            "{row:?} {req}"
        );
        let actual = 100.0 * (3600.0 - rpm) / rpm;
        assert_eq!(row[4], format!("{actual:.1}"), "{row:?}");
        let from_max = 100.0 * (rpm - 4000.0) / 4000.0;
        assert_eq!(row[6], format!("{from_max:+.1}"), "{row:?}");
        assert_eq!(row[8], if actual >= req { "pass" } else { "FAIL" });
    }
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
}

/// An operating range given on the command line: margins from its nearer end.
#[test]
fn campbell_margins_from_an_operating_range() {
    let pump = root().join("examples/my_pump.toml");
    let stdout = run(&[
        "campbell",
        pump.to_str().unwrap(),
        "--operating-rpm",
        "3300:3700",
    ]);
    let (_, table) = stdout
        .split_once("from the operating range 3300 … 3700 rpm, maximum speed 4000 rpm:\n")
        .expect(&stdout);
    let first: Vec<&str> = table.lines().nth(1).unwrap().split_whitespace().collect();
    let rpm: f64 = first[0].parse().unwrap();
    assert_eq!(first[4], format!("{:.1}", 100.0 * (3300.0 - rpm) / rpm));
}

/// The classic rotor has no damping: its modes' damping ratios and log
/// decrements are round-off (1e-24 … 1e-13) and print as 0, never as
/// `2.8e-24` or `-0.0000`.
#[test]
fn undamped_modes_print_zero_damping() {
    for rpm in ["0", "4000"] {
        let stdout = run(&["modes", "--rpm", rpm, "--modes", "6"]);
        let rows: Vec<Vec<&str>> = stdout
            .lines()
            .skip(2)
            .map(|l| l.split_whitespace().collect())
            .collect();
        assert_eq!(rows.len(), 6, "{stdout}");
        for r in rows {
            assert_eq!((r[3], r[4]), ("0", "0"), "{stdout}");
        }
        assert!(!stdout.contains("e-"), "{stdout}");
    }
    // A damped rotor keeps its numbers.
    let damped = root().join("models/classic_disk_rotor_damped.toml");
    let stdout = run(&["modes", damped.to_str().unwrap(), "--rpm", "1000"]);
    let first: Vec<&str> = stdout.lines().nth(2).unwrap().split_whitespace().collect();
    assert!(first[3].parse::<f64>().unwrap() > 1e-4, "{stdout}");
}
