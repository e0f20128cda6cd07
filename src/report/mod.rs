//! Reports of analyses as text tables: the CSV files the `rotor` command writes
//! ([`csv`]) and the series and summary numbers taken from results for plots and
//! messages ([`series`]). No physics here: only selection and formatting.
//!
//! Writing the static deflection of the built-in rotor as CSV:
//!
//! ```
//! use rotor_bearing::analysis::linear::static_deflection;
//! use rotor_bearing::model::RotorModel;
//! use rotor_bearing::report::{csv, series};
//! use rotor_bearing::rotor::Rotor;
//!
//! let rotor = Rotor::new(RotorModel::default_model())?;
//! let q = static_deflection(&rotor)?;
//! let text = csv::static_deflection(&rotor.model.node_z, &q);
//! assert!(text.starts_with("node,z_m,x_m,y_m,rx_rad,ry_rad\n"));
//! assert_eq!(text.lines().count(), 1 + rotor.model.node_count());
//! // Gravity along −y: the disk at mid-span (node 4) sags most.
//! let (node, sag) = series::largest_deflection(&q, rotor.model.node_count());
//! assert_eq!(node, 3);
//! assert!(sag > 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod api;
pub mod cases;
pub mod csv;
pub mod html;
pub mod hydro;
pub mod hydro_loads;
pub mod hydro_torsion;
pub mod level_two;
pub mod orbits;
pub mod review;
pub mod review_summary;
pub mod series;
pub mod stamp;
pub mod text;
