//! Reports of analyses as text tables: the CSV files the `rotor` command writes
//! ([`csv`]) and the series and summary numbers taken from results for plots and
//! messages ([`series`]). No physics here: only selection and formatting.

pub mod csv;
pub mod series;
