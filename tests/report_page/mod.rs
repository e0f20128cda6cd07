//! The page `rotor report` writes for a model, and its tables' rows: shared
//! by the report tests that read the HTML (`hydro_report`, `hydro_loads`,
//! `hydro_torsion`).

use std::process::Command;

/// The page `rotor report` writes for the model `text` (`name` names its
/// scratch directory, unique per test).
pub fn report_page(text: &str, name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("report-page-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{name}.toml"));
    std::fs::write(&file, text).unwrap();
    let html = dir.join("report.html");
    let out = Command::new(env!("CARGO_BIN_EXE_rotor"))
        .arg("report")
        .arg(&file)
        .arg("--out")
        .arg(&html)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let page = std::fs::read_to_string(&html).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    page
}

/// The rows of the table `id` on `page`, cells stripped of tags and the
/// HTML escapes `&lt;`, `&gt;`, `&amp;` undone.
pub fn table_rows(page: &str, id: &str) -> Vec<Vec<String>> {
    let table = &page[page
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no table {id}"))..];
    let table = &table[..table.find("</table>").unwrap()];
    let strip = |c: &str| {
        let mut s = String::new();
        let mut inside = false;
        for ch in c.chars() {
            match ch {
                '<' => inside = true,
                '>' => inside = false,
                _ if !inside => s.push(ch),
                _ => {}
            }
        }
        s.replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&")
            .trim()
            .to_string()
    };
    table
        .split("<tr>")
        .skip(2)
        .map(|r| {
            r.split("<td")
                .skip(1)
                .map(|c| strip(&format!("<td{c}")))
                .collect()
        })
        .collect()
}
