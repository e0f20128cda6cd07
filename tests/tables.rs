//! Coefficient tables (table bearings and seals): PCHIP interpolation against
//! SciPy, inline and CSV tables alike, the clamping warning, errors naming
//! file, line and column, and a seal's cross-coupling in the stability
//! threshold and in a transient.

use std::process::Command;

use rotor_bearing::analysis::linear::unbalance_response;
use rotor_bearing::analysis::linearize::linearized;
use rotor_bearing::analysis::modal::{ModalOptions, modes};
use rotor_bearing::analysis::stability::{mid_span_node, stability};
use rotor_bearing::model::RotorModel;
use rotor_bearing::rotor::Rotor;
use rotor_bearing::solver::{Simulator, SolverOptions};

const RPM: f64 = std::f64::consts::PI / 30.0;

fn classic_damped() -> String {
    std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/models/classic_disk_rotor_damped.toml"
    ))
    .unwrap()
}

/// The damped classic rotor with its non-drive-end bearing replaced by a
/// table bearing (`table` holds its keys after `type = "table"`).
fn with_table_bearing(table: &str) -> String {
    let text = classic_damped();
    let start = text.find("[[bearings]]\nname = \"non_drive_end\"").unwrap();
    let end = start + text[start..].find("[[unbalance]]").unwrap();
    format!(
        "{}[[bearings]]\nname = \"non_drive_end\"\nnode = 7\ntype = \"table\"\n{table}\n{}",
        &text[..start],
        &text[end..]
    )
}

const SPEEDS: &str = "speeds_rpm = [500, 1000, 2000, 3000, 4000]";
const KXX: &str = "kxx = [1.0e6, 1.3e6, 2.1e6, 2.6e6, 2.8e6]";
const KXY: &str = "kxy = [1e5, 2.5e5, 6e5, 9e5, 1.1e6]";
const KYY: &str = "kyy = 1.5e6";
const CXX: &str = "cxx = [3000.0, 2600, 2100, 1900, 1850]";
const CYY: &str = "cyy = 2000.0";

fn inline_table() -> String {
    [SPEEDS, KXX, KXY, KYY, CXX, CYY].join("\n")
}

/// The same bearing as a linear one with the given coefficients.
fn with_linear_bearing(kxx: f64, kxy: f64, cxx: f64) -> String {
    with_table_bearing(&format!(
        "kxx = {kxx:e}\nkxy = {kxy:e}\nkyy = 1.5e6\ncxx = {cxx:e}\ncyy = 2000.0"
    ))
    .replace("type = \"table\"", "type = \"linear\"")
}

fn rotor(text: &str) -> Rotor {
    Rotor::new(RotorModel::from_toml(text, "tables.toml").unwrap()).unwrap()
}

/// Modes and unbalance response of the linearized rotor at `rpm`.
fn linear_results(
    rotor: &Rotor,
    rpm: f64,
) -> (Vec<nalgebra::Complex<f64>>, Vec<nalgebra::Complex<f64>>) {
    let speed = rpm * RPM;
    let linear = linearized(rotor, speed, speed).unwrap();
    let found = modes(
        &linear,
        speed,
        &ModalOptions {
            modes: 6,
            target_frequency: 0.0,
        },
    )
    .unwrap();
    (
        found.iter().map(|m| m.eigenvalue).collect(),
        unbalance_response(&linear, speed).unwrap(),
    )
}

fn assert_close(a: &[nalgebra::Complex<f64>], b: &[nalgebra::Complex<f64>], tol: f64, what: &str) {
    let scale = a.iter().map(|v| v.norm()).fold(0.0, f64::max);
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).norm() <= tol * scale, "{what}: {x} against {y}");
    }
}

/// Between its rows the table bearing is the linear bearing with the
/// coefficients SciPy's `PchipInterpolator` gives at that speed (computed
/// with `scipy.interpolate.PchipInterpolator(speeds, column)(rpm)`, SciPy
/// 1.16): modes and unbalance response agree to 1e-10; at a row speed it is
/// the row itself.
#[test]
fn a_table_bearing_is_the_linear_bearing_interpolated_at_the_speed() {
    let table = rotor(&with_table_bearing(&inline_table()));
    let scipy = [
        (
            750.0,
            1141145.8333333333,
            172687.14689265538,
            2783.2236842105262,
        ),
        (
            1500.0,
            1707451.9230769232,
            424657.7574967405,
            2306.7669172932333,
        ),
        (3500.0, 2729464.285714286, 1011250.0, 1865.0),
        (2000.0, 2.1e6, 6e5, 2100.0),
    ];
    for (rpm, kxx, kxy, cxx) in scipy {
        let linear = rotor(&with_linear_bearing(kxx, kxy, cxx));
        let (tm, tr) = linear_results(&table, rpm);
        let (lm, lr) = linear_results(&linear, rpm);
        assert_close(&tm, &lm, 1e-10, &format!("modes at {rpm} rpm"));
        assert_close(&tr, &lr, 1e-10, &format!("unbalance response at {rpm} rpm"));
    }
}

/// A CSV table beside the model gives exactly the inline table's results;
/// comment lines, blank lines and any column order are accepted.
#[test]
fn a_csv_table_equals_the_inline_table() {
    let dir = std::env::temp_dir().join(format!("rotor_tables_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("vendor.csv"),
        "# vendor bearing code, 2026-11\n\
         cxx,speed_rpm,kxx,kxy,kyy,cyy\n\
         3000,500,1.0e6,1e5,1.5e6,2000\n\
         2600,1000,1.3e6,2.5e5,1.5e6,2000\n\
         \n\
         2100,2000,2.1e6,6e5,1.5e6,2000\n\
         1900,3000,2.6e6,9e5,1.5e6,2000\n\
         1850,4000,2.8e6,1.1e6,1.5e6,2000\n",
    )
    .unwrap();
    let path = dir.join("machine.toml");
    std::fs::write(&path, with_table_bearing("table = \"vendor.csv\"")).unwrap();
    let from_csv = Rotor::new(RotorModel::from_file(&path).unwrap()).unwrap();
    assert_eq!(from_csv.model.table_files().len(), 1);
    let inline = rotor(&with_table_bearing(&inline_table()));
    for rpm in [750.0, 2500.0] {
        let (a, b) = (linear_results(&from_csv, rpm), linear_results(&inline, rpm));
        assert_eq!(a, b, "at {rpm} rpm");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Every malformed table is refused with the file, the line and the field
/// (column) named: unsorted and repeated speeds, non-finite values, columns
/// of the wrong length, an unknown column, a missing speed column, a column
/// without speeds, both a file and inline values, a missing file.
#[test]
fn malformed_tables_are_refused_naming_file_line_and_column() {
    let inline_cases = [
        (
            "speeds_rpm = [500, 400]\nkxx = [1e6, 2e6]",
            "tables.toml:",
            "speeds_rpm[1] = 400: speeds must increase",
        ),
        (
            "speeds_rpm = [500, 500]\nkxx = [1e6, 2e6]",
            "tables.toml:",
            "speeds_rpm[1] = 500: speeds must increase",
        ),
        (
            "speeds_rpm = [500, 600]\nkxx = [1e6, 2e6, 3e6]",
            "tables.toml:",
            "kxx = [1000000.0, 2000000.0, 3000000.0]: has 3 values for 2 speeds",
        ),
        (
            "kxx = [1e6, 2e6]",
            "tables.toml:",
            "kxx = [1000000.0, 2000000.0]: a column of values needs speeds_rpm",
        ),
        (
            "speeds_rpm = [500, 600]\nkxx = [1e6, nan]",
            "tables.toml:",
            "kxx[1] = NaN: must be a finite number",
        ),
        (
            "table = \"x.csv\"\nkxx = 1e6",
            "tables.toml:",
            "table = \"x.csv\": give either a table file",
        ),
    ];
    for (keys, file, want) in inline_cases {
        let err = RotorModel::from_toml(&with_table_bearing(keys), "tables.toml")
            .unwrap_err()
            .to_string();
        assert!(err.starts_with(file), "{keys}: {err}");
        assert!(err.contains(want), "{keys}: {err}");
        // The line of the offending key is named.
        let line: usize = err[file.len()..]
            .split(':')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(line > 40, "{keys}: {err}");
    }
    let dir = std::env::temp_dir().join(format!("rotor_bad_tables_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv_cases = [
        (
            "speed_rpm,kxx\n500,1e6\n400,2e6\n",
            ":3: speed_rpm = 400: speeds must increase",
        ),
        (
            "speed_rpm,kxx\n500,1e6\n500,2e6\n",
            ":3: speed_rpm = 500: speeds must increase",
        ),
        (
            "speed_rpm,kxx\n500,1e6\n600,inf\n",
            ":3: kxx = inf: must be a finite number",
        ),
        (
            "speed_rpm,kxx\n500,1e6\n600\n",
            ":3: (row) = 600: has 1 values for 2 columns",
        ),
        ("speed_rpm,kzz\n500,1e6\n", ":1: kzz = kzz: unknown column"),
        (
            "kxx,kyy\n1e6,1e6\n",
            ":1: speed_rpm = kxx,kyy: the header has no speed_rpm column",
        ),
        (
            "speed_rpm,kxx,kxx\n500,1,2\n",
            ":1: kxx = kxx: column given twice",
        ),
        (
            "speed_rpm,kxx\n",
            ":1: (rows) = : the table has a header but no rows",
        ),
    ];
    for (k, (csv, want)) in csv_cases.iter().enumerate() {
        let name = format!("bad{k}.csv");
        std::fs::write(dir.join(&name), csv).unwrap();
        let path = dir.join("m.toml");
        std::fs::write(&path, with_table_bearing(&format!("table = \"{name}\""))).unwrap();
        let err = RotorModel::from_file(&path).unwrap_err().to_string();
        let file = dir.join(&name).display().to_string();
        assert!(err.starts_with(&file), "{csv:?}: {err}");
        assert!(err[file.len()..].starts_with(want), "{csv:?}: {err}");
    }
    std::fs::write(
        dir.join("m.toml"),
        with_table_bearing("table = \"missing.csv\""),
    )
    .unwrap();
    let err = RotorModel::from_file(&dir.join("m.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("missing.csv: cannot read the model file"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The damped classic rotor with a seal at its disk (mid-span) node whose
/// only coefficients are the cross-coupled `kxy = q`, `kyx = −q` (N/m).
fn with_seal(q: f64) -> String {
    format!(
        "{}\n[[seals]]\nname = \"impeller_eye\"\nnode = 4\nkxy = {q:e}\nkyx = {:e}\n",
        classic_damped(),
        -q
    )
}

/// The threshold cross-coupling of `rotor stability` falls by exactly the
/// seal's cross-coupled stiffness (1e-6), and a transient with the seal 20 %
/// above the seal-free threshold whirls (its free vibration grows) while one
/// 20 % below decays.
#[test]
fn a_seal_cross_coupling_moves_the_stability_threshold_by_itself() {
    let speed = 3000.0 * RPM;
    let threshold = |text: &str| {
        let r = rotor(text);
        assert_eq!(mid_span_node(&r), 3);
        stability(&r, speed, 2e5, 21, 6).unwrap().threshold.unwrap()
    };
    let q0 = threshold(&classic_damped());
    let q_seal = 0.4 * q0;
    let q1 = threshold(&with_seal(q_seal));
    assert!(
        ((q0 - q1) / q_seal - 1.0).abs() < 1e-6,
        "thresholds {q0} and {q1} N/m differ by {} N/m, the seal has {q_seal} N/m",
        q0 - q1
    );
    // Free vibration from a kick at the disk, without unbalance or gravity.
    let growth = |q: f64| {
        let r = rotor(&with_seal(q));
        let disk = r.dofs.free(3, 0).unwrap();
        let mut sim = Simulator::new(
            r,
            SolverOptions {
                time_step: 2e-4,
                gravity: false,
                ..SolverOptions::default()
            },
        )
        .unwrap();
        sim.set_speed(speed, 0.0).unwrap();
        sim.set_unbalance(0, 0.0).unwrap();
        let mut state = sim.state().clone();
        state.ud[disk] = 1e-3;
        sim.set_state(state).unwrap();
        sim.consistent_acceleration().unwrap();
        let peak = |sim: &mut Simulator, from: f64, to: f64| {
            let mut p: f64 = 0.0;
            for k in 0..=200 {
                sim.advance_to(from + (to - from) * k as f64 / 200.0)
                    .unwrap();
                let o = sim.outputs().unwrap();
                p = p.max(o.probes[0].x.hypot(o.probes[0].y));
            }
            p
        };
        // Past the faster-decaying modes the least stable one is left.
        peak(&mut sim, 0.0, 2.0);
        let early = peak(&mut sim, 2.0, 3.0);
        let late = peak(&mut sim, 5.0, 6.0);
        late / early
    };
    let (above, below) = (growth(1.2 * q0), growth(0.8 * q0));
    assert!(
        above > 1.0,
        "20 % above the threshold the whirl decays: {above}"
    );
    assert!(
        below < 1.0,
        "20 % below the threshold the whirl grows: {below}"
    );
}

/// `rotor modes` at a speed outside a table's rows warns once, naming the
/// speed and the table's range; inside it does not warn.
#[test]
fn a_speed_outside_the_table_warns_once() {
    let dir = std::env::temp_dir().join(format!("rotor_table_warn_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("m.toml");
    std::fs::write(&path, with_table_bearing(&inline_table())).unwrap();
    let run = |args: &[&str]| {
        let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
            .args(args)
            .arg(&path)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let outside = run(&["modes", "--rpm", "6000"]);
    let lines: Vec<&str> = outside
        .lines()
        .filter(|l| l.starts_with("warning:"))
        .collect();
    assert_eq!(lines.len(), 1, "{outside}");
    assert!(
        lines[0].ends_with("bearing non_drive_end = 6000: speed 6000 rpm is outside its coefficient table (500 to 4000 rpm): the coefficients are held at the table's last values"),
        "{}",
        lines[0]
    );
    let inside = run(&["modes", "--rpm", "2500"]);
    assert!(!inside.contains("warning:"), "{inside}");
    // A run-up through the end of the table warns once in the transient.
    let ramp = run(&[
        "simulate",
        "--ramp-rpm",
        "3000:5000",
        "--duration",
        "0.2",
        "--csv",
        dir.join("o.csv").to_str().unwrap(),
    ]);
    let lines: Vec<&str> = ramp
        .lines()
        .filter(|l| l.contains("outside its coefficient table"))
        .collect();
    assert_eq!(lines.len(), 1, "{ramp}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A rigid rotor (one stiff element, end rotations held) on two linear
/// bearings `k_b = 1e7` N/m, with a seal of direct stiffness `s` at each end:
/// its translations have the net stiffness `k_b + s` in the bounce mode.
fn rigid_rotor_with_seals(s: f64) -> String {
    format!(
        r#"
name = "seal_divergence"
speed_rpm = 3000
[[materials]]
name = "steel"
youngs_modulus = 211e9
poisson_ratio = 0.3
density = 7810.0
[[shaft]]
length = 0.2
outer_diameter = 0.1
material = "steel"
elements = 1
[[bearings]]
name = "left"
type = "linear"
node = 1
kxx = 1e7
kyy = 1e7
[[bearings]]
name = "right"
type = "linear"
node = 2
kxx = 1e7
kyy = 1e7
[[seals]]
name = "left_seal"
node = 1
kxx = {s:e}
kyy = {s:e}
[[seals]]
name = "right_seal"
node = 2
kxx = {s:e}
kyy = {s:e}
[[supports]]
node = 1
fix = ["rx", "ry"]
[[supports]]
node = 2
fix = ["rx", "ry"]
"#
    )
}

/// Seals of negative stiffness stronger than the bearings make the machine
/// statically unstable: the static solve (and every command and the FMU that
/// start from it) stops with an error naming the seals and the net stiffness
/// `k_b + s` (−5e6 N/m here), instead of returning an equilibrium it cannot
/// hold; weaker seals (net 5e6 N/m) are accepted.
#[test]
fn negative_seal_stiffness_beyond_the_bearings_is_a_static_instability() {
    use rotor_bearing::solver::{SolverOptions, equilibrium};
    let speed = 3000.0 * RPM;
    let unstable = rotor(&rigid_rotor_with_seals(-1.5e7));
    let err = equilibrium(&unstable, speed, &SolverOptions::default(), None)
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("statically unstable: the net stiffness is -5000000 N/m")
            && err.contains("left_seal (-15000000 N/m), right_seal (-15000000 N/m)"),
        "{err}"
    );
    let mut sim = Simulator::new(unstable, SolverOptions::default()).unwrap();
    sim.set_speed(speed, 0.0).unwrap();
    assert!(sim.settle_static().is_err());
    let stable = rotor(&rigid_rotor_with_seals(-0.5e7));
    equilibrium(&stable, speed, &SolverOptions::default(), None).unwrap();
    // The CLI says so and fails.
    let dir = std::env::temp_dir().join(format!("rotor_divergence_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("m.toml");
    std::fs::write(&path, rigid_rotor_with_seals(-1.5e7)).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["static", "--rpm", "3000"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("statically unstable"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

/// The Campbell diagram takes a seal's cross-coupling at every speed: its log
/// decrements are those of the seal-free rotor with the same cross-coupled
/// stiffness added at the seal's node (1e-9), and they fall below the
/// seal-free rotor's.
#[test]
fn campbell_log_decrements_include_the_seal() {
    use rotor_bearing::analysis::campbell::campbell;
    use rotor_bearing::analysis::stability::with_cross_coupling;
    let q = 3e4;
    let sealed = rotor(&with_seal(q));
    let plain = rotor(&classic_damped());
    let options = ModalOptions {
        modes: 6,
        target_frequency: 0.0,
    };
    let speeds = [1000.0 * RPM, 2500.0 * RPM, 4000.0 * RPM];
    let diagram = campbell(&sealed, &speeds, &options).unwrap();
    let free = campbell(&plain, &speeds, &options).unwrap();
    for ((point, free), &speed) in diagram.iter().zip(&free).zip(&speeds) {
        let coupled =
            with_cross_coupling(&linearized(&plain, speed, speed).unwrap(), &[3], q).unwrap();
        let want = modes(&coupled, speed, &options).unwrap();
        for (m, w) in point.modes.iter().zip(&want) {
            assert!(
                (m.log_decrement - w.log_decrement).abs() < 1e-9 * w.log_decrement.abs().max(1.0),
                "{m:?} against {w:?}"
            );
        }
        let least = |ms: &[rotor_bearing::analysis::campbell::ModeSummary]| {
            ms.iter()
                .map(|m| m.log_decrement)
                .fold(f64::INFINITY, f64::min)
        };
        assert!(
            least(&point.modes) < least(&free.modes),
            "the seal destabilizes"
        );
    }
}

/// Issue 48: seven seal tables that end at trip speed, and a bearing table
/// that starts above the diagram's lowest speed, each warn once in a
/// Campbell run (which sweeps to 1.25 × the trip speed), naming the range of
/// the diagram's speeds beyond the table on each side (the value the
/// farthest), not one speed; the library's warning names exactly the speeds
/// it was given outside the rows.
#[test]
fn a_campbell_run_beyond_seal_tables_warns_once_per_element_with_the_range() {
    let seals: String = (1..=7)
        .map(|k| {
            format!(
                "[[seals]]\nname = \"stage{k}\"\nnode = {}\nspeeds_rpm = [0, 2000, 4000]\nkxy = [0.0, 1e3, 4e3]\nkyx = [0.0, -1e3, -4e3]\n\n",
                1 + k % 6
            )
        })
        .collect();
    let text = with_table_bearing(&inline_table())
        .replace("speed_rpm = 1000", "max_speed_rpm = 4000\nspeed_rpm = 1000")
        .replace("[[unbalance]]", &format!("{seals}[[unbalance]]"));
    let model = RotorModel::from_toml(&text, "stages.toml").unwrap();
    // The library: the speeds outside, by side, with the table's range.
    let w: Vec<f64> = [100.0, 300.0, 2500.0, 4500.0, 5000.0]
        .iter()
        .map(|r| r * RPM)
        .collect();
    let warnings = model.table_speed_warnings(&w);
    assert_eq!(warnings.len(), 8, "{warnings:?}");
    assert_eq!(
        warnings[0].to_string(),
        "stages.toml: bearing non_drive_end = 5000: speeds 100 to 300 rpm and 4500 to 5000 rpm are outside its coefficient table (500 to 4000 rpm): the coefficients are held at the table's first and last values there"
    );
    for w in &warnings[1..] {
        assert!(
            w.to_string().ends_with(
                "= 5000: speeds 4500 to 5000 rpm are above its coefficient table (0 to 4000 rpm): the coefficients are held at the table's last values there"
            ),
            "{w}"
        );
    }
    // The command: one warning per table, its range the diagram's speeds.
    let dir = std::env::temp_dir().join(format!("rotor_stage_tables_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("stages.toml");
    std::fs::write(&path, &text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .args(["campbell", "--steps", "8", "--modes", "4"])
        .arg(&path)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let lines: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("coefficient table"))
        .collect();
    assert_eq!(lines.len(), 8, "{stderr}");
    for k in 1..=7 {
        let line = lines
            .iter()
            .find(|l| l.contains(&format!("seal stage{k} = 5000:")))
            .unwrap_or_else(|| panic!("stage{k} in {stderr}"));
        // The grid's speeds above 4000 rpm: 4381.25 … 5000 (8 steps from 50).
        assert!(
            line.ends_with(
                "speeds 4381.25 to 5000 rpm are above its coefficient table (0 to 4000 rpm): the coefficients are held at the table's last values there"
            ),
            "{line}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A compressor-like rotor (1.6 m × 120 mm shaft in 16 elements, five
/// impellers) on two table bearings whose stiffness is strongly anisotropic
/// and speed-dependent (kxx rising 0.5 → 2, kyy falling 2 → 0.5 × `s0` over
/// 2000 … 13000 rpm, as a vendor's tilting-pad tables may run).
fn anisotropic_table_rotor() -> String {
    let speeds = [2000.0f64, 4000.0, 6000.0, 8000.0, 10000.0, 12000.0, 13000.0];
    let list = |f: &dyn Fn(f64) -> f64| {
        let v: Vec<String> = speeds.iter().map(|&s| format!("{:e}", f(s))).collect();
        format!("[{}]", v.join(", "))
    };
    let table = |s0: f64| {
        format!(
            "type = \"table\"\nspeeds_rpm = {}\nkxx = {}\nkyy = {}\ncxx = {}\ncyy = {}\n",
            list(&|s| s),
            list(&|s| s0 * (0.5 + 1.5 * s / 13000.0)),
            list(&|s| s0 * (2.0 - 1.5 * s / 13000.0)),
            list(&|_| 0.3e-3 * s0),
            list(&|_| 0.3e-3 * s0)
        )
    };
    let disks: String = [5, 7, 9, 11, 13]
        .iter()
        .enumerate()
        .map(|(k, n)| {
            format!(
                "[[disks]]\nname = \"impeller{}\"\nnode = {n}\nmaterial = \"steel\"\nouter_diameter = 0.38\ninner_diameter = 0.12\nwidth = 0.05\n\n",
                k + 1
            )
        })
        .collect();
    format!(
        "name = \"anisotropic_tables\"\nspeed_rpm = 10000\nmax_speed_rpm = 10500\n\n[[materials]]\nname = \"steel\"\nyoungs_modulus = 211e9\nshear_modulus = 81.2e9\ndensity = 7810.0\n\n[[shaft]]\nlength = 1.6\nouter_diameter = 0.12\nmaterial = \"steel\"\nelements = 16\n\n{disks}[[bearings]]\nname = \"drive_end\"\nnode = 2\n{}\n[[bearings]]\nname = \"non_drive_end\"\nnode = 16\n{}\n[[unbalance]]\nname = \"mid\"\nnode = 9\nmagnitude = 1e-4\nphase_deg = 0.0\n",
        table(1e8),
        table(0.8e8)
    )
}

/// Issue 48: on anisotropic table bearings the orbits are ellipses and the
/// small orbits of the overhung ends (or of the stations near a nodal point)
/// whirl against the rest of the shaft, so a critical speed forward over
/// nearly all its shape was labelled "mixed whirl". At each (not overdamped)
/// critical the mode on the 1× line (a whole eigen-solve there) is split
/// here into each node's forward and backward radii `|X ± iY|/2`: the label
/// is the sense of the nodes carrying 90 % of `Σ (r_f² + r_b²)` (every node
/// one way: the mode's own label, as before), mixed otherwise; at least two
/// criticals have nodes whirling both ways and are named forward or backward
/// (the old label: mixed), and the command prints the study's labels
/// without a jump.
#[test]
fn criticals_on_anisotropic_table_bearings_are_named_by_their_dominant_whirl() {
    use rotor_bearing::analysis::campbell::{CampbellRequest, campbell_study};
    use rotor_bearing::analysis::modal::{Whirl, modal_analysis_at, orbit_radii};
    let text = anisotropic_table_rotor();
    let rotor = rotor(&text);
    let study = campbell_study(&rotor, &CampbellRequest::default_for(None)).unwrap();
    let options = ModalOptions {
        modes: 8,
        target_frequency: 0.0,
    };
    let mut both_ways = 0;
    let criticals: Vec<_> = study
        .criticals
        .iter()
        .filter(|c| !c.is_overdamped())
        .collect();
    assert!(criticals.len() >= 2, "{criticals:?}");
    for c in &criticals {
        let modes = modal_analysis_at(&rotor, c.speed, &options).unwrap().modes;
        let mode = modes
            .iter()
            .min_by(|a, b| {
                (a.damped_frequency - c.speed)
                    .abs()
                    .total_cmp(&(b.damped_frequency - c.speed).abs())
            })
            .unwrap();
        assert!((mode.damped_frequency / c.speed - 1.0).abs() < 1e-6);
        let (mut f2, mut b2, mut total) = (0.0, 0.0, 0.0);
        let (mut f_nodes, mut b_nodes) = (0, 0);
        for k in 0..rotor.model.node_count() {
            let (f, b) = orbit_radii(mode.shape[4 * k], mode.shape[4 * k + 1]);
            total += f * f + b * b;
            if f > 1.01 * b {
                f_nodes += 1;
                f2 += f * f + b * b;
            } else if b > 1.01 * f {
                b_nodes += 1;
                b2 += f * f + b * b;
            }
        }
        // Every node one way: the mode's own whirl, as before; else the
        // sense of the nodes carrying 90 % of the squared amplitude.
        let want = if f2 >= 0.9 * total {
            Whirl::Forward
        } else if b2 >= 0.9 * total {
            Whirl::Backward
        } else {
            Whirl::Mixed
        };
        assert_eq!(
            c.whirl, want,
            "{c:?}: forward {f2:e}, backward {b2:e} of {total:e}"
        );
        if f_nodes > 0 && b_nodes > 0 && want != Whirl::Mixed {
            both_ways += 1;
        }
    }
    assert!(both_ways >= 2, "{both_ways}");
    let dir = std::env::temp_dir().join(format!("rotor_aniso_tables_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("m.toml");
    std::fs::write(&path, &text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("campbell")
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for c in &criticals {
        let label = format!("branch {}  {} whirl", c.branch + 1, c.whirl.label());
        assert!(stdout.contains(&label), "{label} in\n{stdout}");
    }
    assert!(!stdout.contains("jumps"), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}
