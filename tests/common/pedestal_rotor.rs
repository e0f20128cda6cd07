//! The damped classic rotor (bearings 1 MN/m, 4000 N·s/m) on two 20 kg
//! pedestals (5 MN/m, 2000 N·s/m), shared by the housing-vibration tests.

use rotor_bearing::model::DEFAULT_MODEL_TOML;

/// Its model text with `unbalance` kg·m at the disk and the top-level keys
/// `keys` (each ending in a newline) before `speed_rpm`.
pub fn on_pedestals(unbalance: f64, keys: &str) -> String {
    DEFAULT_MODEL_TOML
        .replace("kyy = 1e6\n", "kyy = 1e6\ncxx = 4000.0\ncyy = 4000.0\n")
        .replace(
            "name = \"drive_end\"\n",
            "name = \"drive_end\"\npedestal = \"left\"\n",
        )
        .replace(
            "name = \"non_drive_end\"\n",
            "name = \"non_drive_end\"\npedestal = \"right\"\n",
        )
        .replace("magnitude = 0.001", &format!("magnitude = {unbalance:e}"))
        .replace("speed_rpm = 1000 ", &format!("{keys}speed_rpm = 1000 "))
        + "\n[[pedestals]]\nname = \"left\"\nmass = 20.0\nkxx = 5e6\nkyy = 5e6\ncxx = 2000.0\ncyy = 2000.0\n"
        + "[[pedestals]]\nname = \"right\"\nmass = 20.0\nkxx = 5e6\nkyy = 5e6\ncxx = 2000.0\ncyy = 2000.0\n"
}
