//! The report of a hydraulic machine set (issue 48): `machine =
//! "hydro_generator"` judges the first critical speed against the runaway
//! speed and each bearing housing by its ISO 10816-5 zone, and leaves out
//! API 617's Level I; the values are the library's own (`campbell_study`,
//! `housing_vibration`); the same model as `generic` keeps the API criteria.

use std::process::Command;

use rotor_bearing::analysis::campbell::{CampbellRequest, campbell_study};
use rotor_bearing::analysis::housing_vibration::{housing_vibration, report_spans};
use rotor_bearing::model::RotorModel;
use rotor_bearing::report::hydro::housing_zone;
use rotor_bearing::report::text::short;
use rotor_bearing::rotor::Rotor;

mod report_page;
use report_page::{report_page, table_rows};

#[path = "common/pedestal_rotor.rs"]
mod pedestal_rotor;

const RPM: f64 = std::f64::consts::PI / 30.0;

/// The damped classic rotor on two 20 kg pedestals, of class `machine`,
/// runaway speed 2000 rpm.
fn model_text(machine: &str) -> String {
    pedestal_rotor::on_pedestals(4.5e-3, &format!("{machine}max_speed_rpm = 2000\n"))
}

#[test]
fn a_hydro_unit_is_judged_by_runaway_speed_and_housing_zones() {
    let text = model_text("machine = \"hydro_generator\"\nhousing_group = 3\n");
    let rows = table_rows(&report_page(&text, "hydro_report_hydro"), "summary-table");
    let rotor = Rotor::new(RotorModel::from_toml(&text, "hydro.toml").unwrap()).unwrap();
    let speed = 1000.0 * RPM;
    // The first critical speed, as the Campbell study finds it.
    let study = campbell_study(&rotor, &CampbellRequest::default_for(None)).unwrap();
    let lowest = study
        .margins
        .iter()
        .map(|m| m.critical.speed)
        .fold(f64::INFINITY, f64::min);
    assert!(
        lowest.is_finite(),
        "the classic rotor has a critical below its top speed"
    );
    let critical = rows
        .iter()
        .find(|r| r[0] == "first critical speed (Campbell)")
        .expect("the hydro critical row");
    assert_eq!(critical[2], format!("{} rpm", short(lowest / RPM)));
    assert_eq!(critical[3], "above the runaway speed 2000 rpm");
    assert_eq!(
        critical[4],
        if lowest > 2000.0 * RPM {
            "pass"
        } else {
            "FAIL"
        }
    );
    // Each bearing housing, as housing_vibration finds it, in its zone.
    let (settle, record) = report_spans(&rotor, speed);
    let housings = housing_vibration(&rotor, speed, settle, record).unwrap();
    assert_eq!(housings.len(), 2);
    for h in &housings {
        let row = rows
            .iter()
            .find(|r| r[0] == "housing vibration (ISO 10816-5)" && r[1] == h.name)
            .expect("a housing row per bearing");
        let zone = housing_zone(
            rotor_bearing::model::machine_class::HousingGroup::VerticalOnFoundation,
            h,
        );
        assert_eq!(
            row[2],
            format!(
                "{} mm/s r.m.s., {} µm pk-pk: zone {}",
                short(h.velocity_rms * 1e3),
                short(h.displacement_pp * 1e6),
                zone.letter()
            )
        );
        assert_eq!(row[4], if zone.acceptable() { "pass" } else { "FAIL" });
    }
    assert!(rows.iter().all(|r| !r[3].contains("API")), "{rows:?}");
    // `rotor campbell` gives the same verdict in its own words.
    let dir = std::env::temp_dir().join(format!("hydro-campbell-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("hydro.toml");
    std::fs::write(&file, &text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("campbell")
        .arg(&file)
        .output()
        .unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(out.status.success());
    let printed = String::from_utf8(out.stdout).unwrap();
    let line = format!(
        "first critical speed {} rpm against the runaway speed 2000 rpm (machine = hydro_generator: above it): {}\n",
        short(lowest / RPM),
        critical[4]
    );
    assert!(printed.contains(&line), "{printed}");
    assert!(!printed.contains("API 684"), "{printed}");
}

#[test]
fn a_generic_model_keeps_the_api_criteria() {
    let rows = table_rows(
        &report_page(&model_text(""), "hydro_report_generic"),
        "summary-table",
    );
    assert!(rows.iter().any(|r| r[3].contains("(API 684)")), "{rows:?}");
    assert!(rows.iter().all(|r| !r[0].contains("ISO 10816-5")));
    assert!(
        rows.iter()
            .all(|r| r[0] != "first critical speed (Campbell)")
    );
}
