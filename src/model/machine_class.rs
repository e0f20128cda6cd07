//! The machine's class (`machine = …`): which criteria the report and the
//! verdict lines judge it by. `generic` (the default) keeps the API 684/617
//! criteria every machine was judged by before the key existed; the hydro
//! classes are judged by ISO 10816-5 (bearing-housing vibration zones of
//! hydraulic machine sets) and their first critical speed against the
//! runaway speed; the API classes by API 684/617.

/// The separation (fraction) a hydro class's torsional natural frequencies
/// keep from the running speed and from the grid frequency and its double
/// when the model gives no `torsional_margin`: 10 %, an engineering
/// assumption of this tool, not a standard's value. (ISO 22266-1 sets such
/// margins for steam and gas turbine generator sets, not hydro units; its
/// numbers are not reproduced here.)
pub const DEFAULT_TORSIONAL_MARGIN: f64 = 0.10;

/// What kind of machine the model describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MachineClass {
    /// Today's criteria (API 684 separation margins, API 617 Level I).
    #[default]
    Generic,
    /// A hydro generator set (turbine and generator).
    HydroGenerator,
    /// A reversible pump-turbine and motor-generator.
    PumpTurbine,
    /// A centrifugal compressor (API 617).
    Compressor,
    /// A steam turbine (API 612).
    SteamTurbine,
    /// A centrifugal pump (API 610).
    Pump,
}

impl MachineClass {
    /// Every class with its model-file name.
    pub const ALL: [(MachineClass, &'static str); 6] = [
        (MachineClass::Generic, "generic"),
        (MachineClass::HydroGenerator, "hydro_generator"),
        (MachineClass::PumpTurbine, "pump_turbine"),
        (MachineClass::Compressor, "compressor"),
        (MachineClass::SteamTurbine, "steam_turbine"),
        (MachineClass::Pump, "pump"),
    ];

    /// The class named `name` in a model file.
    pub fn parse(name: &str) -> Option<MachineClass> {
        Self::ALL.iter().find(|(_, n)| *n == name).map(|(c, _)| *c)
    }

    /// Its model-file name.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(c, _)| *c == self)
            .map_or("generic", |(_, n)| n)
    }

    /// A machine judged by API 684/617 with its own unbalance cases
    /// ([`crate::analysis::api_unbalance`]): compressor, steam turbine, pump.
    pub fn is_api(self) -> bool {
        matches!(
            self,
            MachineClass::Compressor | MachineClass::SteamTurbine | MachineClass::Pump
        )
    }

    /// A machine set of a hydraulic power or pumping plant (ISO 10816-5).
    pub fn is_hydro(self) -> bool {
        matches!(
            self,
            MachineClass::HydroGenerator | MachineClass::PumpTurbine
        )
    }
}

/// The machine group of ISO 10816-5:2000, Annex A, whose bearing-housing
/// zone boundaries apply (`housing_group = 2 | 3 | 4`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HousingGroup {
    /// Group 2: horizontal sets whose bearing housings are braced only
    /// against the hydraulic machine's casing (bulb units, usually below
    /// 300 r/min): velocity boundaries only.
    HorizontalOnCasing,
    /// Group 3: vertical sets whose bearing housings are all braced against
    /// the foundation (60 to 1800 r/min).
    VerticalOnFoundation,
    /// Group 4: vertical sets whose lower bearing housings are braced against
    /// the foundation and whose upper ones only against the generator stator
    /// (60 to 1000 r/min).
    VerticalUpperOnStator,
}

impl HousingGroup {
    /// The group of number `n` (2, 3 or 4).
    pub fn of(n: i64) -> Option<HousingGroup> {
        match n {
            2 => Some(HousingGroup::HorizontalOnCasing),
            3 => Some(HousingGroup::VerticalOnFoundation),
            4 => Some(HousingGroup::VerticalUpperOnStator),
            _ => None,
        }
    }

    /// Its number in ISO 10816-5.
    pub fn number(self) -> u8 {
        match self {
            HousingGroup::HorizontalOnCasing => 2,
            HousingGroup::VerticalOnFoundation => 3,
            HousingGroup::VerticalUpperOnStator => 4,
        }
    }
}
