//! Deflectometer drops as an AASHTO PDDX file (Pavement Deflection Data Exchange); `drops.rs`
//! tells it from a CSV file and places its drops.
//!
//! A PDDX file is INI-like: `[Section]` headings, then `Key = value, value, …` lines. liftoff
//! reads these keys (the names are PDDX's; the case of a key and the spaces around `=` do not
//! matter; lines starting with `;` or `#` are comments, a value holds none; other keys and
//! sections are skipped):
//!
//! ```text
//! [Pavement Deflection Data Exchange File]
//! ; versions 1.x and 2.x are read; the two symbols are optional (defaults `,` and `.`)
//! PDDXVersionNumber = 2.0
//! DelimiterSymbol = ,
//! DecimalSymbol = .
//! [Units]
//! LoadPlateRadiusUnits = millimeter
//! LoadUnits = kilo-Newton
//! DeflectionUnits = micron
//! SensorLocationUnits = millimeter
//! [Device Configuration]
//! LoadPlateRadius = 150
//! NumberOfDeflectionSensors = 9
//! DeflectionSensorXAxisDistances = 0, 203, 305, 457, 610, 914, 1219, 1524, 1829
//! ; optional, and if given all 0
//! DeflectionSensorYAxisDistances = 0, 0, 0, 0, 0, 0, 0, 0, 0
//! [Test Location 1]
//! ; optional: the first value names the station (else the section's number: `1`)
//! TestLocation = 1.000, 0, 0
//! ; optional: checked against the drop lines
//! NumberOfDrops = 2
//! DropData1 = 27.0, 71.2, 68.6, 63.6, 60.8, 54.3, 44.8, 34.3, 23.0, 12.4
//! DropData2 = 40.0, 106.0, 100.9, 94.2, 91.5, 80.7, 63.7, 49.2, 33.5, 20.2
//! ```
//!
//! A drop line (`DropData1`, `DropData_1`, …; numbered 1, 2, … in the file's order) holds the
//! peak load and then one peak deflection per sensor, in the sensors' order. That is the layout
//! of the PDDX files we could see; the specification's field tables (FHWA-HRT-07-040,
//! Appendix C) were not at hand, so a drop line with any other count of values is refused
//! naming its key rather than guessed at. The units are words (`millimeter`, `inch`, `meter`;
//! `kilo-Newton`, `Newton`, `pound`, `kip`; `micron`, `mil`, `millimeter`), required: a file
//! without them cannot be read safely. Sensors off the sensor line (a Y distance that is not 0)
//! or behind the plate (a negative X distance) are refused: liftoff places a drop's sensors on
//! one ray from the plate's centre. PDDX does not say where on a slab a drop was made in a form
//! liftoff reads: every drop is `interior`, at the template's centre, unless a placement says
//! where the file's drops stood (`drops.rs`; `liftoff backcalc --location --at --direction`).
//! Every drop is [`Drop::check`]ed, as a CSV file's are.

use super::area::Basin;
use super::basins::{Drop, Location};
use crate::error::{Error, Result};
use crate::units::{FOOT, INCH, POUND_FORCE};

/// A unit word as it is written in `[Units]`, lower case without separators or a plural `s`.
fn unit_word(word: &str) -> String {
    let w: String = word
        .chars()
        .filter(|c| !matches!(c, '-' | '_' | ' '))
        .flat_map(char::to_lowercase)
        .collect();
    match w.strip_suffix("es").filter(|s| s.ends_with("inch")) {
        Some(s) => s.to_string(),
        None => w.strip_suffix('s').map_or(w.clone(), str::to_string),
    }
}

/// A length unit word, m per unit.
fn length(word: &str) -> Option<f64> {
    match unit_word(word).as_str() {
        "millimeter" | "millimetre" | "mm" => Some(1e-3),
        "centimeter" | "centimetre" | "cm" => Some(1e-2),
        "meter" | "metre" | "m" => Some(1.0),
        "inch" | "in" => Some(INCH),
        "foot" | "feet" | "ft" => Some(FOOT),
        _ => None,
    }
}

/// A force unit word, N per unit.
fn force(word: &str) -> Option<f64> {
    match unit_word(word).as_str() {
        "kilonewton" | "kn" => Some(1e3),
        "newton" | "n" => Some(1.0),
        "pound" | "poundforce" | "lb" | "lbf" => Some(POUND_FORCE),
        "kip" | "kilopound" => Some(1e3 * POUND_FORCE),
        _ => None,
    }
}

/// A deflection unit word, m per unit.
fn deflection(word: &str) -> Option<f64> {
    match unit_word(word).as_str() {
        "micron" | "micrometer" | "micrometre" | "um" | "µm" => Some(1e-6),
        "mil" | "thousandthinch" => Some(1e-3 * INCH),
        "millimeter" | "millimetre" | "mm" => Some(1e-3),
        _ => None,
    }
}

/// One `Key = value` line: its section, key and value, and its line in the file.
struct Entry<'a> {
    section: &'a str,
    key: &'a str,
    value: &'a str,
    line: usize,
}

/// The file's entries in order, or the first line that is neither a heading, an entry, a
/// comment nor blank.
fn entries<'a>(text: &'a str, source: &str) -> Result<Vec<Entry<'a>>> {
    let mut section = "";
    let mut out = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let l = raw.trim();
        if l.is_empty() || l.starts_with(';') || l.starts_with('#') {
            continue;
        }
        if let Some(rest) = l.strip_prefix('[') {
            section = rest
                .strip_suffix(']')
                .ok_or_else(|| {
                    Error::invalid(
                        format!("{source}: line {}", i + 1),
                        format!("`{l}` opens a section heading without closing it with `]`"),
                    )
                })?
                .trim();
            continue;
        }
        let (key, value) = l.split_once('=').ok_or_else(|| {
            Error::invalid(
                format!("{source}: line {}", i + 1),
                format!("`{l}` is neither a `[Section]` heading nor a `Key = value` line"),
            )
        })?;
        out.push(Entry {
            section,
            key: key.trim(),
            value: value.trim(),
            line: i + 1,
        });
    }
    Ok(out)
}

/// The file's own conventions: its delimiter and decimal symbol.
struct Symbols {
    delimiter: char,
    decimal: char,
}

impl Symbols {
    /// A value's items, split at the delimiter and trimmed.
    fn items<'a>(&self, value: &'a str) -> Vec<&'a str> {
        value.split(self.delimiter).map(str::trim).collect()
    }

    /// A number written with the file's decimal symbol.
    fn number(&self, item: &str) -> Option<f64> {
        let t = if self.decimal == '.' {
            item.to_string()
        } else {
            item.replace(self.decimal, ".")
        };
        t.parse::<f64>().ok().filter(|v| v.is_finite())
    }
}

/// Read drops from a PDDX file's text (see the module's description); `source` names the file in
/// errors. Every drop is [`Drop::check`]ed.
pub fn read_pddx(text: &str, source: &str) -> Result<Vec<Drop>> {
    let entries = entries(text, source)?;
    let same = |a: &str, b: &str| a.eq_ignore_ascii_case(b);
    let find = |section: &str, key: &str| {
        entries
            .iter()
            .find(|e| same(e.section, section) && same(e.key, key))
    };
    let field = |section: &str, key: &str| format!("{source}: [{section}] {key}");
    let need = |section: &str, key: &str, what: &str| {
        find(section, key).ok_or_else(|| {
            Error::invalid(
                field(section, key),
                format!("is missing: a PDDX survey needs {what}"),
            )
        })
    };
    const HEAD: &str = "Pavement Deflection Data Exchange File";
    let version = need(HEAD, "PDDXVersionNumber", "its version (1.0 or 2.0)")?;
    let major = version.value.split('.').next().unwrap_or("").trim();
    if !matches!(major, "1" | "2") {
        return Err(Error::invalid(
            field(HEAD, "PDDXVersionNumber"),
            format!(
                "`{}`: liftoff reads PDDX versions 1.x and 2.x",
                version.value
            ),
        ));
    }
    let symbol = |key: &str, default: char| -> Result<char> {
        match find(HEAD, key) {
            None => Ok(default),
            Some(e) => {
                let mut chars = e.value.chars();
                match (chars.next(), chars.next()) {
                    (Some(c), None) => Ok(c),
                    _ => Err(Error::invalid(
                        field(HEAD, key),
                        format!("must be one character, got `{}`", e.value),
                    )),
                }
            }
        }
    };
    let symbols = Symbols {
        delimiter: symbol("DelimiterSymbol", ',')?,
        decimal: symbol("DecimalSymbol", '.')?,
    };
    if symbols.delimiter == symbols.decimal {
        return Err(Error::invalid(
            field(HEAD, "DecimalSymbol"),
            "is the delimiter too: the two must differ",
        ));
    }
    let unit = |key: &str, of: fn(&str) -> Option<f64>, words: &str| -> Result<f64> {
        let e = need("Units", key, "the units of its numbers")?;
        of(e.value).ok_or_else(|| {
            Error::invalid(
                field("Units", key),
                format!("`{}` is not a unit liftoff reads here: {words}", e.value),
            )
        })
    };
    let lengths = "millimeter, centimeter, meter, inch or foot";
    let radius_unit = unit("LoadPlateRadiusUnits", length, lengths)?;
    let load_unit = unit("LoadUnits", force, "kilo-Newton, Newton, pound or kip")?;
    let deflection_unit = unit("DeflectionUnits", deflection, "micron, mil or millimeter")?;
    let sensor_unit = unit("SensorLocationUnits", length, lengths)?;

    const DEVICE: &str = "Device Configuration";
    let numbers = |e: &Entry, section: &str| -> Result<Vec<f64>> {
        symbols
            .items(e.value)
            .iter()
            .map(|item| {
                symbols.number(item).ok_or_else(|| {
                    Error::invalid(
                        field(section, e.key),
                        format!("`{item}` (line {}) is not a number", e.line),
                    )
                })
            })
            .collect()
    };
    let one = |e: &Entry, section: &str| -> Result<f64> {
        match numbers(e, section)?.as_slice() {
            [v] => Ok(*v),
            _ => Err(Error::invalid(
                field(section, e.key),
                format!("must be one number, got `{}`", e.value),
            )),
        }
    };
    let radius = one(
        need(DEVICE, "LoadPlateRadius", "the load plate's radius")?,
        DEVICE,
    )? * radius_unit;
    let count = one(
        need(
            DEVICE,
            "NumberOfDeflectionSensors",
            "the number of its sensors",
        )?,
        DEVICE,
    )?;
    if !(count >= 2.0 && count.fract() == 0.0) {
        return Err(Error::invalid(
            field(DEVICE, "NumberOfDeflectionSensors"),
            format!("must be a whole number, two or more, got {count}"),
        ));
    }
    let n = count as usize;
    let xs = numbers(
        need(
            DEVICE,
            "DeflectionSensorXAxisDistances",
            "its sensors' distances from the plate",
        )?,
        DEVICE,
    )?;
    if xs.len() != n {
        return Err(Error::invalid(
            field(DEVICE, "DeflectionSensorXAxisDistances"),
            format!(
                "gives {} distances for the {n} sensors of NumberOfDeflectionSensors",
                xs.len()
            ),
        ));
    }
    if let Some(e) = find(DEVICE, "DeflectionSensorYAxisDistances") {
        let ys = numbers(e, DEVICE)?;
        if ys.len() != n {
            return Err(Error::invalid(
                field(DEVICE, e.key),
                format!(
                    "gives {} distances for the {n} sensors of NumberOfDeflectionSensors",
                    ys.len()
                ),
            ));
        }
        if let Some(i) = ys.iter().position(|&y| y != 0.0) {
            return Err(Error::invalid(
                field(DEVICE, e.key),
                format!(
                    "sensor {} stands {} off the sensor line: liftoff reads sensors on one line through the plate's centre (all Y distances 0)",
                    i + 1,
                    ys[i]
                ),
            ));
        }
    }
    if let Some(i) = xs.iter().position(|&x| x < 0.0) {
        return Err(Error::invalid(
            field(DEVICE, "DeflectionSensorXAxisDistances"),
            format!(
                "sensor {} stands behind the plate ({}): liftoff reads sensors on one side of it; remove that sensor's distance and its deflection from every drop",
                i + 1,
                xs[i]
            ),
        ));
    }
    // The sensors in the order of their offsets, as the basin needs them.
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| xs[a].total_cmp(&xs[b]));
    let offsets: Vec<f64> = order.iter().map(|&i| xs[i] * sensor_unit).collect();

    // The test locations, in the file's order: a section `Test Location …` each.
    let mut drops: Vec<Drop> = Vec::new();
    let mut sections: Vec<&str> = Vec::new();
    for e in &entries {
        let name = e.section;
        let is_location = name
            .get(..13)
            .is_some_and(|p| p.eq_ignore_ascii_case("Test Location"));
        if is_location && !sections.contains(&name) {
            sections.push(name);
        }
    }
    for section in sections {
        let here = |key: &str| find(section, key);
        let station = here("TestLocation")
            .and_then(|e| symbols.items(e.value).first().map(|s| s.to_string()))
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| section[13..].trim().to_string());
        let earlier = drops.iter().filter(|d| d.station == station).count();
        let lines: Vec<&Entry> = entries
            .iter()
            .filter(|e| {
                same(e.section, section)
                    && e.key
                        .get(..8)
                        .is_some_and(|p| p.eq_ignore_ascii_case("DropData"))
            })
            .collect();
        if let Some(e) = here("NumberOfDrops") {
            let said = one(e, section)?;
            if said != lines.len() as f64 {
                return Err(Error::invalid(
                    field(section, e.key),
                    format!(
                        "says {said} drops, the section holds {} DropData lines",
                        lines.len()
                    ),
                ));
            }
        }
        for (k, e) in lines.iter().enumerate() {
            let values = numbers(e, section)?;
            if values.len() != n + 1 {
                return Err(Error::invalid(
                    field(section, e.key),
                    format!(
                        "holds {} values; liftoff reads the peak load and then one peak deflection for each of the {n} sensors ({} values)",
                        values.len(),
                        n + 1
                    ),
                ));
            }
            let drop = Drop {
                station: station.clone(),
                drop: earlier + k + 1,
                location: Location::Interior,
                basin: Basin {
                    load: values[0] * load_unit,
                    radius,
                    offsets: offsets.clone(),
                    deflections: order
                        .iter()
                        .map(|&i| values[1 + i] * deflection_unit)
                        .collect(),
                },
                at: None,
                direction: 0.0,
                temperature_difference: None,
            };
            drop.check()?;
            drops.push(drop);
        }
    }
    if drops.is_empty() {
        return Err(Error::invalid(
            source,
            "holds no drop: a PDDX survey has `[Test Location …]` sections with `DropData` lines",
        ));
    }
    Ok(drops)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two stations in SI, the sensors listed out of order (the third before the second).
    const FILE: &str = "\
; a survey
[Pavement Deflection Data Exchange File]
PDDXVersionNumber = 2.0
DelimiterSymbol = ,
DecimalSymbol = .

[Units]
LoadPlateRadiusUnits = millimeter
LoadUnits = kilo-Newton
DeflectionUnits = micron
SensorLocationUnits = millimeter

[Device Configuration]
LoadPlateRadius = 150
NumberOfDeflectionSensors = 4
DeflectionSensorXAxisDistances = 0, 610, 305, 914
DeflectionSensorYAxisDistances = 0, 0, 0, 0

[Test Location 1]
TestLocation = 1.000, 0, 0
NumberOfDrops = 2
DropData1 = 40, 100, 75, 90, 60
DropData2 = 50, 125, 94, 112, 75

[Test Location 2]
DropData_0 = 40, 110, 80, 95, 62
";

    #[test]
    fn a_file_reads_in_si_its_sensors_in_order_and_its_drops_numbered() {
        let d = read_pddx(FILE, "f.pdx").expect("reads");
        assert_eq!(d.len(), 3);
        assert_eq!((d[0].station.as_str(), d[0].drop), ("1.000", 1));
        assert_eq!((d[1].station.as_str(), d[1].drop), ("1.000", 2));
        // No TestLocation: the section's number names the station.
        assert_eq!((d[2].station.as_str(), d[2].drop), ("2", 1));
        assert!((d[1].basin.load - 5e4).abs() < 1e-9);
        assert!((d[0].basin.radius - 0.15).abs() < 1e-15);
        assert_eq!(d[0].basin.offsets, vec![0.0, 0.305, 0.61, 0.914]);
        // The 305 mm sensor's deflection is the file's third value, the 610 mm one the second.
        let um: Vec<f64> = d[0].basin.deflections.iter().map(|v| v * 1e6).collect();
        for (got, want) in um.iter().zip([100.0, 90.0, 75.0, 60.0]) {
            assert!((got - want).abs() < 1e-9, "{um:?}");
        }
    }

    #[test]
    fn the_same_survey_reads_the_same_as_a_csv_file() {
        let csv = "station,drop,load_kN,radius_mm,d0mm_um,d305mm_um,d610mm_um,d914mm_um\n\
            1.000,1,40,150,100,90,75,60\n\
            1.000,2,50,150,125,112,94,75\n\
            2,1,40,150,110,95,80,62\n";
        let a = read_pddx(FILE, "f.pdx").expect("pddx");
        let b = super::super::basins::read_basins(csv, "f.csv").expect("csv");
        assert_eq!(a.len(), b.len());
        for (a, b) in a.iter().zip(&b) {
            assert_eq!(
                (&a.station, a.drop, a.location),
                (&b.station, b.drop, b.location)
            );
            assert!((a.basin.load - b.basin.load).abs() < 1e-9);
            assert_eq!(a.basin.offsets, b.basin.offsets);
            for (x, y) in a.basin.deflections.iter().zip(&b.basin.deflections) {
                assert!((x - y).abs() < 1e-15);
            }
        }
    }

    #[test]
    fn us_units_and_a_decimal_comma_convert_exactly() {
        let f = "[Pavement Deflection Data Exchange File]\nPDDXVersionNumber = 1.0\n\
            DelimiterSymbol = ;\nDecimalSymbol = ,\n\
            [Units]\nLoadPlateRadiusUnits = inches\nLoadUnits = pounds\nDeflectionUnits = mils\n\
            SensorLocationUnits = inch\n\
            [Device Configuration]\nLoadPlateRadius = 5,91\nNumberOfDeflectionSensors = 2\n\
            DeflectionSensorXAxisDistances = 0; 12\n\
            [Test Location 7]\nDropData1 = 9000; 4,0; 3,5\n";
        let d = read_pddx(f, "f.pdx").expect("reads");
        assert!((d[0].basin.load - 9000.0 * 4.448_221_615_260_5).abs() < 1e-6);
        assert!((d[0].basin.radius - 5.91 * 0.0254).abs() < 1e-15);
        assert!((d[0].basin.offsets[1] - 0.3048).abs() < 1e-15);
        assert!((d[0].basin.deflections[1] - 3.5 * 25.4e-6).abs() < 1e-15);
    }

    #[test]
    fn bad_files_are_refused_naming_the_section_and_key() {
        let err = |f: &str| match read_pddx(f, "f.pdx") {
            Err(Error::Invalid { field, message }) => format!("{field}: {message}"),
            other => panic!("{other:?}"),
        };
        let swap = |from: &str, to: &str| FILE.replacen(from, to, 1);
        assert!(err(&swap("LoadUnits = kilo-Newton\n", ""))
            .starts_with("f.pdx: [Units] LoadUnits: is missing"));
        assert!(err(&swap("kilo-Newton", "stone"))
            .starts_with("f.pdx: [Units] LoadUnits: `stone` is not a unit"));
        assert!(err(&swap("= 2.0", "= 3.0")).contains("PDDXVersionNumber: `3.0`"));
        // The exporter's slip seen in the wild: a distance more than the sensors.
        assert!(err(&swap("0, 610, 305, 914", "0, 0, 610, 305, 914"))
            .contains("DeflectionSensorXAxisDistances: gives 5 distances for the 4 sensors"));
        assert!(err(&swap("0, 610, 305, 914", "0, 610, -305, 914"))
            .contains("sensor 3 stands behind the plate"));
        assert!(err(&swap("= 0, 0, 0, 0", "= 0, 0, 100, 0")).contains("sensor 3 stands 100 off"));
        assert!(err(&swap("DropData2 = 50,", "DropData2 = 50, 1,"))
            .starts_with("f.pdx: [Test Location 1] DropData2: holds 6 values"));
        assert!(err(&swap("NumberOfDrops = 2", "NumberOfDrops = 3")).contains("says 3 drops"));
        assert!(err(&swap("DropData1 = 40, 100", "DropData1 = 40, 1OO"))
            .contains("`1OO` (line 22) is not a number"));
        assert!(err(&swap("[Units]", "[Units")).starts_with("f.pdx: line 7"));
        // A drop's own check still runs, naming its station.
        assert!(err(&swap(
            "DropData1 = 40, 100, 75, 90",
            "DropData1 = 40, 100, 75, 120"
        ))
        .starts_with("station 1.000, drop 1: sensor at 305 mm"));
    }
}
