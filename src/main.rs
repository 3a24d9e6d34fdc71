//! `mdr-impact`: the command line. Parses, calls the library, prints; nothing else. The flags
//! are in `cli::args`, one function per subcommand in `cli::commands`.

mod cli;

use std::process::ExitCode;

use clap::Parser;
use mdr_impact::error::escape_text;

fn main() -> ExitCode {
    // Rust ignores SIGPIPE, so a closed pipe (`mdr-impact cor --input big.csv | head`) made every
    // `println!` panic; the default action ends the process quietly, as `cat` does.
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to SIG_DFL at the start of main, before any thread
    // exists, has no preconditions.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let parsed = match cli::args::Cli::try_parse() {
        Ok(p) => p,
        // --help and --version print as usual and exit 0
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            // malformed command line: one line, exit code 2
            eprintln!("{}", cli::one_line(&e));
            return ExitCode::from(2);
        }
    };
    match cli::commands::run(parsed.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // escaped: one line, no raw control bytes from a user's text
            eprintln!("error: {}", escape_text(&e.to_string()));
            ExitCode::from(1)
        }
    }
}
