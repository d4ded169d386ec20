//! Result files: CSV tables, the JSON summary, the ParaView grid and the SVG/PNG charts.
//!
//! [`write_all`] stages every file in a hidden directory inside the output directory and
//! renames them into place only when all were written, so a failed run never leaves a
//! half-written file or a half-updated directory behind.

pub mod backcalc;
pub mod chart;
pub mod combinations;
pub mod critical;
pub mod damage;
pub mod joints;
pub mod report;
pub mod studies;

pub mod study_tables;
pub mod tables;
pub mod vtk;

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::post::Report;
pub use crate::summary::{Summary, Times};

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> Error + '_ {
    move |source| Error::Io {
        path: path.display().to_string(),
        source,
    }
}

/// Check, before any solving, that `dir` can be created and files written in it, without
/// leaving anything behind: the folders this call has to create are removed again, and
/// [`Staged::new`] creates them when the files are written. So a run that fails or is
/// interrupted before its files are written leaves no empty output directory, and a directory
/// that existed before is never removed.
pub fn prepare_dir(dir: &Path) -> Result<()> {
    let created = create_dirs(dir)?;
    // The probe file is deleted (dropped) before the folders are removed.
    let probe = tempfile::Builder::new()
        .prefix(".liftoff-write-check")
        .tempfile_in(dir)
        .map(drop)
        .map_err(io(dir));
    remove_created(&created);
    probe
}

/// Create `dir` and its missing parents; returns the folders this call created, outermost
/// first (none when `dir` existed). A failure part of the way removes what it created.
fn create_dirs(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut missing = Vec::new();
    let mut p = dir;
    // Anything at a path, even a dangling link, is not ours to remove.
    while !p.as_os_str().is_empty() && std::fs::symlink_metadata(p).is_err() {
        missing.push(p.to_path_buf());
        match p.parent() {
            Some(parent) => p = parent,
            None => break,
        }
    }
    missing.reverse();
    if let Err(e) = std::fs::create_dir_all(dir) {
        remove_created(&missing);
        return Err(io(dir)(e));
    }
    Ok(missing)
}

/// Remove the folders [`create_dirs`] created, innermost first, each only while it is empty
/// (`remove_dir`): a folder that holds anything — a file written by someone else since — is left
/// with everything above it.
fn remove_created(created: &[PathBuf]) {
    for p in created.iter().rev() {
        if std::fs::remove_dir(p).is_err() {
            break;
        }
    }
}

/// The flag of [`cancel_writes_with`].
static STOP_WRITES: std::sync::OnceLock<&'static std::sync::atomic::AtomicBool> =
    std::sync::OnceLock::new();

/// Make every [`Staged::commit`] of this process refuse once `flag` is set: the staged files are
/// discarded and the commit is [`Error::Cancelled`]. The command line passes its Ctrl-C flag,
/// so an interruption while files are being drawn and written leaves none of them (once the
/// files are being moved into place, the commit completes). The first call wins.
pub fn cancel_writes_with(flag: &'static std::sync::atomic::AtomicBool) {
    let _ = STOP_WRITES.set(flag);
}

/// The staging directory of a [`Staged`] set and its handles, and the folders created for the
/// output directory: dropped without a commit, it removes the staging directory and then those
/// folders (while empty), so nothing of a failed or interrupted write is left.
struct Area {
    path: PathBuf,
    staging: Option<tempfile::TempDir>,
    created: Vec<PathBuf>,
    committed: std::sync::atomic::AtomicBool,
}

impl Drop for Area {
    fn drop(&mut self) {
        drop(self.staging.take());
        if !self.committed.load(std::sync::atomic::Ordering::Relaxed) {
            remove_created(&self.created);
        }
    }
}

/// A set of files written into a staging directory and moved into place together.
pub struct Staged {
    dir: PathBuf,
    area: std::sync::Arc<Area>,
    names: Vec<String>,
}

impl Staged {
    /// Start staging files for `dir`, creating it (and its missing parents) if needed; dropped
    /// without [`Self::commit`] (a failed or interrupted write), the staged files are deleted
    /// and the folders it created removed.
    pub fn new(dir: &Path) -> Result<Self> {
        let created = create_dirs(dir)?;
        let staging = match tempfile::Builder::new()
            .prefix(".liftoff-staging")
            .tempdir_in(dir)
        {
            Ok(s) => s,
            Err(e) => {
                remove_created(&created);
                return Err(io(dir)(e));
            }
        };
        Ok(Self {
            dir: dir.to_path_buf(),
            area: std::sync::Arc::new(Area {
                path: staging.path().to_path_buf(),
                staging: Some(staging),
                created,
                committed: std::sync::atomic::AtomicBool::new(false),
            }),
            names: Vec::new(),
        })
    }

    /// A second handle on the same staging area, to stage files from another thread; hand it
    /// back with [`Self::absorb`] so that its files are committed too.
    pub fn share(&self) -> Self {
        Self {
            dir: self.dir.clone(),
            area: self.area.clone(),
            names: Vec::new(),
        }
    }

    /// Take over the files staged through a handle from [`Self::share`].
    pub fn absorb(&mut self, other: Staged) {
        self.names.extend(other.names);
    }

    /// Path in the staging area for a file that will be called `name` (which may name a
    /// sub-folder: `ULS-1/summary.json`).
    pub fn path(&mut self, name: &str) -> PathBuf {
        self.names.push(name.to_string());
        let p = self.area.path.join(name);
        if let Some(parent) = p.parent() {
            // A failure shows when the file is written, with its path.
            let _ = std::fs::create_dir_all(parent);
        }
        p
    }

    /// Write text to a staged file.
    pub fn write_text(&mut self, name: &str, text: &str) -> Result<()> {
        let p = self.path(name);
        std::fs::write(&p, text).map_err(io(&p))
    }

    /// Move every staged file into the output directory; returns the final paths. Refused,
    /// with nothing moved, once the flag of [`cancel_writes_with`] is set.
    pub fn commit(self) -> Result<Vec<PathBuf>> {
        if STOP_WRITES
            .get()
            .is_some_and(|f| f.load(std::sync::atomic::Ordering::SeqCst))
        {
            return Err(Error::Cancelled("the writing of the files".into()));
        }
        let mut out = Vec::new();
        for name in &self.names {
            let from = self.area.path.join(name);
            let to = self.dir.join(name);
            if let Some(parent) = to.parent() {
                std::fs::create_dir_all(parent).map_err(io(parent))?;
            }
            std::fs::rename(&from, &to).map_err(io(&to))?;
            out.push(to);
        }
        self.area
            .committed
            .store(true, std::sync::atomic::Ordering::Relaxed);
        Ok(out)
    }
}

/// Write the standard result set of one solve into `dir`: summary.json, nodes.csv,
/// elements.csv, profiles.csv, on a jointed plate joints.csv (and dowels.csv with dowels),
/// plate.vtu, profiles.svg, contact.svg, contact.png and the map of
/// the bottom face's largest principal stress (stress-bottom.svg, .png); the contact map shows
/// the model's voids, zones, line loads and bearing limit.
pub fn write_all(
    dir: &Path,
    model: &crate::model::Model,
    report: &Report,
    summary: &Summary,
) -> Result<Vec<PathBuf>> {
    let overlay = chart::Overlay::for_model(model, report);
    let overlay = &overlay;
    let mut st = Staged::new(dir)?;
    stage_all(&mut st, "", report, summary, overlay)?;
    st.commit()
}

/// Stage the standard result set under `prefix` (empty, or a sub-folder ending in '/').
pub fn stage_all(
    st: &mut Staged,
    prefix: &str,
    report: &Report,
    summary: &Summary,
    overlay: &chart::Overlay,
) -> Result<()> {
    st.write_text(&format!("{prefix}summary.json"), &summary.to_json()?)?;
    // The files report the scene's unit system; the charts scale the SI fields themselves.
    let system = summary.physical.map(|p| p.units);
    let field = report.field.in_units(system);
    let elements = report.elements.in_units(system);
    let p = st.path(&format!("{prefix}nodes.csv"));
    tables::write_nodes(&p, &field, system)?;
    let p = st.path(&format!("{prefix}elements.csv"));
    tables::write_elements(&p, &elements, &field.plate, system)?;
    let p = st.path(&format!("{prefix}profiles.csv"));
    tables::write_profiles(&p, &report.profiles)?;
    if !report.joints.is_empty() {
        let p = st.path(&format!("{prefix}joints.csv"));
        joints::write_joints(&p, &report.joints, system)?;
        if report.joints.iter().any(|j| !j.dowels.is_empty()) {
            let p = st.path(&format!("{prefix}dowels.csv"));
            joints::write_dowels(&p, &report.joints, system)?;
        }
    }
    let p = st.path(&format!("{prefix}plate.vtu"));
    vtk::write_vtu(&p, &field, &elements)?;
    let title = format!("{} — {}", summary.title, summary.headline());
    let units = chart::Units::new(summary.physical, summary.dimensionless.mu);
    let p = st.path(&format!("{prefix}profiles.svg"));
    chart::write_profiles_svg(&p, &report.profiles, &title, &units)?;
    let svg = st.path(&format!("{prefix}contact.svg"));
    let png = st.path(&format!("{prefix}contact.png"));
    chart::write_contact_map(&svg, &png, &report.field, &title, &units, overlay)?;
    // The map a pavement or floor designer reads: the largest principal stress at the bottom
    // face, element by element (tension positive).
    let svg = st.path(&format!("{prefix}stress-bottom.svg"));
    let png = st.path(&format!("{prefix}stress-bottom.png"));
    let peak = &summary.stresses.bottom;
    let stress = units.stress();
    chart::write_field_map(
        &svg,
        &png,
        &report.field,
        &chart::MapValues {
            values: &report.elements.bottom.s1,
            name: "σ₁ bottom",
            scale: stress,
        },
        &format!(
            "{} — largest principal stress at the bottom, max {:.3} {}",
            summary.title,
            stress.apply(peak.value),
            stress.unit
        ),
        &units,
        overlay,
    )?;
    Ok(())
}
