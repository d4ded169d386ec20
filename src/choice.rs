//! Named choices — the contact law, the method, the QP form, the route, … — each one list of
//! (value, name) that the scene files (serde), the command line (its possible values) and the
//! Python package read, so that a word is spelled in one place. No front end's types here.

/// An enum chosen by name in scene files, flags and keyword arguments.
pub trait Choice: Copy + PartialEq + Sized + 'static {
    /// Every value, in the order help texts list them.
    const ALL: &'static [Self];

    /// Name as written in scene files, flags and reports.
    fn choice_name(self) -> &'static str;

    /// The value of a name, if it is one of [`Choice::ALL`]'s.
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|c| c.choice_name() == name)
    }

    /// Every name, in order.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|c| c.choice_name()).collect()
    }
}

/// `name()`, `Display`, `FromStr` and [`Choice`] for the small enums of scene files and reports,
/// from one list of `Variant => "name"`. Crate-private: called as `crate::choice::names!`, so
/// that its callers depend on this module, not on the crate root, and it is no public API.
macro_rules! names {
    ($t:ty, $($v:ident => $s:literal),+) => {
        impl $t {
            /// Name as written in scene files and reports.
            pub fn name(self) -> &'static str {
                match self { $(Self::$v => $s),+ }
            }
        }
        impl $crate::choice::Choice for $t {
            const ALL: &'static [Self] = &[$(Self::$v),+];
            fn choice_name(self) -> &'static str {
                self.name()
            }
        }
        impl std::fmt::Display for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.pad(self.name())
            }
        }
        impl std::str::FromStr for $t {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                <Self as $crate::choice::Choice>::from_name(s).ok_or_else(|| {
                    format!(
                        "`{s}` is not one of {}",
                        <Self as $crate::choice::Choice>::names().join(", ")
                    )
                })
            }
        }
    };
}

pub(crate) use names;
