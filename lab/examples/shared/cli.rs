//! Command-line plumbing shared by the example tools: clap errors as one
//! line, the exit codes, sampler names and comma-separated lists whose
//! errors name the offending item, and the one behaviour for output paths
//! (missing folders are created), for standard output closed early (`tool
//! | head` stops the tool quietly) and for pages read back (a size limit).
//!
//! Include it from a tool with `#[path = "../shared/cli.rs"] mod shared;`
//! (or `"shared/cli.rs"` from a single-file example). Each tool uses a
//! part, so the rest is allowed to be dead code.

#![allow(dead_code)]

use std::ffi::OsString;
use std::fmt;
use std::fs::{self, File};
use std::io::{self, Read, Write};
use std::path::Path;
use std::process::ExitCode;

use clap::error::{ContextKind, ErrorKind};
use wellspread::SamplerKind;

/// The exit codes, for the end of every tool's `--help`.
pub const EXIT_CODES: &str = "\
Exit status: 0 on success; 2 for a bad argument or bad input (one line on
standard error, naming the argument or the 1-based input line); 1 if
reading or writing a file or stream fails.";

/// Why a tool stopped early: what it prints and the exit status.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Failure {
    /// A bad argument or bad input: exit status 2.
    Input(String),
    /// Reading or writing failed: exit status 1.
    Io(String),
    /// Standard output was closed before the tool finished (`tool |
    /// head`): it stops quietly, with exit status 0, as it would have if
    /// the reader had taken everything.
    OutputClosed,
}

impl Failure {
    /// The process exit status: 2 for bad input, 1 for I/O.
    pub fn status(&self) -> u8 {
        match self {
            Failure::Input(_) => 2,
            Failure::Io(_) => 1,
            Failure::OutputClosed => 0,
        }
    }
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::Input(message) | Failure::Io(message) => f.write_str(message),
            Failure::OutputClosed => f.write_str("standard output was closed"),
        }
    }
}

/// Prints a failure as `tool: message` on `stderr` and turns the outcome
/// into an exit status (0, 1 or 2).
pub fn finish(tool: &str, result: Result<(), Failure>, stderr: &mut dyn Write) -> u8 {
    match result {
        Ok(()) | Err(Failure::OutputClosed) => 0,
        Err(failure) => {
            // Nothing better to do if standard error itself is gone.
            let _ = writeln!(stderr, "{tool}: {failure}");
            failure.status()
        }
    }
}

/// A write as a tool's outcome: a closed pipe is [`Failure::OutputClosed`]
/// (the tool stops, quietly, with status 0), any other error
/// [`Failure::Io`] (status 1), `cannot write {what}: {error}`.
pub fn written(result: io::Result<()>, what: &str) -> Result<(), Failure> {
    result.map_err(|e| match e.kind() {
        io::ErrorKind::BrokenPipe => Failure::OutputClosed,
        _ => Failure::Io(format!("cannot write {what}: {e}")),
    })
}

/// [`written`] for a write to standard output.
pub fn to_stdout(result: io::Result<()>) -> Result<(), Failure> {
    written(result, "to standard output")
}

/// [`finish`] on the real standard error, as the value `main` returns.
pub fn exit(tool: &str, result: Result<(), Failure>) -> ExitCode {
    ExitCode::from(finish(tool, result, &mut io::stderr()))
}

/// Parses `args` (without the program name) with clap, adding
/// `after_help` to the end of `--help`. `Ok(None)` means the help was
/// written to `out` and the tool should stop with status 0. A parse error
/// is one line (clap's first line, without its `error: ` prefix).
pub fn parse<P: clap::Parser>(
    name: &'static str,
    after_help: &str,
    args: impl IntoIterator<Item = OsString>,
    out: &mut dyn Write,
) -> Result<Option<P>, Failure> {
    let command = P::command().name(name).bin_name(name);
    let command = command.after_help(after_help.to_owned());
    let args = negative_values_attached(&command, args);
    let args = std::iter::once(OsString::from(name)).chain(args);
    match command.try_get_matches_from(args) {
        Ok(mut matches) => P::from_arg_matches_mut(&mut matches)
            .map(Some)
            .map_err(|e| Failure::Input(one_line(&e))),
        Err(e) => match e.kind() {
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
                write!(out, "{e}")
                    .map_err(|e| Failure::Io(format!("cannot write the help: {e}")))?;
                Ok(None)
            }
            _ => Err(Failure::Input(one_line(&e))),
        },
    }
}

/// `args` with a value that starts with `-` and a digit (`--pattern -1`,
/// `--projection -1,2`, `--stratified -1x2`) attached to the long option
/// before it that takes a value (`--pattern=-1`), so that it reaches the
/// value parser, which says the value must be non-negative, instead of
/// reading as an unknown flag `-1`.
fn negative_values_attached(
    command: &clap::Command,
    args: impl IntoIterator<Item = OsString>,
) -> Vec<OsString> {
    let takes_value = |flag: &str| {
        let Some(flag) = flag.strip_prefix("--") else {
            return false;
        };
        command.get_arguments().any(|arg| {
            let aliases = arg.get_all_aliases().unwrap_or_default();
            arg.get_action().takes_values()
                && (arg.get_long() == Some(flag) || aliases.contains(&flag))
        })
    };
    let mut joined: Vec<OsString> = Vec::new();
    for arg in args {
        let negative = arg.to_str().is_some_and(|text| {
            let mut chars = text.chars();
            chars.next() == Some('-') && chars.next().is_some_and(|c| c.is_ascii_digit())
        });
        let after_flag = joined
            .last()
            .and_then(|last| last.to_str())
            .is_some_and(takes_value);
        match joined.last_mut() {
            Some(last) if negative && after_flag => {
                last.push("=");
                last.push(&arg);
            }
            _ => joined.push(arg),
        }
    }
    joined
}

/// A clap error as one line: its first paragraph (the message and, for
/// missing arguments, their names) without `error: `, plus a pointer to
/// `--help`. A value our parser rejected is reported by our message alone,
/// which quotes at most 80 characters of it (clap's own would quote all).
fn one_line(error: &clap::Error) -> String {
    if error.kind() == ErrorKind::ValueValidation {
        let arg = error.get(ContextKind::InvalidArg);
        if let (Some(arg), Some(reason)) = (arg, std::error::Error::source(error)) {
            return format!("{arg}: {reason} (try --help)");
        }
    }
    let text = error.to_string();
    let words: Vec<&str> = text
        .lines()
        .take_while(|line| !line.trim().is_empty())
        .map(str::trim)
        .collect();
    let message = words.join(" ");
    let message = message.strip_prefix("error: ").unwrap_or(&message);
    format!("{message} (try --help)")
}

/// The one of `all` whose `name_of` is `name`, or an error that lists
/// every name.
pub fn by_name<T: Copy>(
    all: &[T],
    name: &str,
    name_of: fn(T) -> &'static str,
    what: &str,
) -> Result<T, String> {
    all.iter()
        .copied()
        .find(|&item| name_of(item) == name)
        .ok_or_else(|| {
            let names: Vec<&str> = all.iter().map(|&item| name_of(item)).collect();
            format!(
                "unknown {what} {name:?}; expected one of: {}",
                names.join(" ")
            )
        })
}

/// `text` quoted and escaped as a Rust string (so a newline cannot split a
/// one-line message), cut to its first 80 characters with `...` inside the
/// quotes if longer.
pub fn quoted(text: &str) -> String {
    match text.char_indices().nth(80) {
        Some((cut, _)) => format!("{:?}", format!("{}...", &text[..cut])),
        None => format!("{text:?}"),
    }
}

/// The sampler names, space-separated, for help texts.
pub fn sampler_names() -> String {
    let names: Vec<&str> = SamplerKind::ALL.iter().map(|kind| kind.name()).collect();
    names.join(" ")
}

/// One sampler name, for clap's `value_parser`. The error quotes the name
/// and lists the known ones.
pub fn sampler_kind(name: &str) -> Result<SamplerKind, String> {
    name.parse().map_err(|_| {
        let hint = if name.trim() != name && name.trim().parse::<SamplerKind>().is_ok() {
            " (no spaces around names)"
        } else {
            ""
        };
        format!(
            "unknown sampler {}{hint}; expected one of: {}",
            quoted(name),
            sampler_names()
        )
    })
}

/// A comma-separated list of sampler names, duplicates dropped, in the
/// order given. A newtype, so that clap's derive takes it as one value
/// (it would read a `Vec` field as repeated flags):
///
/// ```ignore
/// #[arg(long, value_name = "LIST", value_parser = shared::sampler_list)]
/// sampler: shared::SamplerList,
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SamplerList(pub Vec<SamplerKind>);

/// Parses a [`SamplerList`], for clap's `value_parser`. The error names the
/// unknown item and its position.
pub fn sampler_list(value: &str) -> Result<SamplerList, String> {
    list(value, sampler_kind).map(SamplerList)
}

/// A comma-separated list, each item parsed by `item`, duplicates dropped
/// in order. An empty item or a bad one is an error that quotes the item
/// and its 1-based position when the list has more than one.
pub fn list<T: PartialEq>(
    value: &str,
    item: impl Fn(&str) -> Result<T, String>,
) -> Result<Vec<T>, String> {
    let parts: Vec<&str> = value.split(',').collect();
    let mut list = Vec::new();
    for (number, part) in (1..).zip(&parts) {
        let at = if parts.len() > 1 {
            format!("item {number} of {}: ", quoted(value))
        } else {
            String::new()
        };
        if part.is_empty() {
            return Err(format!("{at}empty name"));
        }
        let parsed = item(part).map_err(|e| format!("{at}{e}"))?;
        if !list.contains(&parsed) {
            list.push(parsed);
        }
    }
    Ok(list)
}

/// The one message of every tool for a negative number where counts,
/// sizes and patterns go: `Err` when `text`, or a part of it between `,`
/// and `x` (`-1,2`, `8x-8`), is a negative number.
pub fn non_negative(text: &str) -> Result<(), String> {
    let negative = |part: &str| {
        part.strip_prefix('-')
            .is_some_and(|digits| digits.parse::<f64>().is_ok())
    };
    if text.split([',', 'x', 'X']).any(negative) {
        Err(format!(
            "the value must be non-negative, got {}",
            quoted(text)
        ))
    } else {
        Ok(())
    }
}

/// A `u32` in decimal or `0x` hex, for clap's `value_parser`.
pub fn u32_dec_or_hex(text: &str) -> Result<u32, String> {
    non_negative(text)?;
    let parsed = match text.strip_prefix("0x").or_else(|| text.strip_prefix("0X")) {
        Some(hex) => u32::from_str_radix(hex, 16).ok(),
        None => text.parse().ok(),
    };
    parsed.ok_or_else(|| {
        format!(
            "{} is not a number from 0 to {} (decimal or 0x hex)",
            quoted(text),
            u32::MAX
        )
    })
}

/// A decimal `u32`, for clap's `value_parser` (clap's own message for a
/// bad `u32` does not say the range).
pub fn whole_number(text: &str) -> Result<u32, String> {
    non_negative(text)?;
    text.parse().map_err(|_| {
        format!(
            "{} is not a whole number from 0 to {}",
            quoted(text),
            u32::MAX
        )
    })
}

/// Creates the folders `path` needs (every tool does the same: a missing
/// output folder is made, as `--out DIR` is), then the file, empty.
pub fn create_file(path: &Path) -> Result<File, Failure> {
    if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
        fs::create_dir_all(parent)
            .map_err(|e| Failure::Io(format!("cannot create {}: {e}", parent.display())))?;
    }
    File::create(path).map_err(|e| Failure::Io(format!("cannot create {}: {e}", path.display())))
}

/// The largest page a tool reads back to rewrite its generated block
/// (`--docs`), and the largest other text file it reads whole (the Mitsuba
/// CSV): far more than any page under `docs/`.
pub const MAX_PAGE: u64 = 4 << 20;

/// The text of the docs page at `path`: [`read_text`] of a `"docs page"`.
pub fn read_page(path: &Path) -> Result<String, Failure> {
    read_text(path, "docs page")
}

/// The text of the file at `path`, read with a limit of [`MAX_PAGE`]
/// bytes, so that `--docs /dev/zero` stops with an error instead of filling
/// memory. `what` names the file in that error: `{path} is larger than 4
/// MiB, the limit for a {what}`.
pub fn read_text(path: &Path, what: &str) -> Result<String, Failure> {
    let cannot = |e: &dyn fmt::Display| Failure::Io(format!("cannot read {}: {e}", path.display()));
    let file = File::open(path).map_err(|e| cannot(&e))?;
    let mut bytes = Vec::new();
    file.take(MAX_PAGE + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| cannot(&e))?;
    if bytes.len() as u64 > MAX_PAGE {
        return Err(Failure::Input(format!(
            "{} is larger than {} MiB, the limit for a {what}",
            path.display(),
            MAX_PAGE >> 20
        )));
    }
    String::from_utf8(bytes)
        .map_err(|_| Failure::Input(format!("{} is not UTF-8 text", path.display())))
}

/// Checks, before any work, that `path` can be the page `flag` (`--docs`)
/// rewrites: a regular file, or nothing yet (it is created). Anything else
/// that exists is an input error naming what it is, so that a FIFO (whose
/// opening would block until a reader comes) or a device such as
/// `/dev/zero` is refused before a render, not after it.
pub fn check_page_path(flag: &str, path: &Path) -> Result<(), Failure> {
    let file_type = match fs::metadata(path) {
        Ok(metadata) => metadata.file_type(),
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(e) => {
            return Err(Failure::Io(format!("cannot read {}: {e}", path.display())));
        }
    };
    if file_type.is_file() {
        return Ok(());
    }
    Err(Failure::Input(format!(
        "{flag} {}: {}, not a regular file; a page to rewrite must be one",
        path.display(),
        file_kind(file_type)
    )))
}

/// What a file that is not a regular file is, for messages.
fn file_kind(file_type: fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if file_type.is_fifo() {
            return "a FIFO";
        }
        if file_type.is_char_device() || file_type.is_block_device() {
            return "a device";
        }
        if file_type.is_socket() {
            return "a socket";
        }
    }
    if file_type.is_dir() {
        "a directory"
    } else {
        "a special file"
    }
}
