//! Validation of a parsed model file into a [`RotorModel`], one section at a
//! time in file order (so the first error reported is the first in the file's
//! logical order): name, materials, shaft, disks, pedestals, bearings, loads
//! (unbalance), probes, supports, gravity and nominal speed.

mod bearings;
mod contact;
mod couplings;
mod disks;
mod loads;
mod materials;
mod pedestals;
mod placement;
mod point_masses;
mod shaft;
mod stators;
mod supports;
mod tables;
mod torsion;

use super::context::Ctx;
use super::error::FieldPath;
use super::file::ModelFile;
use super::{ModelError, RotorModel};

/// Check every section of `raw` and assemble the model.
pub(super) fn build(ctx: &Ctx, raw: ModelFile) -> Result<RotorModel, ModelError> {
    let root = FieldPath::default();
    check_name(ctx, &root, &raw.name)?;
    let materials = materials::materials(ctx, &root, &raw.materials)?;
    let shaft = shaft::shaft(ctx, &root, &raw, &materials)?;
    let node_z = shaft.node_z;
    let disks = disks::disks(ctx, &root, raw.disks, &node_z, &materials)?;
    let pedestals = pedestals::pedestals(ctx, &root, &raw.pedestals)?;
    let point_masses = point_masses::point_masses(ctx, &root, raw.point_masses, &node_z)?;
    let (bearings, table_files) = bearings::bearings(
        ctx,
        &root,
        (raw.bearings, raw.rubs, raw.seals, raw.magnetic_pull),
        &node_z,
        &shaft.elements,
        &pedestals,
    )?;
    pedestals::check_carried(ctx, &root, &pedestals, &bearings)?;
    let unbalances = loads::unbalances(ctx, &root, raw.unbalance, &node_z)?;
    let probes = loads::probes(ctx, &root, raw.probes, &node_z, &bearings)?;
    let forces = loads::forces(ctx, &root, raw.forces, &node_z)?;
    let ports = loads::ports(ctx, &root, raw.ports, &node_z)?;
    let couplings = couplings::couplings(ctx, &root, raw.couplings, &node_z, &shaft.elements)?;
    let torques = torsion::torques(ctx, &root, raw.torques, &node_z)?;
    let torsional_damping_ratio = torsion::damping_ratio(ctx, &root, raw.torsion.as_ref())?;
    let drive = torsion::drive(ctx, &root, raw.torsion, &torques)?;
    let supports = supports::supports(ctx, &root, raw.supports, &node_z)?;
    let gravity = loads::gravity(ctx, &root, raw.gravity)?;
    let weight = {
        let mass: f64 = shaft.elements.iter().map(|e| e.element.mass()).sum::<f64>()
            + disks.iter().map(|d| d.disk.mass).sum::<f64>();
        mass * gravity[2].abs()
    };
    let thrust_bearings =
        torsion::thrust_bearings(ctx, &root, raw.thrust_bearings, &node_z, weight)?;
    // Nominal speed: rpm → rad/s.
    let nominal_speed = ctx.finite(root.key("speed_rpm"), raw.speed_rpm.unwrap_or(0.0))?
        * std::f64::consts::PI
        / 30.0;
    let max_speed = ctx.within(
        root.key("max_speed_rpm"),
        raw.max_speed_rpm.unwrap_or(super::DEFAULT_MAX_SPEED_RPM),
        &super::limits::MAX_SPEED_RPM,
    )? * std::f64::consts::PI
        / 30.0;
    if nominal_speed.abs() > max_speed {
        return Err(ctx.err(
            root.key("speed_rpm"),
            format!("{}", raw.speed_rpm.unwrap_or(0.0)),
            "must not exceed max_speed_rpm",
        ));
    }
    let operating_range = match &raw.operating_rpm {
        None => None,
        Some(v) => {
            let path = root.key("operating_rpm");
            let shown = format!("{v:?}");
            if v.len() != 2 {
                return Err(ctx.err(path, shown, "must be [min, max] in rpm"));
            }
            let (a, b) = (
                ctx.positive(path.index(0), v[0])?,
                ctx.positive(path.index(1), v[1])?,
            );
            if b < a || b * std::f64::consts::PI / 30.0 > max_speed {
                return Err(ctx.err(
                    path,
                    shown,
                    "must be [min, max] with 0 < min ≤ max ≤ max_speed_rpm",
                ));
            }
            Some([
                a * std::f64::consts::PI / 30.0,
                b * std::f64::consts::PI / 30.0,
            ])
        }
    };
    let (machine, housing_group) = machine_class(ctx, &root, &raw.machine, raw.housing_group)?;
    let (grid_frequency, torsional_margin) = torsional_criteria(
        ctx,
        &root,
        machine,
        raw.grid_frequency_hz,
        raw.torsional_margin,
    )?;
    let reduction = match raw.reduction {
        None => None,
        Some(r) => Some(match r.modes {
            None => super::ReductionRequest::FromSpeedRange,
            Some(m) if (1..=super::MAX_REDUCED_MODES as i64).contains(&m) => {
                super::ReductionRequest::Modes(m as usize)
            }
            Some(m) => {
                return Err(ctx.err(
                    root.key("reduction").key("modes"),
                    m,
                    &format!(
                        "must be a mode count from 1 to {}",
                        super::MAX_REDUCED_MODES
                    ),
                ));
            }
        }),
    };
    let tolerance_cases = super::tolerance_cases::validate(ctx, &root, raw.cases, &bearings)?;
    let shaft_zones =
        super::shaft_zones::validate(ctx, &root, raw.shaft_vibration_zones, machine, &bearings)?;
    let model = RotorModel {
        reduction,
        tolerance_cases,
        shaft_zones,
        nominal_speed,
        max_speed,
        max_speed_stated: raw.max_speed_rpm.is_some(),
        operating_range,
        machine,
        housing_group,
        grid_frequency,
        torsional_margin,
        name: raw.name,
        description: raw.description,
        source: ctx.source.to_string(),
        node_z,
        elements: shaft.elements,
        disks,
        point_masses,
        bearings,
        table_files,
        unbalances,
        probes,
        forces,
        ports,
        couplings,
        torques,
        thrust_bearings,
        drive,
        torsional_damping_ratio,
        supports,
        pedestals,
        gravity,
    };
    loads::check_force_bounds(ctx, &root, &model)?;
    Ok(model)
}

/// The model name must be an identifier (it becomes the FMU's model name).
fn check_name(ctx: &Ctx, root: &FieldPath, name: &str) -> Result<(), ModelError> {
    if name.is_empty()
        || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        || name.starts_with(|c: char| c.is_ascii_digit())
    {
        return Err(ctx.err(
            root.key("name"),
            format!("{name:?}"),
            "must be a non-empty identifier of letters, digits and '_' not starting with a digit",
        ));
    }
    Ok(())
}

/// `machine` and `housing_group`: the class (default generic) and, for a
/// hydro class, its ISO 10816-5 group; a group on another class is an error.
fn machine_class(
    ctx: &Ctx,
    root: &FieldPath,
    machine: &Option<String>,
    group: Option<i64>,
) -> Result<
    (
        super::machine_class::MachineClass,
        Option<super::machine_class::HousingGroup>,
    ),
    ModelError,
> {
    use super::machine_class::{HousingGroup, MachineClass};
    let class = match machine {
        None => MachineClass::Generic,
        Some(name) => MachineClass::parse(name).ok_or_else(|| {
            let names: Vec<&str> = MachineClass::ALL.iter().map(|(_, n)| *n).collect();
            ctx.err(
                root.key("machine"),
                format!("{name:?}"),
                &format!("must be one of {}", names.join(", ")),
            )
        })?,
    };
    let group = match group {
        None => None,
        Some(n) => {
            let path = root.key("housing_group");
            if !class.is_hydro() {
                return Err(ctx.err(
                    path,
                    n,
                    "is an ISO 10816-5 group of hydraulic machine sets: give it with machine = \"hydro_generator\" or \"pump_turbine\"",
                ));
            }
            Some(HousingGroup::of(n).ok_or_else(|| {
                ctx.err(
                    path,
                    n,
                    "must be 2 (horizontal, housings braced on the casing), 3 (vertical, all housings on the foundation) or 4 (vertical, upper housings on the generator stator)",
                )
            })?)
        }
    };
    Ok((class, group))
}

/// `grid_frequency_hz` and `torsional_margin`: the criteria of a hydro
/// class's torsional modes (the grid frequency in hertz, the margin a
/// fraction); on another class an error.
fn torsional_criteria(
    ctx: &Ctx,
    root: &FieldPath,
    class: super::machine_class::MachineClass,
    grid: Option<f64>,
    margin: Option<f64>,
) -> Result<(Option<f64>, Option<f64>), ModelError> {
    for (key, value) in [("grid_frequency_hz", grid), ("torsional_margin", margin)] {
        if value.is_some() && !class.is_hydro() {
            return Err(ctx.err(
                root.key(key),
                crate::units::Short(value.unwrap_or_default()),
                "judges a hydraulic machine set's torsional modes: give it with machine = \"hydro_generator\" or \"pump_turbine\"",
            ));
        }
    }
    let grid = match grid {
        Some(f) => Some(ctx.within(
            root.key("grid_frequency_hz"),
            f,
            &super::limits::GRID_FREQUENCY_HZ,
        )?),
        None => None,
    };
    let margin = match margin {
        Some(m) => Some(ctx.within(
            root.key("torsional_margin"),
            m,
            &super::limits::TORSIONAL_MARGIN,
        )?),
        None => None,
    };
    Ok((grid, margin))
}
