//! Issue 47, acceptance 5 (lift-off): a rotor at rest lifts off on finite
//! films as on short ones, the contact law unchanged. The Jeffcott rotor
//! (two plain bearings, L/D 0.5) on the finite film with force tables
//! (mesh 72 × 6, Gümbel and Swift–Stieber, built once into a scratch cache):
//! at standstill its journals rest on the same contact law, at the same
//! position, as on the short film (the film carries nothing without
//! rotation); a slow run-up lifts them off within 2 % of the speed at which
//! the finite film's static equilibrium first stays clear of contact, and a
//! slow coast-down touches down within 2 % of it — the test
//! `tests/operating_envelope.rs` holds for the short film. The finite
//! film's lift-off speed is its own (printed against the short film's).

use std::path::{Path, PathBuf};

use rotor_bearing::model::RotorModel;

#[path = "common/lift_off.rs"]
mod lift_off;
use lift_off::{contact, ramp, settled, static_lift_off};

fn jeffcott(film: &str, dir: &Path) -> RotorModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("models/jeffcott.toml");
    let text = std::fs::read_to_string(path)
        .unwrap()
        .replace("type = \"plain\"\n", &format!("type = \"plain\"\n{film}"));
    RotorModel::from_toml_cached(&text, "jeffcott_lift_off.toml", Some(dir)).unwrap()
}

#[test]
fn a_rotor_at_rest_lifts_off_on_finite_films_as_on_short_ones() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("lift_off_tables_{}", std::process::id()));
    let short = jeffcott("", &dir);
    let short_lift_off = static_lift_off(&short, 1e-3, 100.0);
    let at_rest = settled(&short, 0.0);
    for cavitation in ["gumbel", "swift_stieber"] {
        let finite = jeffcott(
            &format!(
                "film = \"finite\"\nfilm_mesh = [72, 6]\ncavitation = \"{cavitation}\"\nfilm_tables = true\n"
            ),
            &dir,
        );
        // At standstill: the same contact law, the same resting position.
        let rest = settled(&finite, 0.0);
        for (f, s) in rest.bearings.iter().zip(&at_rest.bearings) {
            assert!(s.report.contact_force > 0.0);
            assert!(
                (f.report.contact_force - s.report.contact_force).abs()
                    <= 1e-9 * s.report.contact_force,
                "{cavitation}: {} N against {} N on the short film",
                f.report.contact_force,
                s.report.contact_force
            );
            assert!((f.x - s.x).abs() <= 1e-12 && (f.y - s.y).abs() <= 1e-12);
        }
        let lift_off = static_lift_off(&finite, 1e-3, 100.0);
        eprintln!(
            "{cavitation}: static lift-off {lift_off:.4} rad/s on the finite film, {short_lift_off:.4} on the short film"
        );
        let (below, above) = (0.8 * lift_off, 1.2 * lift_off);
        let up = ramp(&finite, (below, above), (200.0, 0.0), 1e-2);
        assert!(contact(&up[0]) > 0.0, "below lift-off the journals touch");
        let last_contact = up.iter().rposition(|o| contact(o) > 0.0).unwrap();
        let lift = up[last_contact + 1].speed;
        eprintln!("{cavitation}: the run-up lifts off at {lift:.4} rad/s");
        assert!(
            (lift - lift_off).abs() < 0.02 * lift_off,
            "{cavitation}: run-up lifts off at {lift} rad/s, static lift-off {lift_off} rad/s"
        );
        let down = ramp(&finite, (above, below), (200.0, 0.0), 1e-2);
        assert_eq!(contact(&down[0]), 0.0, "floating at {above} rad/s");
        let touch = down[down.iter().position(|o| contact(o) > 0.0).unwrap()].speed;
        eprintln!("{cavitation}: the coast-down touches down at {touch:.4} rad/s");
        assert!(
            (touch - lift_off).abs() < 0.02 * lift_off,
            "{cavitation}: coast-down touches down at {touch} rad/s, static lift-off {lift_off} rad/s"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
