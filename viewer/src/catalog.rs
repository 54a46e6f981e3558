//! The preset list: built-in or from `--presets FILE`; `viewer presets`.

use crate::cli::PresetsArgs;
use crate::error::Error;
use bake::presets::{self, NamedPreset};
use std::io::{self, BufWriter, Write};

/// The presets `args` selects: the file's with `--presets FILE`, else the built-in ones.
pub fn load(args: &PresetsArgs) -> Result<Vec<NamedPreset>, Error> {
    match &args.presets {
        Some(path) => presets::load_file(path),
        None => presets::builtin(),
    }
    .map_err(Error::input)
}

/// The preset called `name`; the error lists the known names.
pub fn find<'a>(list: &'a [NamedPreset], name: &str) -> Result<&'a NamedPreset, Error> {
    presets::find(list, name).ok_or_else(|| {
        let known: Vec<&str> = list.iter().map(|p| p.name.as_str()).collect();
        Error::input(format!(
            "unknown preset `{name}` (known presets: {})",
            known.join(", ")
        ))
    })
}

/// `viewer presets`: one line per preset, the name, a tab, the source.
pub fn list(args: &PresetsArgs) -> Result<(), Error> {
    let list = load(args)?;
    let mut out = BufWriter::new(io::stdout().lock());
    for p in &list {
        // Keep one preset per line even if a user's source spans several.
        let source: String = p
            .source
            .chars()
            .map(|c| if c.is_control() { ' ' } else { c })
            .collect();
        writeln!(out, "{}\t{}", p.name, source)?;
    }
    out.flush()?;
    Ok(())
}
