//! The command line as a terminal and a pipe meet it: every command's output
//! ends with a newline and stays a screenful (tables go to files), a closed
//! pipe (`… --png X | head`) never loses a file, help says what a command
//! does, and `info` says where every node is.

use std::path::PathBuf;
use std::process::Command;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("hygiene");
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_command_ends_its_output_with_a_newline_and_stays_short() {
    let pump = root().join("examples/my_pump.toml");
    let pump = pump.to_str().unwrap();
    let png = dir().join("draw.png");
    let png = png.to_str().unwrap();
    let commands: Vec<Vec<&str>> = vec![
        vec!["info", pump],
        vec!["draw", pump, "--png", png],
        vec!["static", pump, "--rpm", "3600"],
        vec!["static"],
        vec!["modes", pump, "--rpm", "3600"],
        vec!["campbell", pump],
        vec!["coefficients", pump],
        vec!["simulate", pump, "--rpm", "3600", "--duration", "0.5"],
        vec!["unbalance", pump],
        vec!["operating-point", pump, "--rpm", "3600"],
        vec!["ucs", pump],
        vec!["stability", pump, "--rpm", "3600"],
    ];
    for args in commands {
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(&args)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stdout = String::from_utf8(out.stdout).unwrap();
        assert!(
            stdout.is_empty() || stdout.ends_with('\n'),
            "{args:?}: no trailing newline: {:?}",
            &stdout[stdout.len().saturating_sub(40)..]
        );
        // A table of a 20 000-step run or of every node goes to a file.
        assert!(
            stdout.lines().count() < 100,
            "{args:?}: {} lines",
            stdout.lines().count()
        );
        assert!(
            !stdout.contains("speed_rpm,") && !stdout.contains("time_s,"),
            "{args:?}"
        );
    }
}

/// `rotor X --png FILE | head -1`: the pipe closes after the first line, and
/// the figure is written all the same (the table used to come first, and the
/// closed pipe ended the process before the PNG).
#[test]
fn a_closed_pipe_never_loses_a_file() {
    let pump = root().join("examples/my_pump.toml");
    for (command, option, extra) in [
        ("coefficients", "--png", ""),
        ("campbell", "--png", ""),
        ("unbalance", "--png", ""),
        ("modes", "--shapes-png", "--rpm 3600"),
        ("ucs", "--png", ""),
        ("stability", "--png", "--rpm 3600"),
    ] {
        let png = dir().join(format!("{command}_pipe.png"));
        let _ = std::fs::remove_file(&png);
        let script = format!(
            "{} {command} {} {extra} {option} {} | head -1 > /dev/null",
            env!("CARGO_BIN_EXE_rotor"),
            pump.display(),
            png.display()
        );
        let status = Command::new("bash").args(["-c", &script]).status().unwrap();
        assert!(status.success(), "{script}");
        let bytes = std::fs::read(&png).unwrap_or_else(|e| panic!("{command}: {e}"));
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "{command}");
    }
}

#[test]
fn help_and_info_say_what_they_should() {
    let help = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["static", "--help"])
        .output()
        .unwrap();
    let help = String::from_utf8(help.stdout).unwrap();
    assert!(!help.contains("(linear bearings)"), "{help}");
    assert!(
        help.contains("fluid films in their static equilibrium"),
        "{help}"
    );
    let info = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("info")
        .arg(root().join("examples/my_pump.toml"))
        .output()
        .unwrap();
    let info = String::from_utf8(info.stdout).unwrap();
    // 10 elements over 1 m: nodes every 0.1 m, eight to a line.
    assert!(
        info.contains("  node z (m): 1: 0, 2: 0.1, 3: 0.2, 4: 0.3, 5: 0.4, 6: 0.5, 7: 0.6, 8: 0.7\n              9: 0.8, 10: 0.9, 11: 1\n"),
        "{info}"
    );
}
