//! Rotor model files (TOML) and the validated [`RotorModel`] they produce.
//!
//! `RotorModel` is plain data in SI units that has passed every check: the rest of
//! the crate never sees an unchecked number. Errors name the file, the field
//! (as a path such as `shaft[2].outer_diameter`), the offending value and, when
//! the TOML parser knows it, the line.

mod error;
pub mod file;

pub use error::ModelError;

use std::collections::HashSet;
use std::path::Path;

use crate::bearing::tilting_pad::Pad;
use crate::bearing::{BearingKind, PlainBearing, TiltingPadBearing};
use crate::fe::disk::Disk;
use crate::fe::section::{CircularSection, Material};
use crate::fe::shaft::{ShaftEffects, ShaftElement};
use error::{FieldPath, Seg};
use file::{BearingEntry, ModelFile};

/// The built-in default model: the classic disk-on-shaft rotor.
pub const DEFAULT_MODEL_NAME: &str = "classic_disk_rotor";
/// Text of the default model file (shipped as `models/classic_disk_rotor.toml`).
pub const DEFAULT_MODEL_TOML: &str = include_str!("../../models/classic_disk_rotor.toml");

/// A shaft element placed between nodes `node` and `node + 1` (0-based).
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedElement {
    /// Index of the left node (0-based).
    pub node: usize,
    /// The element's section, material and effects.
    pub element: ShaftElement,
    /// Axial tension carried by the element (N, compression negative).
    pub axial_force: f64,
}

/// A disk on a node.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedDisk {
    /// Name (default `disk<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Inertia properties.
    pub disk: Disk,
}

/// A bearing between a shaft node and ground.
#[derive(Debug, Clone, PartialEq)]
pub struct PlacedBearing {
    /// Name (default `bearing<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Bearing type and parameters.
    pub kind: BearingKind,
}

/// An unbalance plane: a mass `m` at radius `e` rotating with the shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct UnbalancePlane {
    /// Name (default `unbalance<k>`).
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
    /// Unbalance `m·e` (kg·m).
    pub magnitude: f64,
    /// Angular position at spin angle zero, from +x toward +y (rad).
    pub phase: f64,
}

/// A named node whose displacements are reported.
#[derive(Debug, Clone, PartialEq)]
pub struct Probe {
    /// Name, unique in the model.
    pub name: String,
    /// Node index (0-based).
    pub node: usize,
}

/// Ideal constraints at a node: `fixed[k]` fixes node DOF `k` (see [`crate::fe`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Support {
    /// Node index (0-based).
    pub node: usize,
    /// Which of `(x, y, θx, θy)` are fixed.
    pub fixed: [bool; 4],
}

/// A validated rotor model, SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct RotorModel {
    /// Identifier (letters, digits, `_`).
    pub name: String,
    /// Free text.
    pub description: String,
    /// Where the model came from (file path or `<built-in>`).
    pub source: String,
    /// Axial position of every node (m), increasing.
    pub node_z: Vec<f64>,
    /// Shaft elements, in node order.
    pub elements: Vec<PlacedElement>,
    /// Disks.
    pub disks: Vec<PlacedDisk>,
    /// Bearings.
    pub bearings: Vec<PlacedBearing>,
    /// Unbalance planes.
    pub unbalances: Vec<UnbalancePlane>,
    /// Probes.
    pub probes: Vec<Probe>,
    /// Ideal supports.
    pub supports: Vec<Support>,
    /// Gravity vector (m/s²), `z` along the shaft.
    pub gravity: [f64; 3],
    /// Nominal spin speed (rad/s), 0 when the file gives none.
    pub nominal_speed: f64,
}

impl RotorModel {
    /// Read and validate a model file.
    pub fn from_file(path: &Path) -> Result<Self, ModelError> {
        let source = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ModelError::Io {
            file: source.clone(),
            message: e.to_string(),
        })?;
        Self::from_toml(&text, &source)
    }

    /// The built-in default model (the classic disk-on-shaft rotor).
    pub fn default_model() -> Self {
        match Self::from_toml(DEFAULT_MODEL_TOML, "<built-in classic_disk_rotor.toml>") {
            Ok(model) => model,
            Err(e) => unreachable!("the built-in model is checked by tests: {e}"),
        }
    }

    /// Parse and validate model text; `source` names it in error messages.
    pub fn from_toml(text: &str, source: &str) -> Result<Self, ModelError> {
        let raw: ModelFile = toml::from_str(text).map_err(|e| {
            let line = e.span().map(|s| line_of(text, s.start));
            ModelError::Syntax {
                file: source.to_string(),
                line,
                message: e.message().trim().to_string(),
            }
        })?;
        let ctx = Ctx { text, source };
        build(&ctx, raw)
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.node_z.len()
    }

    /// Total rotating mass: shaft plus disks (kg).
    pub fn total_mass(&self) -> f64 {
        self.elements.iter().map(|e| e.element.mass()).sum::<f64>()
            + self.disks.iter().map(|d| d.disk.mass).sum::<f64>()
    }
}

/// 1-based line of a byte offset.
fn line_of(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

struct Ctx<'a> {
    text: &'a str,
    source: &'a str,
}

impl Ctx<'_> {
    fn err(&self, path: FieldPath, value: impl std::fmt::Display, problem: &str) -> ModelError {
        ModelError::Invalid {
            file: self.source.to_string(),
            line: self.locate(&path),
            field: path.to_string(),
            value: value.to_string(),
            problem: problem.to_string(),
        }
    }

    /// Line of a field in the source text, from the TOML parser's spans.
    fn locate(&self, path: &FieldPath) -> Option<usize> {
        let root = toml::de::DeTable::parse(self.text).ok()?;
        let mut span = root.span();
        let mut table = Some(root.get_ref());
        let mut value: Option<&toml::de::DeValue> = None;
        for seg in &path.0 {
            let next = match (seg, table, value) {
                (Seg::Key(k), Some(t), _) => t.get(k.as_str()),
                (Seg::Key(k), None, Some(v)) => v.get(k.as_str()),
                (Seg::Index(i), _, Some(v)) => v.get(*i),
                _ => None,
            }?;
            span = next.span();
            table = None;
            value = Some(next.get_ref());
        }
        Some(line_of(self.text, span.start))
    }

    fn finite(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.err(path, v, "must be a finite number"))
        }
    }

    fn positive(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(self.err(path, v, "must be a finite number greater than zero"))
        }
    }

    fn non_negative(&self, path: FieldPath, v: f64) -> Result<f64, ModelError> {
        if v.is_finite() && v >= 0.0 {
            Ok(v)
        } else {
            Err(self.err(path, v, "must be a finite number not less than zero"))
        }
    }

    /// Resolve `node` (1-based) or `z` (m) to a node index.
    fn location(
        &self,
        path: &FieldPath,
        node: Option<i64>,
        z: Option<f64>,
        node_z: &[f64],
    ) -> Result<usize, ModelError> {
        match (node, z) {
            (Some(n), None) => {
                if n >= 1 && (n as usize) <= node_z.len() {
                    Ok(n as usize - 1)
                } else {
                    Err(self.err(
                        path.key("node"),
                        n,
                        &format!("must be a node number from 1 to {}", node_z.len()),
                    ))
                }
            }
            (None, Some(z)) => {
                let z = self.finite(path.key("z"), z)?;
                let span = node_z[node_z.len() - 1] - node_z[0];
                let (best, dist) = node_z
                    .iter()
                    .enumerate()
                    .map(|(i, &zn)| (i, (zn - z).abs()))
                    .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
                if dist <= 1e-9 * span.max(1.0) {
                    Ok(best)
                } else {
                    Err(self.err(
                        path.key("z"),
                        z,
                        &format!(
                            "no node there; the nearest is node {} at z = {} m (split the shaft section so that a node falls at this position)",
                            best + 1,
                            node_z[best]
                        ),
                    ))
                }
            }
            (Some(n), Some(z)) => Err(self.err(
                path.key("node"),
                format!("{n} (and z = {z})"),
                "give either node or z, not both",
            )),
            (None, None) => Err(self.err(path.clone(), "(missing)", "needs node or z")),
        }
    }
}

fn default_name(given: Option<String>, prefix: &str, k: usize) -> String {
    given.unwrap_or_else(|| format!("{prefix}{}", k + 1))
}

fn build(ctx: &Ctx, raw: ModelFile) -> Result<RotorModel, ModelError> {
    let root = FieldPath::default();
    if raw.name.is_empty()
        || !raw
            .name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_')
        || raw.name.starts_with(|c: char| c.is_ascii_digit())
    {
        return Err(ctx.err(
            root.key("name"),
            format!("{:?}", raw.name),
            "must be a non-empty identifier of letters, digits and '_' not starting with a digit",
        ));
    }

    let mut materials: Vec<Material> = Vec::new();
    for (i, m) in raw.materials.iter().enumerate() {
        let p = root.key("materials").index(i);
        if materials.iter().any(|x| x.name == m.name) {
            return Err(ctx.err(p.key("name"), &m.name, "duplicate material name"));
        }
        let youngs_modulus = ctx.positive(p.key("youngs_modulus"), m.youngs_modulus)?;
        let density = ctx.positive(p.key("density"), m.density)?;
        let shear_modulus = match (m.shear_modulus, m.poisson_ratio) {
            (Some(g), None) => {
                let g = ctx.positive(p.key("shear_modulus"), g)?;
                let nu = youngs_modulus / (2.0 * g) - 1.0;
                if !(-1.0..0.5).contains(&nu) {
                    return Err(ctx.err(
                        p.key("shear_modulus"),
                        g,
                        &format!("gives Poisson's ratio E/(2G) − 1 = {nu:.4}, outside (−1, 0.5)"),
                    ));
                }
                g
            }
            (None, Some(nu)) => {
                if !(nu > -1.0 && nu < 0.5) {
                    return Err(ctx.err(p.key("poisson_ratio"), nu, "must lie in (−1, 0.5)"));
                }
                youngs_modulus / (2.0 * (1.0 + nu))
            }
            (Some(g), Some(_)) => {
                return Err(ctx.err(
                    p.key("shear_modulus"),
                    g,
                    "give shear_modulus or poisson_ratio, not both",
                ));
            }
            (None, None) => {
                return Err(ctx.err(p.clone(), &m.name, "needs shear_modulus or poisson_ratio"));
            }
        };
        materials.push(Material {
            name: m.name.clone(),
            youngs_modulus,
            shear_modulus,
            density,
        });
    }
    let find_material = |path: FieldPath, name: &str| -> Result<Material, ModelError> {
        materials
            .iter()
            .find(|m| m.name == name)
            .cloned()
            .ok_or_else(|| {
                let known: Vec<&str> = materials.iter().map(|m| m.name.as_str()).collect();
                ctx.err(
                    path,
                    format!("{name:?}"),
                    &format!("unknown material (defined: {known:?})"),
                )
            })
    };

    let effects = ShaftEffects {
        shear_deformation: raw.shear_deformation.unwrap_or(true),
        rotary_inertia: raw.rotary_inertia.unwrap_or(true),
    };
    let default_axial = ctx.finite(root.key("axial_force"), raw.axial_force.unwrap_or(0.0))?;
    let start_z = ctx.finite(root.key("start_z"), raw.start_z.unwrap_or(0.0))?;

    if raw.shaft.is_empty() {
        return Err(ctx.err(
            root.key("shaft"),
            "[]",
            "the model needs at least one [[shaft]] section",
        ));
    }
    let mut node_z = vec![start_z];
    let mut elements = Vec::new();
    for (i, s) in raw.shaft.iter().enumerate() {
        let p = root.key("shaft").index(i);
        let length = ctx.positive(p.key("length"), s.length)?;
        let outer = ctx.positive(p.key("outer_diameter"), s.outer_diameter)?;
        let inner = ctx.non_negative(p.key("inner_diameter"), s.inner_diameter)?;
        if inner >= outer {
            return Err(ctx.err(
                p.key("inner_diameter"),
                inner,
                &format!("must be smaller than outer_diameter = {outer}"),
            ));
        }
        let material = find_material(p.key("material"), &s.material)?;
        let count = s.elements.unwrap_or(1);
        if !(1..=1_000_000).contains(&count) {
            return Err(ctx.err(p.key("elements"), count, "must be from 1 to 1000000"));
        }
        let axial_force = match s.axial_force {
            Some(f) => ctx.finite(p.key("axial_force"), f)?,
            None => default_axial,
        };
        let element = ShaftElement {
            length: length / count as f64,
            section: CircularSection {
                outer_diameter: outer,
                inner_diameter: inner,
            },
            material,
            effects,
        };
        let z0 = node_z[node_z.len() - 1];
        for k in 0..count {
            elements.push(PlacedElement {
                node: node_z.len() - 1,
                element: element.clone(),
                axial_force,
            });
            node_z.push(z0 + length * (k + 1) as f64 / count as f64);
        }
    }

    let mut disks = Vec::new();
    for (i, d) in raw.disks.into_iter().enumerate() {
        let p = root.key("disks").index(i);
        let node = ctx.location(&p, d.node, d.z, &node_z)?;
        let by_inertia =
            d.mass.is_some() || d.polar_inertia.is_some() || d.diametral_inertia.is_some();
        let by_geometry = d.material.is_some()
            || d.outer_diameter.is_some()
            || d.inner_diameter.is_some()
            || d.width.is_some();
        let disk = match (by_inertia, by_geometry) {
            (true, false) => {
                let need = |key: &'static str, v: Option<f64>| match v {
                    Some(v) => ctx.non_negative(p.key(key), v),
                    None => Err(ctx.err(
                        p.key(key),
                        "(missing)",
                        "needed with mass-and-inertia disks",
                    )),
                };
                let mass = need("mass", d.mass)?;
                let polar_inertia = need("polar_inertia", d.polar_inertia)?;
                let diametral_inertia = need("diametral_inertia", d.diametral_inertia)?;
                Disk {
                    mass,
                    polar_inertia,
                    diametral_inertia,
                }
            }
            (false, true) => {
                let material = match &d.material {
                    Some(name) => find_material(p.key("material"), name)?,
                    None => {
                        return Err(ctx.err(
                            p.key("material"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                let outer = match d.outer_diameter {
                    Some(v) => ctx.positive(p.key("outer_diameter"), v)?,
                    None => {
                        return Err(ctx.err(
                            p.key("outer_diameter"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                let inner =
                    ctx.non_negative(p.key("inner_diameter"), d.inner_diameter.unwrap_or(0.0))?;
                if inner >= outer {
                    return Err(ctx.err(
                        p.key("inner_diameter"),
                        inner,
                        &format!("must be smaller than outer_diameter = {outer}"),
                    ));
                }
                let width = match d.width {
                    Some(v) => ctx.positive(p.key("width"), v)?,
                    None => {
                        return Err(ctx.err(
                            p.key("width"),
                            "(missing)",
                            "needed with disk geometry",
                        ));
                    }
                };
                Disk::from_geometry(material.density, outer, inner, width)
            }
            (true, true) => {
                return Err(ctx.err(
                    p.clone(),
                    "mass/inertia and geometry",
                    "give either mass, polar_inertia, diametral_inertia or material, outer_diameter, inner_diameter, width — not both",
                ));
            }
            (false, false) => {
                return Err(ctx.err(
                    p.clone(),
                    "(empty)",
                    "give mass, polar_inertia, diametral_inertia or material, outer_diameter, inner_diameter, width",
                ));
            }
        };
        disks.push(PlacedDisk {
            name: default_name(d.name, "disk", i),
            node,
            disk,
        });
    }

    let mut bearings = Vec::new();
    for (i, b) in raw.bearings.into_iter().enumerate() {
        let p = root.key("bearings").index(i);
        let (name, node, kind) = match b {
            BearingEntry::Linear {
                name,
                node,
                z,
                kxx,
                kxy,
                kyx,
                kyy,
                cxx,
                cxy,
                cyx,
                cyy,
            } => {
                let node = ctx.location(&p, node, z, &node_z)?;
                let f = |key: &str, v: f64| ctx.finite(p.key(key), v);
                let k = [
                    [f("kxx", kxx)?, f("kxy", kxy)?],
                    [f("kyx", kyx)?, f("kyy", kyy)?],
                ];
                let c = [
                    [f("cxx", cxx)?, f("cxy", cxy)?],
                    [f("cyx", cyx)?, f("cyy", cyy)?],
                ];
                for (key, v) in [
                    ("kxx", k[0][0]),
                    ("kyy", k[1][1]),
                    ("cxx", c[0][0]),
                    ("cyy", c[1][1]),
                ] {
                    ctx.non_negative(p.key(key), v)?;
                }
                (
                    name,
                    node,
                    BearingKind::Linear {
                        stiffness: k,
                        damping: c,
                    },
                )
            }
            BearingEntry::Plain {
                name,
                node,
                z,
                radius,
                length,
                clearance,
                viscosity,
            } => {
                let node = ctx.location(&p, node, z, &node_z)?;
                let bearing = PlainBearing {
                    radius: ctx.positive(p.key("radius"), radius)?,
                    length: ctx.positive(p.key("length"), length)?,
                    clearance: ctx.positive(p.key("clearance"), clearance)?,
                    viscosity: ctx.positive(p.key("viscosity"), viscosity)?,
                };
                if bearing.clearance >= 0.1 * bearing.radius {
                    return Err(ctx.err(
                        p.key("clearance"),
                        bearing.clearance,
                        &format!(
                            "must be much smaller than the radius {} (thin-film theory)",
                            bearing.radius
                        ),
                    ));
                }
                (name, node, BearingKind::Plain(bearing))
            }
            BearingEntry::TiltingPad {
                name,
                node,
                z,
                radius,
                length,
                clearance,
                viscosity,
                pads,
                first_pivot_deg,
                pivots_deg,
                pad_arc_deg,
                pivot_offset,
                preload,
            } => {
                let node = ctx.location(&p, node, z, &node_z)?;
                let radius = ctx.positive(p.key("radius"), radius)?;
                let clearance = ctx.positive(p.key("clearance"), clearance)?;
                if clearance >= 0.1 * radius {
                    return Err(ctx.err(
                        p.key("clearance"),
                        clearance,
                        &format!(
                            "must be much smaller than the radius {radius} (thin-film theory)"
                        ),
                    ));
                }
                let pivots: Vec<f64> = match (pads, first_pivot_deg, pivots_deg) {
                    (Some(count), first, None) => {
                        if !(3..=18).contains(&count) {
                            return Err(ctx.err(p.key("pads"), count, "must be from 3 to 18"));
                        }
                        let first = ctx.finite(p.key("first_pivot_deg"), first.unwrap_or(0.0))?;
                        (0..count)
                            .map(|k| first + 360.0 * k as f64 / count as f64)
                            .collect()
                    }
                    (None, None, Some(list)) => {
                        if !(3..=18).contains(&list.len()) {
                            return Err(ctx.err(
                                p.key("pivots_deg"),
                                format!("{list:?}"),
                                "must list from 3 to 18 pivot angles",
                            ));
                        }
                        for (k, v) in list.iter().enumerate() {
                            ctx.finite(p.key("pivots_deg").index(k), *v)?;
                        }
                        list
                    }
                    _ => {
                        return Err(ctx.err(
                            p.clone(),
                            "pads / first_pivot_deg / pivots_deg",
                            "give either pads (and optionally first_pivot_deg) or pivots_deg",
                        ));
                    }
                };
                let arc = ctx.positive(p.key("pad_arc_deg"), pad_arc_deg)?;
                let offset = pivot_offset.unwrap_or(0.5);
                if !(0.0..=1.0).contains(&offset) {
                    return Err(ctx.err(p.key("pivot_offset"), offset, "must lie in [0, 1]"));
                }
                let preload = preload.unwrap_or(0.0);
                if !(0.0..1.0).contains(&preload) {
                    return Err(ctx.err(p.key("preload"), preload, "must lie in [0, 1)"));
                }
                // Pads must not overlap: sorted pivots at least one arc apart.
                let mut sorted: Vec<f64> = pivots.iter().map(|d| d.rem_euclid(360.0)).collect();
                sorted.sort_by(f64::total_cmp);
                let gaps = sorted
                    .windows(2)
                    .map(|w| w[1] - w[0])
                    .chain(std::iter::once(
                        sorted[0] + 360.0 - sorted[sorted.len() - 1],
                    ));
                if gaps.fold(f64::INFINITY, f64::min) < arc {
                    return Err(ctx.err(
                        p.key("pad_arc_deg"),
                        arc,
                        "pads overlap: the arc exceeds the spacing of the pivots",
                    ));
                }
                let bearing = TiltingPadBearing {
                    radius,
                    length: ctx.positive(p.key("length"), length)?,
                    clearance,
                    viscosity: ctx.positive(p.key("viscosity"), viscosity)?,
                    pads: pivots
                        .iter()
                        .map(|d| Pad::new(d.to_radians(), arc.to_radians(), offset, preload))
                        .collect(),
                };
                (name, node, BearingKind::TiltingPad(bearing))
            }
        };
        bearings.push(PlacedBearing {
            name: default_name(name, "bearing", i),
            node,
            kind,
        });
    }

    let mut unbalances = Vec::new();
    for (i, u) in raw.unbalance.into_iter().enumerate() {
        let p = root.key("unbalance").index(i);
        let node = ctx.location(&p, u.node, u.z, &node_z)?;
        let magnitude = ctx.non_negative(p.key("magnitude"), u.magnitude)?;
        let phase = ctx.finite(p.key("phase_deg"), u.phase_deg)?.to_radians();
        unbalances.push(UnbalancePlane {
            name: default_name(u.name, "unbalance", i),
            node,
            magnitude,
            phase,
        });
    }

    let mut probes = Vec::new();
    let mut names = HashSet::new();
    for (i, pr) in raw.probes.into_iter().enumerate() {
        let p = root.key("probes").index(i);
        if !names.insert(pr.name.clone()) {
            return Err(ctx.err(p.key("name"), &pr.name, "duplicate probe name"));
        }
        let node = ctx.location(&p, pr.node, pr.z, &node_z)?;
        probes.push(Probe {
            name: pr.name,
            node,
        });
    }

    let mut supports = Vec::new();
    for (i, s) in raw.supports.into_iter().enumerate() {
        let p = root.key("supports").index(i);
        let node = ctx.location(&p, s.node, s.z, &node_z)?;
        let mut fixed = [false; 4];
        for (j, dof) in s.fix.iter().enumerate() {
            let set: &[usize] = match dof.as_str() {
                "x" => &[0],
                "y" => &[1],
                "rx" => &[2],
                "ry" => &[3],
                "pinned" => &[0, 1],
                "clamped" => &[0, 1, 2, 3],
                _ => {
                    return Err(ctx.err(
                        p.key("fix").index(j),
                        format!("{dof:?}"),
                        "must be one of \"x\", \"y\", \"rx\", \"ry\", \"pinned\", \"clamped\"",
                    ));
                }
            };
            for &k in set {
                fixed[k] = true;
            }
        }
        supports.push(Support { node, fixed });
    }

    let gravity = raw.gravity.unwrap_or([0.0; 3]);
    for (k, g) in gravity.iter().enumerate() {
        ctx.finite(root.key("gravity").index(k), *g)?;
    }

    let nominal_speed = ctx.finite(root.key("speed_rpm"), raw.speed_rpm.unwrap_or(0.0))?
        * std::f64::consts::PI
        / 30.0;
    Ok(RotorModel {
        nominal_speed,
        name: raw.name,
        description: raw.description,
        source: ctx.source.to_string(),
        node_z,
        elements,
        disks,
        bearings,
        unbalances,
        probes,
        supports,
        gravity,
    })
}

#[cfg(test)]
mod tests;
